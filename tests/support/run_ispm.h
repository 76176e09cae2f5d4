// Runs a command line the way a user would (through the shell) and collects what it printed, for
// the tests that drive the `ispm` executable (cli, bench, viewer).
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace ispm::test {

struct RunResult {
    int exitCode = -1;  // -1: the process was killed by a signal
    std::string output; // stdout, and stderr too when merged
};

enum class Stderr { Merge, Discard };

// With Stderr::Discard, `output` is exactly what stdout got (for JSON output).
inline RunResult runCommand(const std::string& command, Stderr stderrMode = Stderr::Merge) {
    const std::string full = command + (stderrMode == Stderr::Merge ? " 2>&1" : " 2>/dev/null");
    RunResult result;
    FILE* pipe = ::popen(full.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe)) {
        result.output += buffer.data();
    }
    const int status = ::pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

// `ispm ARGS`, optionally with environment assignments before it ("ISPM_SHADER_DIR=...").
inline RunResult runIspm(const std::string& args, Stderr stderrMode = Stderr::Merge,
                         const std::string& environment = "") {
    return runCommand(environment + (environment.empty() ? "" : " ") + ISPM_EXECUTABLE + " " + args,
                      stderrMode);
}

} // namespace ispm::test
