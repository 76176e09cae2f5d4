// Runs the ispm binary the way a user would (a shell command line) and collects what it printed;
// shared by the viewer's window tests.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace ispm::test {

struct RunResult {
    int exitCode = -1;
    std::string output; // stdout and stderr together
};

inline RunResult run(const std::string& args, const std::string& environment = "") {
    const std::string command =
        environment + (environment.empty() ? "" : " ") + ISPM_EXECUTABLE + " " + args + " 2>&1";
    RunResult result;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe)) {
        result.output += buffer.data();
    }
    const int status = ::pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

} // namespace ispm::test
