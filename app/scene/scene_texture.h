// Colour textures of the scene model: reading PNG and JPEG files (stb_image) into 8-bit sRGB
// RGBA, converting decoded glTF images, and the sRGB transfer function their means need.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace ispm {

// The sRGB electro-optical transfer function (IEC 61966-2-1): an 8-bit code to linear [0, 1].
float decodeSrgb(uint8_t code);

// The mean linear colour of the texture's texels (RGB, alpha ignored): what a surface covered by
// it reflects on average, for the lobes that cannot vary per point.
glm::vec3 computeLinearMean(const SceneTexture& texture);

// Reads a PNG or JPEG file (any channel count, 8 or 16 bits) as 8-bit RGBA. Throws
// std::runtime_error with stb_image's reason (without the file name) when it cannot.
SceneTexture readTextureFile(const std::string& path);

// Decoded pixels of `channels` (1..4) components of `bits` (8 or 16) each, row 0 at the top, to
// 8-bit RGBA (grey spread to RGB, missing alpha opaque). Returns false for other layouts.
bool convertToRgba8(const uint8_t* pixels, int width, int height, int channels, int bits,
                    SceneTexture& out);

} // namespace ispm
