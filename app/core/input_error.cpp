// One-line user-input errors: "file: /json/path: expected ...". Newlines from nested messages
// (tinyobjloader, nlohmann) are folded so the CLI can print the error on a single line.
#include "core/input_error.h"

namespace ispm {

namespace {

std::string foldLines(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        if (c == '\r') continue;
        if (c == '\n') {
            // A trailing newline adds nothing; an inner one becomes a separator.
            out += "; ";
        } else {
            out += c;
        }
    }
    while (out.size() >= 2 && out.compare(out.size() - 2, 2, "; ") == 0)
        out.resize(out.size() - 2);
    return out;
}

} // namespace

void throwInputError(const std::string& file, const std::string& jsonPath,
                     const std::string& what) {
    std::string message;
    if (!file.empty()) message += file + ": ";
    if (!jsonPath.empty()) message += jsonPath + ": ";
    message += "expected " + what;
    throw InputError(foldLines(message));
}

} // namespace ispm
