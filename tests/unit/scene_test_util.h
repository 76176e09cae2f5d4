// Helpers shared by the scene unit tests: a scratch directory per test and scene files written
// into it, so the loader is exercised through its real entry point, loadScene.
#pragma once

#include "core/input_error.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <unistd.h>

namespace ispm::test {

// A fresh directory under the test temp dir, removed with everything in it at the end.
class ScratchDir {
  public:
    ScratchDir() {
        static std::atomic<int> counter{0};
        mPath = std::filesystem::path(::testing::TempDir()) /
                ("ispm_scene_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        std::filesystem::create_directories(mPath);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(mPath, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    std::string getPath(const std::string& name) const { return (mPath / name).string(); }

    std::string write(const std::string& name, const std::string& text) const {
        const std::string path = getPath(name);
        std::ofstream out(path, std::ios::binary);
        out << text;
        return path;
    }

  private:
    std::filesystem::path mPath;
};

// The InputError message of loading `text` as a scene file named `name`; "" when none is thrown.
inline std::string getLoadError(const ScratchDir& dir, const std::string& text,
                                const std::string& name = "bad_scene.json") {
    try {
        loadScene(dir.write(name, text));
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace ispm::test
