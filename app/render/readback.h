// Reading GPU images back into CPU images (outputs, tests): GL rows start at the bottom, Image rows
// at the top.
#pragma once

#include "gl/objects.h"
#include "image/image.h"

namespace ispm {

Image readTextureImage(const gl::Texture& texture, int layer = 0);
// The texels with w kept, row 0 at the top as in Image.
std::vector<glm::vec4> readTextureTopDown(const gl::Texture& texture, int layer = 0);

} // namespace ispm
