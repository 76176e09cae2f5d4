// The scene's colour textures as one sRGB 2D texture array with mipmaps, a layer per texture:
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

// The array of the scene's textures, or a 1x1 white layer when it has none (so the sampler the
// shaders declare is always complete).
gl::Texture buildSceneTextureArray(std::span<const SceneTexture> textures);

} // namespace ispm
