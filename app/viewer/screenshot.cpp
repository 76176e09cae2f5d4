// Window read-back with glReadPixels on framebuffer 0.
#include "viewer/screenshot.h"

#include "gl/state.h"
#include "image/image_io.h"

#include <cstdint>
#include <vector>

namespace ispm {
namespace {

constexpr int kChannels = 4; // gl::readDefaultFramebuffer reads RGBA8
constexpr float kByteMax = 255.0f;

} // namespace

Image readWindowImage(int width, int height) {
    const std::vector<uint8_t> bytes = gl::readDefaultFramebuffer(width, height);
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        // GL row 0 is the bottom of the window, Image row 0 the top.
        const size_t row = static_cast<size_t>(height - 1 - y) * static_cast<size_t>(width);
        for (int x = 0; x < width; ++x) {
            const uint8_t* p = &bytes[(row + static_cast<size_t>(x)) * kChannels];
            image.at(x, y) = glm::vec3(p[0], p[1], p[2]) / kByteMax;
        }
    }
    return image;
}

void writeScreenshot(const std::string& path, int width, int height) {
    writeImage(path, readWindowImage(width, height));
}

} // namespace ispm
