// Texture files to 8-bit sRGB RGBA; the one place the scene layer decodes images.
#include "scene/scene_texture.h"

#include "core/strings.h"

#include <stb_image.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace ispm {

namespace {

constexpr int kRgbaChannels = 4;
constexpr int kMaxCode8 = 255;
constexpr int kMaxCode16 = 65535;

} // namespace

float decodeSrgb(uint8_t code) {
    // IEC 61966-2-1: linear below the knee, a 2.4 power above.
    constexpr float kKnee = 0.04045f;
    constexpr float kLinearSlope = 12.92f;
    constexpr float kOffset = 0.055f;
    constexpr float kGamma = 2.4f;
    const float c = float(code) / float(kMaxCode8);
    return c <= kKnee ? c / kLinearSlope : std::pow((c + kOffset) / (1.0f + kOffset), kGamma);
}

glm::vec3 computeLinearMean(const SceneTexture& texture) {
    std::array<float, kMaxCode8 + 1> table{};
    for (int i = 0; i <= kMaxCode8; ++i)
        table[static_cast<size_t>(i)] = decodeSrgb(static_cast<uint8_t>(i));
    glm::dvec3 sum(0.0);
    const size_t count = static_cast<size_t>(texture.width) * static_cast<size_t>(texture.height);
    for (size_t i = 0; i < count; ++i) {
        for (int c = 0; c < 3; ++c)
            sum[c] += double(table[texture.rgba[i * kRgbaChannels + static_cast<size_t>(c)]]);
    }
    return count == 0 ? glm::vec3(1.0f) : glm::vec3(sum / double(count));
}

bool convertToRgba8(const uint8_t* pixels, int width, int height, int channels, int bits,
                    SceneTexture& out) {
    if (width <= 0 || height <= 0 || channels < 1 || channels > kRgbaChannels ||
        (bits != 8 && bits != 16)) {
        return false;
    }
    const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
    out.width = width;
    out.height = height;
    out.rgba.assign(count * kRgbaChannels, static_cast<uint8_t>(kMaxCode8));
    const auto read = [&](size_t i) -> uint8_t {
        if (bits == 8) return pixels[i];
        uint16_t v = 0;
        std::memcpy(&v, pixels + 2 * i, sizeof(v));
        return static_cast<uint8_t>((v * kMaxCode8 + kMaxCode16 / 2) / kMaxCode16);
    };
    const auto in = static_cast<size_t>(channels);
    for (size_t p = 0; p < count; ++p) {
        uint8_t* o = &out.rgba[p * kRgbaChannels];
        if (channels <= 2) { // grey (+ alpha)
            o[0] = o[1] = o[2] = read(p * in);
            if (channels == 2) o[3] = read(p * in + 1);
        } else {
            for (size_t c = 0; c < in; ++c)
                o[c] = read(p * in + c);
        }
    }
    return true;
}

SceneTexture readTextureFile(const std::string& path) {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load(path.c_str(), &width, &height, &channels, kRgbaChannels), stbi_image_free);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        throw std::runtime_error(
            strCat("cannot read the image (", reason ? reason : "unknown", ")"));
    }
    SceneTexture texture;
    texture.name = std::filesystem::path(path).filename().string();
    texture.sourcePath = path;
    convertToRgba8(pixels.get(), width, height, kRgbaChannels, 8, texture);
    return texture;
}

} // namespace ispm
