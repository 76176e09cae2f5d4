// ReloadableProgram: modification-time stamps of the expanded source files decide what to rebuild.
#include "render/reloadable_program.h"

#include "gl/debug.h"
#include "gl/gl.h" // gl::Error
#include "render/shader_root.h"

namespace ispm {

ReloadableProgram::ReloadableProgram(gl::ProgramDesc desc)
    : mDesc(std::move(desc)), mProgram(gl::Program::build(getShaderRoot(), mDesc)),
      mStamps(readStamps(mProgram.getSourceFiles())) {}

ReloadableProgram::Stamps
ReloadableProgram::readStamps(const std::vector<std::filesystem::path>& files) {
    Stamps stamps;
    stamps.reserve(files.size());
    for (const std::filesystem::path& file : files) {
        std::error_code error; // a deleted file reads as "changed": the rebuild then reports it
        stamps.push_back(std::filesystem::last_write_time(file, error));
    }
    return stamps;
}

void ReloadableProgram::reloadIfChanged(ShaderReloadReport& report) {
    ++report.checked;
    if (readStamps(mProgram.getSourceFiles()) == mStamps) return;
    // The compiler's KHR_debug messages repeat the info log, which the report carries; as GL
    // errors they would fail the run over a shader the user is still editing. A debug group
    // restores the message filter it started with when it ends, so the silence stays in here.
    const gl::DebugGroup group("shader reload");
    gl::muteShaderCompilerMessages();
    try {
        gl::Program rebuilt = gl::Program::build(getShaderRoot(), mDesc);
        mStamps = readStamps(rebuilt.getSourceFiles());
        mProgram = std::move(rebuilt);
        ++report.rebuilt;
    } catch (const gl::Error& e) {
        report.errors.emplace_back(e.what());
    }
}

const ReloadableProgram& ProgramVariants::get(const std::vector<std::string>& defines) {
    if (const auto found = mVariants.find(defines); found != mVariants.end()) return found->second;
    gl::ProgramDesc desc = mBase;
    for (size_t i = 0; i < defines.size(); ++i) {
        desc.defines.push_back(defines[i]);
        desc.label += (i == 0 ? " (" : ", ") + defines[i];
    }
    if (!defines.empty()) desc.label += ")";
    return mVariants.emplace(defines, ReloadableProgram(std::move(desc))).first->second;
}

void ProgramVariants::reloadIfChanged(ShaderReloadReport& report) {
    for (auto& [defines, program] : mVariants)
        program.reloadIfChanged(report);
}

} // namespace ispm
