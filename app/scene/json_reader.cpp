// Checked JSON reading for scene files. Parsing tracks the JSON path of every value as it goes so
// that errors nlohmann reports without a path (number overflow, duplicate keys) still get one.
#include "scene/json_reader.h"

#include "core/input_error.h"
#include "core/strings.h"

#include <array>
#include <charconv>
#include <cmath>
#include <set>

namespace ispm {

namespace {

constexpr size_t kMaxShownValueChars = 40; // longer values are cut in messages, which stay one line
// Scene files nest a handful of levels (an animation's keyframes are the deepest, at 5). Deeper
// text is refused as it is read: each level costs the path tracker a path as long as the depth,
// and 100,000 levels exhausted memory and the stack.
constexpr int kMaxJsonDepth = 64;

// Follows nlohmann's parse callbacks to know the JSON path of the value being read.
class PathTracker {
  public:
    explicit PathTracker(const std::string& file) : mFile(file) {}

    bool onEvent(nlohmann::json::parse_event_t event, const nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        switch (event) {
        case Event::object_start:
        case Event::array_start: {
            std::string path = getCurrentPath();
            if (!mFrames.empty() && mFrames.back().isArray) ++mFrames.back().nextIndex;
            mFrames.push_back({event == Event::array_start, std::move(path), 0, {}, {}});
            break;
        }
        case Event::key: {
            Frame& frame = mFrames.back();
            frame.key = parsed.get<std::string>();
            if (!frame.keys.insert(frame.key).second) {
                throwInputError(mFile, getCurrentPath(),
                                strCat("each key once per object, got '", frame.key, "' twice"));
            }
            break;
        }
        case Event::value:
            if (!mFrames.empty() && mFrames.back().isArray) ++mFrames.back().nextIndex;
            break;
        case Event::object_end:
        case Event::array_end:
            mFrames.pop_back();
            break;
        }
        return true;
    }

    // The path of the value about to be read (or being read when an exception stopped parsing).
    std::string getCurrentPath() const {
        if (mFrames.empty()) return "";
        const Frame& frame = mFrames.back();
        if (frame.isArray) return strCat(frame.path, "/", frame.nextIndex);
        return frame.path + "/" + escapeJsonPointer(frame.key);
    }

