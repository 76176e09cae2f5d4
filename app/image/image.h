// A linear RGB float image on the CPU: what the renderer reads back, what image files hold and what
// the metrics compare. Row 0 is the TOP row (as in PNG and EXR); PFM's bottom-up order is handled
// by its reader and writer.
#pragma once

#include <glm/vec3.hpp>

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ispm {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> pixels; // row-major, width * height, row 0 at the top

    Image() = default;
    Image(int widthPx, int heightPx, glm::vec3 fill = glm::vec3(0.0f))
        : width(widthPx), height(heightPx),
          pixels(static_cast<size_t>(widthPx) * static_cast<size_t>(heightPx), fill) {
        assert(widthPx >= 0 && heightPx >= 0);
    }

    size_t getPixelCount() const { return pixels.size(); }
    bool isEmpty() const { return pixels.empty(); }

    glm::vec3& at(int x, int y) { return pixels[getIndex(x, y)]; }
    const glm::vec3& at(int x, int y) const { return pixels[getIndex(x, y)]; }

  private:
    size_t getIndex(int x, int y) const {
        assert(x >= 0 && x < width && y >= 0 && y < height);
        return static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
    }
};

// A per-pixel selection, same layout as Image::pixels: non-zero includes the pixel.
using PixelMask = std::vector<uint8_t>;

// Throws InputError naming both sizes when the images differ in size: comparing a render with a
// reference of another resolution is a user mistake, not a programming one.
void requireSameSize(const Image& test, const Image& reference);

// a - b per pixel (e.g. reference bounces B minus bounces 0 = the indirect light); throws
// InputError when the sizes differ.
Image subtractImages(const Image& a, const Image& b);

// Throws InputError when `mask` (if given) has another pixel count than `image`.
void requireMaskSize(const Image& image, const PixelMask* mask);

} // namespace ispm
