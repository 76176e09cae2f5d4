// Texture read-back with the vertical flip.
#include "render/readback.h"

#include <algorithm>

namespace ispm {

std::vector<glm::vec4> readTextureTopDown(const gl::Texture& texture, int layer) {
    const std::vector<glm::vec4> texels = texture.readRgba(layer);
    const auto w = static_cast<size_t>(texture.getWidth());
    const auto h = static_cast<size_t>(texture.getHeight());
    std::vector<glm::vec4> rows(texels.size());
    for (size_t y = 0; y < h; ++y) {
        std::copy_n(texels.begin() + static_cast<std::ptrdiff_t>((h - 1 - y) * w), w,
                    rows.begin() + static_cast<std::ptrdiff_t>(y * w));
    }
    return rows;
}

Image readTextureImage(const gl::Texture& texture, int layer) {
    const std::vector<glm::vec4> texels = readTextureTopDown(texture, layer);
    Image image(texture.getWidth(), texture.getHeight());
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = glm::vec3(texels[i]);
    return image;
}

} // namespace ispm
