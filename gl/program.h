// GLSL programs from files: `#include "path"` is expanded (each file once) with `#line` so that
// compiler messages name the right file and line; `#define` variants are prepended after the
// `#version` line the loader writes. Failures throw gl::Error with `file:line: message` lines.
#pragma once

#include "gl/handle.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gl {

enum class ShaderStage { Vertex, Geometry, Fragment, Compute };

struct ProgramDesc {
    std::string label;
    std::vector<std::pair<ShaderStage, std::string>> stages; // paths relative to the shader root
    std::vector<std::string> defines;                        // "NAME" or "NAME VALUE"
    std::vector<std::string> feedbackVaryings;               // interleaved transform feedback
};

// The expanded source of one stage and the files it was made of (index = #line source number).
struct ExpandedSource {
    std::string text;
    std::vector<std::string> files;
};

ExpandedSource expandShaderSource(const std::filesystem::path& root, const std::string& path,
                                  const std::vector<std::string>& defines);

// Rewrites a driver's info log so "<source>:<line>" references name files.
std::string translateShaderLog(const std::string& log, const std::vector<std::string>& files);

class Program {
  public:
    Program() = default;
    // Compiles and links; throws gl::Error on failure.
    static Program build(const std::filesystem::path& root, const ProgramDesc& desc);
    void use() const;
    GLuint getId() const { return mHandle.get(); }
    // The files the program was built from, for hot reload.
    const std::vector<std::filesystem::path>& getSourceFiles() const { return mSourceFiles; }
    // Where the linker placed uniform `name` in its block (bytes from the block's start; a
    // member of a struct instance: "params.lightCount"), and the byte size of uniform block
    // `block`: the layout the GLSL side sees, to check against the C++ one. nullopt where the
    // program has no active uniform or block of that name.
    std::optional<size_t> getUniformOffset(const std::string& name) const;
    std::optional<size_t> getUniformBlockSize(const std::string& block) const;

  private:
    Handle<deleteProgram> mHandle;
    std::vector<std::filesystem::path> mSourceFiles;
};

} // namespace gl
