// Every relative link and image in README.md and docs/*.md names a file that exists, and every
// #anchor a heading of its file: text moved between documents cannot leave a dead link behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace ispm {
namespace {

namespace fs = std::filesystem;

// A link or image as written: the Markdown file, its line (from 1) and the target in parentheses.
struct Link {
    fs::path file;
    int line = 0;
    std::string target;
};

// Lines of a Markdown file with fenced code blocks blanked (left as empty lines, so that line
// numbers stay those of the file): what a fence holds is code, not links or headings.
std::vector<std::string> readProseLines(const fs::path& file) {
    std::vector<std::string> lines;
    std::ifstream in(file);
    std::string text;
    bool inFence = false;
    while (std::getline(in, text)) {
        if (!text.empty() && text.back() == '\r') text.pop_back();
        const size_t first = text.find_first_not_of(" \t");
        const bool isFence = first != std::string::npos && (text.compare(first, 3, "```") == 0 ||
                                                            text.compare(first, 3, "~~~") == 0);
        if (isFence) inFence = !inFence;
        lines.push_back(isFence || inFence ? std::string() : text);
    }
    return lines;
}

// Inline code spans hold commands and globs (`[--camera NAME]`), not links: each becomes a plain
// word, so that a link whose text is code (`[`animation`](#animation)`) is still found.
std::string replaceCodeSpans(const std::string& line) {
    static const std::regex kCodeSpan("`[^`]*`");
    return std::regex_replace(line, kCodeSpan, "code");
}

// GitHub's anchor for a heading: links reduced to their text, lower case, spaces to '-', other
// punctuation than '-' and '_' dropped; the bytes of non-ASCII characters are kept as letters.
std::string makeSlug(const std::string& heading) {
    static const std::regex kInlineLink(R"(!?\[([^\]]*)\]\([^)]*\))");
    std::string slug;
    for (const char c : std::regex_replace(heading, kInlineLink, "$1")) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == ' ') {
            slug += '-';
        } else if (std::isalnum(byte) || c == '-' || c == '_' || byte >= 0x80) {
            slug += static_cast<char>(std::tolower(byte));
        }
    }
    return slug;
}

// The anchors of a file's headings; a repeated slug gets -1, -2 ... as on GitHub.
std::set<std::string> readAnchors(const fs::path& file) {
    static const std::regex kHeading(R"(^#{1,6}[ \t]+(.*?)[ \t#]*$)");
    std::set<std::string> anchors;
    std::map<std::string, int> seen;
    for (const std::string& line : readProseLines(file)) {
        std::smatch match;
        if (!std::regex_match(line, match, kHeading)) continue;
        const std::string slug = makeSlug(match[1].str());
        const int repeats = seen[slug]++;
        anchors.insert(repeats == 0 ? slug : slug + "-" + std::to_string(repeats));
    }
    return anchors;
}

bool isExternal(const std::string& target) {
    for (const char* scheme : {"http:", "https:", "mailto:"}) {
        if (target.rfind(scheme, 0) == 0) return true;
    }
    return false;
}

// Every relative `[text](target)` and `![alt](target)` outside code, with its line.
std::vector<Link> findRelativeLinks(const fs::path& file) {
    static const std::regex kLink(R"(!?\[[^\]]*\]\(([^)\s]+)(?:\s+"[^"]*")?\))");
    std::vector<Link> links;
    const std::vector<std::string> lines = readProseLines(file);
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::string prose = replaceCodeSpans(lines[i]);
        for (auto it = std::sregex_iterator(prose.begin(), prose.end(), kLink);
             it != std::sregex_iterator(); ++it) {
            const std::string target = (*it)[1].str();
            if (!isExternal(target)) links.push_back({file, static_cast<int>(i) + 1, target});
        }
    }
    return links;
}

// What is wrong with a link, or "" when its file exists and its anchor names a heading there.
// Anchors are checked in Markdown files only (and within the linking file itself).
std::string checkLink(const Link& link, std::map<std::string, std::set<std::string>>& anchors) {
    const size_t hash = link.target.find('#');
    const std::string pathPart = link.target.substr(0, hash);
    const fs::path resolved =
        pathPart.empty() ? link.file : (link.file.parent_path() / pathPart).lexically_normal();
    if (!fs::exists(resolved)) return "no such file: " + resolved.string();
    if (hash == std::string::npos || resolved.extension() != ".md") return "";
    const std::string anchor = link.target.substr(hash + 1);
    const std::string key = resolved.string();
    if (anchors.count(key) == 0) anchors[key] = readAnchors(resolved);
    if (anchors[key].count(anchor) == 0) return "no heading with the anchor #" + anchor;
    return "";
}

TEST(DocsLinks, SlugsAreGitHubs) {
    EXPECT_EQ(makeSlug("Where the method fails"), "where-the-method-fails");
    EXPECT_EQ(makeSlug("`animation`"), "animation");
    EXPECT_EQ(makeSlug("Splat and filter: radii, 1/2 (auto)"), "splat-and-filter-radii-12-auto");
    EXPECT_EQ(makeSlug("splat_mode and dof-focus"), "splat_mode-and-dof-focus");
    EXPECT_EQ(makeSlug("See [glTF](#gltf) files"), "see-gltf-files");
}

TEST(DocsLinks, RelativeLinksAndAnchorsResolve) {
    const fs::path root = ISPM_SOURCE_DIR;
    ASSERT_TRUE(fs::exists(root / "README.md")) << root / "README.md";
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(root / "docs")) {
        if (entry.is_regular_file() && entry.path().extension() == ".md") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    files.insert(files.begin(), root / "README.md");

    std::map<std::string, std::set<std::string>> anchors;
    int linkCount = 0;
    for (const fs::path& file : files) {
        for (const Link& link : findRelativeLinks(file)) {
            ++linkCount;
            const std::string problem = checkLink(link, anchors);
            if (!problem.empty()) {
                ADD_FAILURE() << fs::relative(link.file, root).string() << ":" << link.line << ": ("
                              << link.target << "): " << problem;
            }
        }
    }
    // README links every document in docs/: none found means the pattern above is broken.
    EXPECT_GT(linkCount, 0) << "no relative links found in README.md and docs/*.md";
}

} // namespace
} // namespace ispm
