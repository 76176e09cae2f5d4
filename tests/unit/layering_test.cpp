// The layers of docs/design.md "Layers and folders", from the sources: dependencies point down
// only (cli/viewer -> render -> scene, bvh, image, gl; scene -> settings, image (an environment
// image's file); core under everything),
// gl/ knows nothing of the engine, and settings/, scene/, bvh/, image/ and core/ know no GL. A
// header above its layer fails here with the file and the line that includes it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace ispm {
namespace {

namespace fs = std::filesystem;

// Each folder (a library) and the folders its quoted includes may name.
const std::map<std::string, std::set<std::string>>& getAllowed() {
    static const std::map<std::string, std::set<std::string>> kAllowed = {
        {"app/core", {"core"}},
        {"app/settings", {"core", "settings"}},
        {"app/scene", {"core", "settings", "image", "scene"}},
        {"app/bvh", {"core", "settings", "image", "scene", "bvh"}},
        {"app/image", {"core", "image"}},
        {"gl", {"gl"}},
        {"app/render", {"core", "settings", "scene", "bvh", "image", "gl", "render"}},
        {"app/viewer", {"core", "settings", "scene", "bvh", "image", "gl", "render", "viewer"}},
        {"app/cli", {"core", "settings", "scene", "bvh", "image", "gl", "render", "viewer", "cli"}},
    };
    return kAllowed;
}

// Angle-bracket headers of GL, its loaders and windows: below render/ none may use them.
bool isGlHeader(const std::string& path) {
    for (const char* prefix : {"glad/", "GL/", "GLES", "EGL/", "GLFW/", "KHR/"}) {
        if (path.rfind(prefix, 0) == 0) return true;
    }
    return false;
}

struct Include {
    std::string file;
    int line = 0;
    std::string path;
    bool quoted = false;
};

std::vector<Include> readIncludes(const fs::path& file) {
    std::vector<Include> out;
    std::ifstream in(file);
    std::string text;
    int line = 0;
    while (std::getline(in, text)) {
        ++line;
        if (text.rfind("#include ", 0) != 0 || text.size() < 12) continue;
        const char open = text[9];
        const char close = open == '"' ? '"' : '>';
        const size_t end = text.find(close, 10);
        if ((open != '"' && open != '<') || end == std::string::npos) continue;
        out.push_back({file.string(), line, text.substr(10, end - 10), open == '"'});
    }
    return out;
}

TEST(Layering, IncludesPointDownOnly) {
    const fs::path root = ISPM_SOURCE_DIR;
    int files = 0;
    for (const auto& [folder, allowed] : getAllowed()) {
        const bool knowsGl = allowed.count("gl") > 0;
        for (const auto& entry : fs::directory_iterator(root / folder)) {
            const std::string ext = entry.path().extension().string();
            if (ext != ".cpp" && ext != ".h") continue;
            ++files;
            for (const Include& inc : readIncludes(entry.path())) {
                if (inc.quoted) {
                    const size_t slash = inc.path.find('/');
                    // "x.h" without a folder: a neighbour in the same folder.
                    if (slash == std::string::npos) continue;
                    const std::string layer = inc.path.substr(0, slash);
                    EXPECT_TRUE(allowed.count(layer) > 0) << inc.file << ":" << inc.line << ": "
                                                          << folder << " includes " << inc.path;
                } else if (!knowsGl) {
                    EXPECT_FALSE(isGlHeader(inc.path))
                        << inc.file << ":" << inc.line << ": " << folder << " includes <"
                        << inc.path << "> and must know no GL";
                }
            }
        }
    }
    EXPECT_GT(files, 50) << "the sources were not found under " << root;
}

} // namespace
} // namespace ispm
