// Screen-space bounds of world boxes: the pixels a draw needs to cover (deferred light of a
// light whose reach is bounded). Pure math, unit-tested on its own.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <optional>

namespace ispm {

// Pixels [x, x + width) x [y, y + height) of an image, y up (GL's window coordinates).
struct PixelRect {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    bool isEmpty() const { return width <= 0 || height <= 0; }
    double getArea() const { return isEmpty() ? 0.0 : double(width) * double(height); }
};

// The pixels of a width x height image that `box` may cover seen through `clipFromWorld`, with a
// pixel's margin (sub-pixel offsets, round-off); empty when the box lies outside the image. None
// when a corner lies at or behind the eye's plane: the box may then cover any pixel.
std::optional<PixelRect> computePixelRect(const Aabb& box, const glm::mat4& clipFromWorld,
                                          int width, int height);

} // namespace ispm
