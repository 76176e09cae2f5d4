// The settings tables in README.md (user settings) and docs/settings.md (every setting, by group)
// are the code's table, word for word: documentation cannot drift from the settings the renderer
// accepts. And each help string stays one line that a tooltip or a table cell can hold.
#include "settings/settings.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
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
    EXPECT_EQ(readBetweenMarkers(root + "/README.md"), formatUserSettingsMarkdown())
        << "README.md: regenerate the table with `ispm settings`";
    EXPECT_EQ(readBetweenMarkers(root + "/docs/settings.md"), formatAllSettingsMarkdown())
        << "docs/settings.md: regenerate the tables with `ispm settings --all`";
}

TEST(SettingsDocs, TheUserTableListsUserSettingsOnly) {
    const std::string user = formatUserSettingsMarkdown();
    const std::string all = formatAllSettingsMarkdown();
    int users = 0;
    for (const SettingDesc& d : getSettingTable()) {
        const std::string cell = "| `" + std::string(d.name) + "` |";
        EXPECT_NE(all.find(cell), std::string::npos) << d.name << " missing from the full table";
        const bool isUser = d.level == SettingLevel::User;
        EXPECT_EQ(user.find(cell) != std::string::npos, isUser) << d.name;
        users += isUser ? 1 : 0;
    }
    // A user table of a few dozen rows is one a newcomer reads; most settings tune the method.
    EXPECT_GT(users, 10);
    EXPECT_LT(users, static_cast<int>(getSettingTable().size()) / 2 + 1);
}

TEST(SettingsDocs, HelpIsOneShortLine) {
    for (const SettingDesc& d : getSettingTable()) {
        EXPECT_FALSE(d.help.empty()) << d.name;
        EXPECT_LE(d.help.size(), kMaxSettingHelpChars) << d.name << ": " << d.help;
        EXPECT_EQ(d.help.find('\n'), std::string_view::npos) << d.name;
        EXPECT_EQ(d.help.find('|'), std::string_view::npos) << d.name << ": breaks the table";
    }
}

TEST(SettingsDocs, EveryGroupHoldsAUserSetting) {
    // A group with user settings only folded away would hide them in the viewer.
    std::set<SettingGroup> withUser;
    for (const SettingDesc& d : getSettingTable()) {
        if (d.level == SettingLevel::User) withUser.insert(d.group);
    }
    EXPECT_EQ(withUser.size(), kSettingGroupNames.size());
}

} // namespace
} // namespace ispm::test