  private:
    struct Frame {
        bool isArray;
        std::string path;
        size_t nextIndex;
        std::string key;
        std::set<std::string> keys;
    };
    const std::string& mFile;
    std::vector<Frame> mFrames;
};

// nlohmann's messages read "[json.exception.parse_error.101] parse error at line 3, column 7:
// syntax error ..."; keep the location and the detail, drop the prefix.
[[noreturn]] void throwParseError(const std::string& file, const nlohmann::json::parse_error& e) {
    const std::string message = e.what();
    const size_t at = message.find(" at line ");
    const size_t colon = at == std::string::npos ? std::string::npos : message.find(": ", at);
    if (colon == std::string::npos) {
        throwInputError(file, strCat("byte ", e.byte), strCat("valid JSON (", message, ")"));
    }
    const std::string location = message.substr(at + 4, colon - at - 4);
    throwInputError(file, location, strCat("valid JSON (", message.substr(colon + 2), ")"));
}

std::string showValue(const nlohmann::json& value) {
    std::string text;
    if (value.is_number()) {
        text = strCat(value.get<double>()); // dump() would print inf as null
    } else {
        text = value.dump();
    }
    if (text.size() > kMaxShownValueChars) text = text.substr(0, kMaxShownValueChars) + "...";
    return text;
}

std::string formatNumber(double v) {
    return strCat(v);
}

// "[json.exception.out_of_range.406] number overflow ..." -> "number overflow ...".
std::string stripExceptionId(const std::string& message) {
    const size_t end = message.find("] ");
    return message.rfind("[json.exception.", 0) == 0 && end != std::string::npos
               ? message.substr(end + 2)
               : message;
}

} // namespace

nlohmann::json parseJsonText(const std::string& text, const std::string& file) {
    PathTracker tracker(file);
    const nlohmann::json::parser_callback_t callback =
        [&tracker, &file](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
            using Event = nlohmann::json::parse_event_t;
            if (depth >= kMaxJsonDepth &&
                (event == Event::object_start || event == Event::array_start)) {
                throwInputError(file, tracker.getCurrentPath(),
                                strCat("at most ", kMaxJsonDepth, " levels of nesting"));
            }
            return tracker.onEvent(event, parsed);
        };
    try {
        return nlohmann::json::parse(text, callback, /*allow_exceptions=*/true,
                                     /*ignore_comments=*/false);
    } catch (const nlohmann::json::parse_error& e) {
        throwParseError(file, e);
    } catch (const nlohmann::json::out_of_range& e) {
        // 406: a number too large for a double (1e999); nlohmann gives no position, the tracker
        // does.
        throwInputError(file, tracker.getCurrentPath(),
                        strCat("a finite number (", stripExceptionId(e.what()), ")"));
    } catch (const nlohmann::json::exception& e) {
        throwInputError(file, tracker.getCurrentPath(),
                        strCat("valid JSON (", stripExceptionId(e.what()), ")"));
    }
}

std::string formatFloat(float v) {
    constexpr size_t kMaxFloatChars = 32; // the longest float needs ~15
    std::array<char, kMaxFloatChars> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
    return std::string(buffer.data(), result.ptr);
}

std::string escapeJsonPointer(std::string_view key) {
    std::string out;
    for (char c : key) {
        if (c == '~') {
            out += "~0";
        } else if (c == '/') {
            out += "~1";
        } else {
            out += c;
        }
    }
    return out;
}

bool NumberRange::contains(double v) const {
    if (!std::isfinite(v)) return false;
    const bool aboveLo = isLoOpen ? v > lo : v >= lo;
    const bool belowHi = isHiOpen ? v < hi : v <= hi;
    return aboveLo && belowHi;
}

std::string NumberRange::describe() const {
    const bool hasLo = std::isfinite(lo);
    const bool hasHi = std::isfinite(hi);
    if (hasLo && hasHi) {
        return strCat("a number in ", isLoOpen ? "(" : "[", formatNumber(lo), ", ",
                      formatNumber(hi), isHiOpen ? ")" : "]");
    }
    if (hasLo) return strCat("a number ", isLoOpen ? "> " : ">= ", formatNumber(lo));
    if (hasHi) return strCat("a number ", isHiOpen ? "< " : "<= ", formatNumber(hi));
    return "a finite number";
}

void JsonNode::fail(const std::string& expected) const {
    throwInputError(*mFile, mPath, expected);
}

void JsonNode::failGot(const std::string& expected) const {
    throwInputError(*mFile, mPath, strCat(expected, ", got ", showValue(*mValue)));
}

void JsonNode::requireObject(std::string_view what) const {
    if (!mValue->is_object()) failGot(strCat(what, " (a JSON object)"));
}

void JsonNode::checkKeys(std::initializer_list<std::string_view> known,
                         std::string_view what) const {
    requireObject(what);
    for (const auto& item : mValue->items()) {
        bool isKnown = false;
        for (std::string_view k : known)
            isKnown = isKnown || k == item.key();
        if (isKnown) continue;
        std::string list;
        for (std::string_view k : known)
            list += (list.empty() ? "" : ", ") + std::string(k);
        child(item.key())
            .fail(strCat("a key of ", what, " (", list, "), got unknown key '", item.key(), "'"));
    }
}

bool JsonNode::has(std::string_view key) const {
    return mValue->is_object() && mValue->find(key) != mValue->end();
}

JsonNode JsonNode::get(std::string_view key) const {
    if (!has(key)) {
        // Name the missing key's own path, so the message points where it belongs.
        throwInputError(*mFile, mPath + "/" + escapeJsonPointer(key),
                        strCat("the required key '", key, "'"));
    }
    return child(key);
}

std::optional<JsonNode> JsonNode::find(std::string_view key) const {
    if (!has(key)) return std::nullopt;
    return child(key);
}

std::vector<std::pair<std::string, JsonNode>> JsonNode::getMembers() const {
    std::vector<std::pair<std::string, JsonNode>> members;
    for (const auto& item : mValue->items())
        members.emplace_back(item.key(), child(item.key()));
    return members;
}

std::vector<JsonNode> JsonNode::getElements(std::string_view what) const {
    if (!mValue->is_array()) failGot(strCat(what, " (a JSON array)"));
    std::vector<JsonNode> elements;
    elements.reserve(mValue->size());
    for (size_t i = 0; i < mValue->size(); ++i)
        elements.push_back(child(i));
    return elements;
}

double JsonNode::readNumber(const NumberRange& range) const {
    if (!mValue->is_number()) failGot(range.describe());
    const double v = mValue->get<double>();
    if (!range.contains(v)) failGot(range.describe());
    return v;
}

float JsonNode::readFloat(const NumberRange& range) const {
    const double v = readNumber(range);
    if (std::fabs(v) > static_cast<double>(std::numeric_limits<float>::max())) {
        failGot(strCat(range.describe(), " within single-precision range"));
    }
    return static_cast<float>(v);
}

int64_t JsonNode::readInt(int64_t lo, int64_t hi) const {
    const std::string what = strCat("an integer in [", lo, ", ", hi, "]");
    if (!mValue->is_number()) failGot(what);
    if (mValue->is_number_integer()) {
        // is_number_integer is also true for unsigned values; those above int64 are out of range.
        if (mValue->is_number_unsigned() &&
            mValue->get<uint64_t>() > static_cast<uint64_t>(std::numeric_limits<int64_t>::max())) {
            failGot(what);
        }
        const int64_t v = mValue->get<int64_t>();
        if (v < lo || v > hi) failGot(what);
        return v;
    }
    // 3.0 is accepted as 3: JSON writers do not always keep the distinction.
    const double v = mValue->get<double>();
    if (!std::isfinite(v) || v != std::floor(v) || v < static_cast<double>(lo) ||
        v > static_cast<double>(hi)) {
        failGot(what);
    }
    return static_cast<int64_t>(v);
}

uint64_t JsonNode::readUint64() const {
    const char* what = "an integer in [0, 18446744073709551615]";
    if (mValue->is_number_unsigned()) return mValue->get<uint64_t>();
    if (mValue->is_number_integer()) {
        if (mValue->get<int64_t>() < 0) failGot(what);
        return static_cast<uint64_t>(mValue->get<int64_t>());
    }
    // Doubles are exact integers only up to 2^53; beyond that the value was already rounded.
    constexpr double kMaxExactDouble = 9007199254740992.0; // 2^53
    if (!mValue->is_number()) failGot(what);
    const double v = mValue->get<double>();
    if (!std::isfinite(v) || v != std::floor(v) || v < 0 || v > kMaxExactDouble) failGot(what);
    return static_cast<uint64_t>(v);
}

std::string JsonNode::readString() const {
    if (!mValue->is_string()) failGot("a string");
    return mValue->get<std::string>();
}

bool JsonNode::readBool() const {
    if (!mValue->is_boolean()) failGot("true or false");
    return mValue->get<bool>();
}

std::vector<JsonNode> JsonNode::readFixedArray(size_t count, std::string_view what) const {
    if (!mValue->is_array() || mValue->size() != count) failGot(std::string(what));
    return getElements(what);
}

glm::vec3 JsonNode::readVec3(const NumberRange& range) const {
    const std::vector<JsonNode> e = readFixedArray(3, "3 numbers");
    return {e[0].readFloat(range), e[1].readFloat(range), e[2].readFloat(range)};
}

glm::vec3 JsonNode::readDirection() const {
    const glm::vec3 v = readVec3();
    const float length = glm::length(v);
    if (!(length > 0.0f) || !std::isfinite(length)) failGot("a non-zero direction (3 numbers)");
    return v / length;
}

glm::vec2 JsonNode::readFloatPair(const NumberRange& range) const {
    const std::vector<JsonNode> e = readFixedArray(2, "2 numbers [min, max]");
    const glm::vec2 v{e[0].readFloat(range), e[1].readFloat(range)};
    if (v.x > v.y) failGot("[min, max] with min <= max");
    return v;
}

glm::ivec2 JsonNode::readIntPair(int64_t lo, int64_t hi) const {
    const std::vector<JsonNode> e = readFixedArray(2, "2 integers [min, max]");
    const glm::ivec2 v{static_cast<int>(e[0].readInt(lo, hi)),
                       static_cast<int>(e[1].readInt(lo, hi))};
    if (v.x > v.y) failGot("[min, max] with min <= max");
    return v;
}

glm::vec2 JsonNode::readVec2(const NumberRange& range) const {
    const std::vector<JsonNode> e = readFixedArray(2, "2 numbers [x, z]");
    return {e[0].readFloat(range), e[1].readFloat(range)};
}

glm::ivec2 JsonNode::readIVec2(int64_t lo, int64_t hi) const {
    const std::vector<JsonNode> e = readFixedArray(2, "2 integers [x, z]");
    return {static_cast<int>(e[0].readInt(lo, hi)), static_cast<int>(e[1].readInt(lo, hi))};
}

JsonNode JsonNode::child(std::string_view key) const {
    return JsonNode(mValue->find(key).value(), mPath + "/" + escapeJsonPointer(key), *mFile);
}

JsonNode JsonNode::child(size_t index) const {
    return JsonNode((*mValue)[index], strCat(mPath, "/", index), *mFile);
}

} // namespace ispm
