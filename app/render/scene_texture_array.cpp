// Packing the scene's textures into mipmapped arrays: colour (sRGB) and normal maps (linear).
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

SceneTextureLayers assignSceneTextureLayers(const Scene& scene) {
    SceneTextureLayers layers;
    layers.colorLayer.assign(scene.textures.size(), -1);
    layers.normalLayer.assign(scene.textures.size(), -1);
    for (const Material& m : scene.materials) {
        if (m.diffuseTexture != kNoTexture) layers.colorLayer[m.diffuseTexture] = 0;
        if (m.normalTexture != kNoTexture) layers.normalLayer[m.normalTexture] = 0;
    }
    for (uint32_t t = 0; t < scene.textures.size(); ++t) {
        // Textures no material reads (an emissive texture's, its mean taken) stay in the colour
        // array, as before normal maps.
        const bool normalOnly = layers.normalLayer[t] == 0 && layers.colorLayer[t] < 0;
        if (!normalOnly) {
            layers.colorLayer[t] = static_cast<int>(layers.colorTextures.size());
            layers.colorTextures.push_back(t);
        }
        if (layers.normalLayer[t] == 0) {
            layers.normalLayer[t] = static_cast<int>(layers.normalTextures.size());
            layers.normalTextures.push_back(t);
        }
    }
    return layers;
}

gl::Texture buildSceneTextureArray(std::span<const SceneTexture> textures,
                                   std::span<const uint32_t> which, TextureEncoding encoding) {
    const bool linear = encoding == TextureEncoding::Linear;
    const gl::Format format = linear ? gl::Format::RGBA8 : gl::Format::SRGB8A8;
    const char* label = linear ? "scene normal maps" : "scene textures";
    if (which.empty()) {
        gl::Texture single = gl::Texture::createMipmapped2DArray(label, format, 1, 1, 1, 1);
        constexpr uint8_t kHalf = 128; // 2 x 128 / 255 - 1: 0.004, normalised away
        const std::vector<uint8_t> texel = linear
                                               ? std::vector<uint8_t>{kHalf, kHalf, kWhite, kWhite}
                                               : std::vector<uint8_t>(kRgbaBytes, kWhite);
        single.uploadRgba8(texel, 0);
        return single;
    }
    int width = 1;
    int height = 1;
    for (const uint32_t t : which) {
        width = std::max(width, std::min(textures[t].width, kMaxTextureLayerPx));
        height = std::max(height, std::min(textures[t].height, kMaxTextureLayerPx));
    }
    const int levels = std::bit_width(static_cast<unsigned>(std::max(width, height)));
    gl::Texture array = gl::Texture::createMipmapped2DArray(label, format, width, height,
                                                            static_cast<int>(which.size()), levels);
    for (size_t i = 0; i < which.size(); ++i)
        array.uploadRgba8(resampleTexture(textures[which[i]], width, height), static_cast<int>(i));
    array.generateMipmaps();
    return array;
}

} // namespace ispm
