// Pixel rectangles of world boxes: every pixel a box's points fall in lies inside its rect.
#include "render/pixel_rect.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <random>

namespace ispm::test {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 200;

glm::mat4 makeClipFromWorld() {
    const glm::mat4 view =
        glm::lookAt(glm::vec3(2.0f, 6.0f, 12.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::perspective(glm::radians(50.0f), float(kWidth) / float(kHeight), 0.1f, 100.0f) *
           view;
}

Aabb makeBox(const glm::vec3& lo, const glm::vec3& hi) {
    Aabb box;
    box.extend(lo);
    box.extend(hi);
    return box;
}

TEST(PixelRect, HoldsThePixelOfEveryPointOfTheBox) {
    const glm::mat4 clipFromWorld = makeClipFromWorld();
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int b = 0; b < 50; ++b) {
        const glm::vec3 lo(-6.0f + 10.0f * unit(rng), -3.0f + 4.0f * unit(rng),
                           -6.0f + 10.0f * unit(rng));
        const Aabb box =
            makeBox(lo, lo + glm::vec3(0.1f) + 3.0f * glm::vec3(unit(rng), unit(rng), unit(rng)));
        const std::optional<PixelRect> rect = computePixelRect(box, clipFromWorld, kWidth, kHeight);
        ASSERT_TRUE(rect.has_value()) << b; // every box lies in front of the eye
        for (int k = 0; k < 500; ++k) {
            const glm::vec3 p =
                box.lo + glm::vec3(unit(rng), unit(rng), unit(rng)) * box.getExtent();
            const glm::vec4 clip = clipFromWorld * glm::vec4(p, 1.0f);
            const glm::vec2 pixel =
                (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(float(kWidth), float(kHeight));
            const glm::ivec2 at(glm::floor(pixel));
            if (at.x < 0 || at.y < 0 || at.x >= kWidth || at.y >= kHeight)
                continue; // not in the image
            EXPECT_TRUE(at.x >= rect->x && at.x < rect->x + rect->width && at.y >= rect->y &&
                        at.y < rect->y + rect->height)
                << "box " << b << " point " << k;
        }
    }
}

TEST(PixelRect, SmallBoxGetsASmallRect) {
    // A 0.2 m box at the point the camera looks at: a few pixels, and not the image.
    const std::optional<PixelRect> rect = computePixelRect(
        makeBox(glm::vec3(-0.1f), glm::vec3(0.1f)), makeClipFromWorld(), kWidth, kHeight);
    ASSERT_TRUE(rect.has_value());
    EXPECT_FALSE(rect->isEmpty());
    EXPECT_LT(rect->getArea(), 0.01 * kWidth * kHeight);
    // Around the image's centre.
    EXPECT_LE(rect->x, kWidth / 2);
    EXPECT_GE(rect->x + rect->width, kWidth / 2);
    EXPECT_LE(rect->y, kHeight / 2);
    EXPECT_GE(rect->y + rect->height, kHeight / 2);
}

TEST(PixelRect, BoxBehindTheEyeOrBesideTheImage) {
    const glm::mat4 clipFromWorld = makeClipFromWorld();
    // Around the eye: some corners behind it, so any pixel may be covered.
    EXPECT_FALSE(
        computePixelRect(makeBox(glm::vec3(1.0f, 5.0f, 11.0f), glm::vec3(3.0f, 7.0f, 13.0f)),
                         clipFromWorld, kWidth, kHeight)
            .has_value());
    // Far to the camera's side: no pixel.
    const std::optional<PixelRect> beside =
        computePixelRect(makeBox(glm::vec3(60.0f, 0.0f, 0.0f), glm::vec3(61.0f, 1.0f, 1.0f)),
                         clipFromWorld, kWidth, kHeight);
    ASSERT_TRUE(beside.has_value());
    EXPECT_TRUE(beside->isEmpty());
    // An empty box covers nothing.
    const std::optional<PixelRect> none = computePixelRect(Aabb{}, clipFromWorld, kWidth, kHeight);
    ASSERT_TRUE(none.has_value());
    EXPECT_TRUE(none->isEmpty());
}

} // namespace
} // namespace ispm::test
