// computePixelRect: a box's eight corners projected; their hull bounds the box's image.
#include "render/pixel_rect.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ispm {

std::optional<PixelRect> computePixelRect(const Aabb& box, const glm::mat4& clipFromWorld,
                                          int width, int height) {
    if (box.isEmpty() || width <= 0 || height <= 0) return PixelRect{};
    // Nearer than this (clip w, ~ metres in front of the eye) a corner's pixel is too far out
    // to be worth a bound, and at w <= 0 it has none.
    constexpr float kMinDepth = 1e-6f;
    glm::vec2 lo(std::numeric_limits<float>::max());
    glm::vec2 hi(-std::numeric_limits<float>::max());
    for (int i = 0; i < kAabbCornerCount; ++i) {
        const glm::vec4 clip = clipFromWorld * glm::vec4(box.getCorner(i), 1.0f);
        if (!(clip.w > kMinDepth)) return std::nullopt;
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    // In front of the eye the box's image is the hull of its corners' images. Pixel i covers
    // [i, i + 1); one pixel of margin each side.
    const glm::vec2 size{static_cast<float>(width), static_cast<float>(height)};
    const glm::vec2 first = glm::floor((lo * 0.5f + 0.5f) * size) - 1.0f;
    const glm::vec2 last = glm::ceil((hi * 0.5f + 0.5f) * size) + 1.0f;
    const auto clampTo = [](float v, int n) { return int(std::clamp(v, 0.0f, float(n))); };
    PixelRect rect;
    rect.x = clampTo(first.x, width);
    rect.y = clampTo(first.y, height);
    rect.width = clampTo(last.x, width) - rect.x;
    rect.height = clampTo(last.y, height) - rect.y;
    if (rect.isEmpty()) return PixelRect{};
    return rect;
}

} // namespace ispm
