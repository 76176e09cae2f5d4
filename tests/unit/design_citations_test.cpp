// The design lives in docs/design.md: no source names the plan it grew from, and every section a
// comment cites there is one of its headings. A failure names the file and the line.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace ispm {
namespace {

namespace fs = std::filesystem;

// Where the sources that may cite the design live, and the files read there.
constexpr std::array<std::string_view, 5> kCitingFolders = {"app", "gl", "shaders", "tests",
                                                            "tools"};
constexpr std::array<std::string_view, 9> kCitingExtensions = {
    ".cpp", ".h", ".glsl", ".vert", ".frag", ".geom", ".comp", ".py", ".sh"};
constexpr std::string_view kDesignPath = "docs/design.md";
// This file spells what it looks for in its code, so it is not read.
constexpr std::string_view kThisFile = "design_citations_test.cpp";

// The plan's old file name, built from pieces so that no source spells it out.
std::string getRetiredName() {
    return std::string("DESIGN") + ".md";
}

std::vector<std::string> readLines(const fs::path& file) {
    std::vector<std::string> lines;
    std::ifstream in(file);
    std::string text;
    while (std::getline(in, text))
        lines.push_back(text);
    return lines;
}

// The headings of a Markdown file, at any level: the text after the #s, without the spaces round
// it. Lines inside fenced code blocks are not headings.
std::set<std::string> readHeadings(const fs::path& file) {
    std::set<std::string> headings;
    bool inFence = false;
    for (const std::string& text : readLines(file)) {
        const size_t start = text.find_first_not_of(" \t");
        if (start != std::string::npos && text.compare(start, 3, "```") == 0) {
            inFence = !inFence;
            continue;
        }
        if (inFence || text.empty() || text[0] != '#') continue;
        const size_t first = text.find_first_not_of(" \t", text.find_first_not_of('#'));
        if (first == std::string::npos) continue;
        const size_t last = text.find_last_not_of(" \t\r");
        headings.insert(text.substr(first, last - first + 1));
    }
    return headings;
}

// The files under the citing folders with a citing extension, in path order.
std::vector<fs::path> listCitingFiles(const fs::path& root) {
    std::vector<fs::path> files;
    for (std::string_view folder : kCitingFolders) {
        const fs::path dir = root / folder;
        if (!fs::is_directory(dir)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(dir)) {
            if (!entry.is_regular_file() || entry.path().filename().string() == kThisFile) continue;
            const std::string ext = entry.path().extension().string();
            if (std::find(kCitingExtensions.begin(), kCitingExtensions.end(), ext) !=
                kCitingExtensions.end()) {
                files.push_back(entry.path());
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

// A line without its indentation and comment leaders (//, #, *): where a cited section quoted at
// the start of a comment's next line begins.
std::string_view skipCommentLeader(std::string_view line) {
    const size_t start = line.find_first_not_of(" \t/#*");
    return start == std::string_view::npos ? std::string_view() : line.substr(start);
}

// The section quoted at the start of `text` ("Heading"): none when `text` does not start with a
// quote, "" when the quote does not close on the line.
std::optional<std::string> findQuotedSection(std::string_view text) {
    if (text.empty() || text[0] != '"') return std::nullopt;
    const size_t close = text.find('"', 1);
    if (close == std::string_view::npos) return std::string();
    return std::string(text.substr(1, close - 1));
}

struct Citation {
    std::string where; // file:line, the file relative to the repository
    std::string section;
};

// Every docs/design.md "Section" in `lines`, the section on the same line (after an optional
// comma) or at the start of the next comment line. A path in code ("docs/... or /docs/...) is
// not a citation.
std::vector<Citation> findCitations(const std::vector<std::string>& lines,
                                    const std::string& file) {
    std::vector<Citation> citations;
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::string_view line = lines[i];
        for (size_t at = line.find(kDesignPath); at != std::string_view::npos;
             at = line.find(kDesignPath, at + 1)) {
            if (at > 0 && (line[at - 1] == '"' || line[at - 1] == '/' || line[at - 1] == '\''))
                continue;
            std::string_view rest = line.substr(at + kDesignPath.size());
            const size_t next = rest.find_first_not_of(", \t\r");
            rest = next == std::string_view::npos ? std::string_view() : rest.substr(next);
            if (rest.empty() && i + 1 < lines.size()) rest = skipCommentLeader(lines[i + 1]);
            if (const std::optional<std::string> section = findQuotedSection(rest))
                citations.push_back({file + ":" + std::to_string(i + 1), *section});
        }
    }
    return citations;
}

TEST(DesignCitations, NoSourceNamesTheRetiredPlan) {
    const fs::path root = ISPM_SOURCE_DIR;
    const std::string retired = getRetiredName();
    const std::vector<fs::path> files = listCitingFiles(root);
    for (const fs::path& path : files) {
        const std::vector<std::string> lines = readLines(path);
        for (size_t i = 0; i < lines.size(); ++i) {
            if (lines[i].find(retired) == std::string::npos) continue;
            ADD_FAILURE() << fs::relative(path, root).string() << ":" << i + 1 << ": names "
                          << retired << "; the design is " << kDesignPath;
        }
    }
    EXPECT_GT(files.size(), 100u) << "the sources were not found under " << root;
}

TEST(DesignCitations, CitedSectionsAreHeadingsOfTheDesign) {
    const fs::path root = ISPM_SOURCE_DIR;
    const fs::path design = root / kDesignPath;
    ASSERT_TRUE(fs::is_regular_file(design)) << design << " is missing";
    const std::set<std::string> headings = readHeadings(design);
    ASSERT_FALSE(headings.empty()) << design << " has no heading";
    size_t cited = 0;
    for (const fs::path& path : listCitingFiles(root)) {
        const std::string file = fs::relative(path, root).string();
        for (const Citation& citation : findCitations(readLines(path), file)) {
            ++cited;
            if (citation.section.empty()) {
                ADD_FAILURE() << citation.where << ": the section cited from " << kDesignPath
                              << " is not quoted whole on one line";
            } else if (headings.count(citation.section) == 0) {
                ADD_FAILURE() << citation.where << ": cites " << kDesignPath << " \""
                              << citation.section << "\", which has no such heading";
            }
        }
    }
    EXPECT_GT(cited, 0u) << "no source cites a section of " << kDesignPath;
}

} // namespace
} // namespace ispm
