// Shader source expansion (#include, #line, #define) and program compile/link with readable logs.
#include "gl/program.h"

#include "gl/gl.h"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace gl {
namespace {

constexpr const char* kVersionLine = "#version 450 core\n";

std::string readTextFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": cannot open shader source");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

struct Expander {
    std::filesystem::path root;
    ExpandedSource out;
    std::set<std::string> included;

    void expand(const std::string& path, const std::string& from, int fromLine) {
        if (!included.insert(path).second) return; // each file once, like #pragma once
        const std::filesystem::path full = root / path;
        if (!std::filesystem::exists(full)) {
            if (from.empty())
                throw Error(path + ": shader source not found under " + root.string());
            throw Error(from + ":" + std::to_string(fromLine) + ": cannot find included file \"" +
                        path + "\"");
        }
        const std::string text = readTextFile(full);
        const int fileIndex = static_cast<int>(out.files.size());
        out.files.push_back(path);
        out.text += "#line 1 " + std::to_string(fileIndex) + "\n";
        std::istringstream lines(text);
        std::string line;
        int lineNumber = 0;
        static const std::regex kInclude(R"(^\s*#\s*include\s*"([^"]+)\"\s*$)");
        while (std::getline(lines, line)) {
            ++lineNumber;
            std::smatch match;
            if (std::regex_match(line, match, kInclude)) {
                // Relative to the including file first, then to the root.
                const std::filesystem::path parent = std::filesystem::path(path).parent_path();
                std::string target = (parent / match[1].str()).lexically_normal().string();
                if (!std::filesystem::exists(root / target)) target = match[1].str();
                expand(target, path, lineNumber);
                out.text += "#line " + std::to_string(lineNumber + 1) + " " +
                            std::to_string(fileIndex) + "\n";
            } else if (line.rfind("#pragma once", 0) == 0) {
                out.text += "\n";
            } else {
                out.text += line + "\n";
            }
        }
    }
};

GLenum getStageEnum(ShaderStage stage) {
    switch (stage) {
    case ShaderStage::Vertex:
        return GL_VERTEX_SHADER;
    case ShaderStage::Geometry:
        return GL_GEOMETRY_SHADER;
    case ShaderStage::Fragment:
        return GL_FRAGMENT_SHADER;
    case ShaderStage::Compute:
        return GL_COMPUTE_SHADER;
    }
    return GL_VERTEX_SHADER;
}

std::string getShaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.c_str();
}

std::string getProgramLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log.c_str();
}

} // namespace

ExpandedSource expandShaderSource(const std::filesystem::path& root, const std::string& path,
                                  const std::vector<std::string>& defines) {
    Expander expander{root, {}, {}};
    expander.out.text = kVersionLine;
    for (const std::string& define : defines)
        expander.out.text += "#define " + define + "\n";
    expander.expand(path, "", 0);
    return std::move(expander.out);
}

std::string translateShaderLog(const std::string& log, const std::vector<std::string>& files) {
    // Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error ...". Both start with source:line.
    static const std::regex kMesa(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");
    static const std::regex kNvidia(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
    std::istringstream lines(log);
    std::string line;
    std::string out;
    auto fileName = [&](const std::string& index) {
        const size_t i = std::stoul(index);
        return i < files.size() ? files[i] : "<source " + index + ">";
    };
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_match(line, m, kMesa)) {
            out += fileName(m[1]) + ":" + m[2].str() + ":" + m[3].str() + ": " + m[4].str() + "\n";
        } else if (std::regex_match(line, m, kNvidia)) {
            out += fileName(m[1]) + ":" + m[2].str() + ": " + m[3].str() + "\n";
        } else if (!line.empty()) {
            out += line + "\n";
        }
    }
    return out;
}

Program Program::build(const std::filesystem::path& root, const ProgramDesc& desc) {
    Program program;
    const GLuint id = glCreateProgram();
    program.mHandle = Handle<deleteProgram>(id);
    std::vector<GLuint> shaders;
    auto deleteShaders = [&] {
        for (GLuint s : shaders)
            glDeleteShader(s);
    };
    for (const auto& [stage, path] : desc.stages) {
        ExpandedSource source = expandShaderSource(root, path, desc.defines);
        for (const std::string& f : source.files)
            program.mSourceFiles.push_back(root / f);
        const GLuint shader = glCreateShader(getStageEnum(stage));
        shaders.push_back(shader);
        const char* text = source.text.c_str();
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        GLint ok = 0;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            const std::string log = translateShaderLog(getShaderLog(shader), source.files);
            deleteShaders();
            throw Error("shader compile failed (" + desc.label + "):\n" + log);
        }
        glAttachShader(id, shader);
    }
    if (!desc.feedbackVaryings.empty()) {
        std::vector<const char*> names;
        for (const std::string& v : desc.feedbackVaryings)
            names.push_back(v.c_str());
        glTransformFeedbackVaryings(id, static_cast<GLsizei>(names.size()), names.data(),
                                    GL_INTERLEAVED_ATTRIBS);
    }
    glLinkProgram(id);
    deleteShaders();
    GLint linked = 0;
    glGetProgramiv(id, GL_LINK_STATUS, &linked);
    if (!linked) throw Error("program link failed (" + desc.label + "):\n" + getProgramLog(id));
    setLabel(GL_PROGRAM, id, desc.label);
    return program;
}

void Program::use() const {
    glUseProgram(getId());
}

std::optional<size_t> Program::getUniformOffset(const std::string& name) const {
    const GLuint index = glGetProgramResourceIndex(getId(), GL_UNIFORM, name.c_str());
    if (index == GL_INVALID_INDEX) return std::nullopt;
    const GLenum property = GL_OFFSET;
    GLint offset = -1;
    glGetProgramResourceiv(getId(), GL_UNIFORM, index, 1, &property, 1, nullptr, &offset);
    if (offset < 0) return std::nullopt; // a uniform outside any block
    return static_cast<size_t>(offset);
}

std::optional<size_t> Program::getUniformBlockSize(const std::string& block) const {
    const GLuint index = glGetProgramResourceIndex(getId(), GL_UNIFORM_BLOCK, block.c_str());
    if (index == GL_INVALID_INDEX) return std::nullopt;
    const GLenum property = GL_BUFFER_DATA_SIZE;
    GLint bytes = 0;
    glGetProgramResourceiv(getId(), GL_UNIFORM_BLOCK, index, 1, &property, 1, nullptr, &bytes);
    return static_cast<size_t>(bytes);
}

} // namespace gl
