// The scene's colour textures as one sRGB 2D texture array with mipmaps, a layer per texture, and
// its normal maps as a linear one:
// the rasterisers and the compute tracers (photon tracer, reference path tracer) sample it alike,
// with no bindless handles (llvmpipe has none). Layers share one size, the largest width and
// height among the textures (at most kMaxTextureLayerPx); smaller ones are resampled to it.
#pragma once

#include "gl/objects.h"
#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace ispm {

inline constexpr int kMaxTextureLayerPx = 2048; // per axis: 16 MiB a layer before mipmaps

// `texture` resampled bilinearly (repeating, as the sampler does) to width x height, RGBA8.
std::vector<uint8_t> resampleTexture(const SceneTexture& texture, int width, int height);

// How a texture's RGB bytes are read: sRGB-encoded colour (decoded to linear by the sampler)
// or linear values (normal maps, whose 2 rgb - 1 is a direction: an sRGB decode would bend it).
enum class TextureEncoding { Srgb, Linear };

// Which of the scene's textures go to which array: its colour textures (Material::diffuseTexture)
// to the sRGB one, its normal maps (Material::normalTexture) to the linear one, each in the
// order of Scene::textures. A texture that is only a normal map stays out of the colour array,
// so scenes without normal maps keep the array they had.
struct SceneTextureLayers {
    std::vector<uint32_t> colorTextures;  // indices into Scene::textures, a layer each
    std::vector<uint32_t> normalTextures; // likewise
    std::vector<int> colorLayer;          // per scene texture: its colour layer, or -1
    std::vector<int> normalLayer;         // per scene texture: its normal map layer, or -1
};
SceneTextureLayers assignSceneTextureLayers(const Scene& scene);

// The array of the scene's textures listed in `which`, or a 1x1 layer when it lists none (so the
// sampler the shaders declare is always complete): white, or for normal maps the unperturbed
// normal (0.5, 0.5, 1).
gl::Texture buildSceneTextureArray(std::span<const SceneTexture> textures,
                                   std::span<const uint32_t> which, TextureEncoding encoding);

} // namespace ispm
