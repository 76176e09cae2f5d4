// Checked reading of scene JSON: every node knows its file and JSON pointer, so each mistake in
// a scene becomes one InputError line "file: /json/path: expected ...". Internal to ispm_scene.
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ispm {

// Parses JSON text. Syntax errors (with line and column), numbers that overflow a double (with
// the JSON path where they stand) and keys given twice in one object become InputError.
nlohmann::json parseJsonText(const std::string& text, const std::string& file);

// The accepted interval of a number, and the words that describe it in a message.
struct NumberRange {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool isLoOpen = false;
    bool isHiOpen = false;

    static NumberRange getAny() { return {}; }
    // Positions, offsets and angles: within 10,000 km (or degrees), where a float still resolves
    // a metre and the renderer's derived planes and epsilons stay finite (3e38 gave NaN pixels).
    static NumberRange getCoordinate() { return {-kMaxCoordinate, kMaxCoordinate, false, false}; }
    static constexpr double kMaxCoordinate = 1e7;
    static NumberRange getAtLeast(double lo) { return {lo, kInf, false, false}; }
    static NumberRange getAbove(double lo) { return {lo, kInf, true, false}; }
    static NumberRange getClosed(double lo, double hi) { return {lo, hi, false, false}; }
    static NumberRange getOpen(double lo, double hi) { return {lo, hi, true, true}; }
    static NumberRange getLeftOpen(double lo, double hi) { return {lo, hi, true, false}; }

    bool contains(double v) const;
    std::string describe() const; // "a number in (0, 180)", "a number >= 0" ...

    static constexpr double kInf = std::numeric_limits<double>::infinity();
};

class JsonNode {
  public:
    JsonNode(const nlohmann::json& value, std::string path, const std::string& file)
        : mValue(&value), mPath(std::move(path)), mFile(&file) {}

    const nlohmann::json& getJson() const { return *mValue; }
    const std::string& getPath() const { return mPath; }
    const std::string& getFile() const { return *mFile; }

    // Throws InputError "file: path: expected <expected>".
    [[noreturn]] void fail(const std::string& expected) const;
    // As fail(), followed by ", got <the value as written>".
    [[noreturn]] void failGot(const std::string& expected) const;

    // Objects. `what` names the expected thing in the message ("a material").
    void requireObject(std::string_view what) const;
    // Fails on the first key that is not in `known`, naming it and listing the known ones.
    void checkKeys(std::initializer_list<std::string_view> known, std::string_view what) const;
    bool has(std::string_view key) const;
    JsonNode get(std::string_view key) const; // a required key
    std::optional<JsonNode> find(std::string_view key) const;
    std::vector<std::pair<std::string, JsonNode>> getMembers() const;

    // Arrays: the elements, failing unless this is an array.
    std::vector<JsonNode> getElements(std::string_view what) const;

    // Scalars: fail with the range's words on a wrong type, NaN/inf or an out-of-range value.
    double readNumber(const NumberRange& range) const;
    float readFloat(const NumberRange& range) const; // also fails outside float's range
    int64_t readInt(int64_t lo, int64_t hi) const;
    uint64_t readUint64() const;
    std::string readString() const;
    bool readBool() const; // true or false, nothing else

    // Exactly 3 numbers; each element checked against `range` (errors name the element's path).
    glm::vec3 readVec3(const NumberRange& range = NumberRange::getCoordinate()) const;
    // A non-zero vector, normalised.
    glm::vec3 readDirection() const;
    // [min, max] with each in `range` and min <= max.
    glm::vec2 readFloatPair(const NumberRange& range) const;
    glm::ivec2 readIntPair(int64_t lo, int64_t hi) const;
    // Exactly 2 numbers (x, z pairs that are not ranges).
    glm::vec2 readVec2(const NumberRange& range) const;
    glm::ivec2 readIVec2(int64_t lo, int64_t hi) const;

  private:
    JsonNode child(std::string_view key) const;
    JsonNode child(size_t index) const;
    std::vector<JsonNode> readFixedArray(size_t count, std::string_view what) const;

    const nlohmann::json* mValue;
    std::string mPath;
    const std::string* mFile;
};

// The shortest text that reads back as `v` ("0.8", not "0.800000012"), for messages.
std::string formatFloat(float v);

// JSON pointer escaping of one key ("~" -> "~0", "/" -> "~1").
std::string escapeJsonPointer(std::string_view key);

} // namespace ispm
