// A GLSL program that remembers how it was built, so the viewer's F5 can rebuild it when one of
// its source files changed on disk, keeping the working program when the new sources fail.
#pragma once

#include "gl/program.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace ispm {

// What one reload did, summed over every program asked.
struct ShaderReloadReport {
    int checked = 0;
    int rebuilt = 0;
    std::vector<std::string> errors; // compile or link logs of the programs that were kept
};

class ReloadableProgram {
  public:
    ReloadableProgram() = default;
    // Builds from the shader root; throws gl::Error as gl::Program::build does.
    explicit ReloadableProgram(gl::ProgramDesc desc);

    void use() const { mProgram.use(); }
    const gl::Program& get() const { return mProgram; }

    // Rebuilds when a source file's modification time differs from the last successful build.
    // On failure the old program stays and the error joins the report; the stamps stay too, so
    // the next reload tries (and reports) again until the file is fixed.
    void reloadIfChanged(ShaderReloadReport& report);

  private:
    using Stamps = std::vector<std::filesystem::file_time_type>;
    static Stamps readStamps(const std::vector<std::filesystem::path>& files);

    gl::ProgramDesc mDesc;
    gl::Program mProgram;
    Stamps mStamps;
};

// Variants of one program, each built at its first use: the base description plus extra defines
// ("NAME VALUE"). A variant compiles out what a scene or a setting never takes: llvmpipe runs
// both sides of every branch, uniform ones too, so a path left to a uniform costs every pixel.
class ProgramVariants {
  public:
    explicit ProgramVariants(gl::ProgramDesc base) : mBase(std::move(base)) {}
    // Builds the variant at the first call for `defines` (throws gl::Error as gl::Program::build).
    const ReloadableProgram& get(const std::vector<std::string>& defines);
    void reloadIfChanged(ShaderReloadReport& report);

  private:
    gl::ProgramDesc mBase;
    std::map<std::vector<std::string>, ReloadableProgram> mVariants;
};

} // namespace ispm
