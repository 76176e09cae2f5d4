// The settings tables in README.md and docs/scene-format.md are the code's table, word for word:
// documentation cannot drift from the settings the renderer accepts.
#include "settings/settings.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace ispm::test {
namespace {

std::string readBetweenMarkers(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    const std::string all = text.str();
    const std::string begin = "<!-- settings-table:begin -->\n";
    const std::string end = "<!-- settings-table:end -->";
    const size_t b = all.find(begin);
    const size_t e = all.find(end);
    if (b == std::string::npos || e == std::string::npos || e < b) return "<markers missing>";
    return all.substr(b + begin.size(), e - b - begin.size());
}

TEST(SettingsDocs, TablesMatchTheCode) {
    const std::string root = std::string(ISPM_TEST_DATA_DIR) + "/..";
    for (const char* file : {"/README.md", "/docs/scene-format.md"}) {
        EXPECT_EQ(readBetweenMarkers(root + file), formatSettingsMarkdown())
            << file << ": regenerate the table with `ispm settings`";
    }
}

} // namespace
} // namespace ispm::test
