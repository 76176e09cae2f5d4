// Packing the scene's textures into one mipmapped sRGB array.
#include "render/scene_texture_array.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace ispm {

namespace {

constexpr size_t kRgbaBytes = 4;
constexpr uint8_t kWhite = 255;

} // namespace

std::vector<uint8_t> resampleTexture(const SceneTexture& texture, int width, int height) {
    if (texture.width == width && texture.height == height) return texture.rgba;
    std::vector<uint8_t> out(static_cast<size_t>(width) * static_cast<size_t>(height) * kRgbaBytes);
    const auto texel = [&](int x, int y, size_t c) -> float {
        x = (x % texture.width + texture.width) % texture.width;
        y = (y % texture.height + texture.height) % texture.height;
        const size_t at =
            (static_cast<size_t>(y) * static_cast<size_t>(texture.width) + static_cast<size_t>(x)) *
                kRgbaBytes +
            c;
        return float(texture.rgba[at]);
    };
    for (int y = 0; y < height; ++y) {
        // Texel centres of the output in the input's texel coordinates.
        const float sy = (float(y) + 0.5f) * float(texture.height) / float(height) - 0.5f;
        const int y0 = int(std::floor(sy));
        const float fy = sy - float(y0);
        for (int x = 0; x < width; ++x) {
            const float sx = (float(x) + 0.5f) * float(texture.width) / float(width) - 0.5f;
            const int x0 = int(std::floor(sx));
            const float fx = sx - float(x0);
            for (size_t c = 0; c < kRgbaBytes; ++c) {
                const float top = texel(x0, y0, c) * (1.0f - fx) + texel(x0 + 1, y0, c) * fx;
                const float bottom =
                    texel(x0, y0 + 1, c) * (1.0f - fx) + texel(x0 + 1, y0 + 1, c) * fx;
                const float v = top * (1.0f - fy) + bottom * fy;
                out[(static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) *
                        kRgbaBytes +
                    c] = static_cast<uint8_t>(std::clamp(std::lround(v), 0L, long(kWhite)));
            }
        }
    }
    return out;
}

gl::Texture buildSceneTextureArray(std::span<const SceneTexture> textures) {
    if (textures.empty()) {
        gl::Texture white =
            gl::Texture::createMipmapped2DArray("scene textures", gl::Format::SRGB8A8, 1, 1, 1, 1);
        const std::vector<uint8_t> texel(kRgbaBytes, kWhite);
        white.uploadRgba8(texel, 0);
        return white;
    }
    int width = 1;
    int height = 1;
    for (const SceneTexture& t : textures) {
        width = std::max(width, std::min(t.width, kMaxTextureLayerPx));
        height = std::max(height, std::min(t.height, kMaxTextureLayerPx));
    }
    const int levels = std::bit_width(static_cast<unsigned>(std::max(width, height)));
    gl::Texture array =
        gl::Texture::createMipmapped2DArray("scene textures", gl::Format::SRGB8A8, width, height,
                                            static_cast<int>(textures.size()), levels);
    for (size_t i = 0; i < textures.size(); ++i)
        array.uploadRgba8(resampleTexture(textures[i], width, height), static_cast<int>(i));
    array.generateMipmaps();
    return array;
}

} // namespace ispm
