// Texture read-back with the vertical flip.
#include "render/readback.h"

namespace ispm {

Image readTextureImage(const gl::Texture& texture, int layer) {
    const std::vector<glm::vec4> texels = texture.readRgba(layer);
    const int w = texture.getWidth();
    const int h = texture.getHeight();
    Image image(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            image.at(x, y) = glm::vec3(texels[static_cast<size_t>((h - 1 - y) * w + x)]);
        }
    }
    return image;
}

} // namespace ispm
