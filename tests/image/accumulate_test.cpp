// Temporal accumulation (AccumulatePass, FrameRunner): the accumulated light of N still frames
// is the mean of N single frames with seeds seed .. seed + N - 1 and the sub-pixel offsets of
// frames 0 .. N - 1; when the camera or an object moves, the indirect history follows the
// surfaces and starts anew where they were hidden; a light switched off or moved leaves no stale
// light one frame later.
#include "support/gl_fixture.h"
#include "support/render_support.h"

#include "image/metrics.h"
#include "render/accumulate_pass.h"
#include "render/frame.h"
#include "render/readback.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace ispm::test {
namespace {

constexpr int kSize = 48; // px: small, the photons still light every wall

Scene loadCornell() {
    return loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
}

Settings makeSettings(const Scene& scene, int accumulate, int seed) {
    Settings s = withSettings(scene.settings, {{"width", kSize},
                                               {"height", kSize},
                                               {"photons", 4000},
                                               {"bounces", 2},
                                               {"shadow_map_size", 256},
                                               {"accumulate", accumulate},
                                               {"seed", seed}});
    return s;
}

Image renderIndirect(FrameRunner& runner, int frames) {
    for (int i = 0; i < frames; ++i)
        runner.renderFrame();
    return readTextureImage(runner.getAov(Aov::Indirect));
}

class AccumulateTest : public GlTest {};

TEST_F(AccumulateTest, StillFramesAverageTheirSeedsAndOffsets) {
    constexpr int kFrames = 4;
    const Scene scene = loadCornell();
    FrameRunner accumulating(scene, makeSettings(scene, kFrames, 7), gl::TimingMethod::CpuFinish);
    // Each frame's own light, before accumulation, averaged here: the direct light over every
    // frame (0 where its centre saw the background), the indirect light, the surface's, over the
    // frames whose centre saw a surface (the direct light's alpha: its coverage).
    Image mean(kSize, kSize);
    Image meanDirect(kSize, kSize);
    std::vector<float> surfaceFrames(mean.pixels.size(), 0.0f);
    Image first;
    Image firstDirect;
    for (int f = 0; f < kFrames; ++f) {
        accumulating.renderFrame();
        const Image frame = readTextureImage(accumulating.getPasses().upsample.getOutput());
        const Image direct = readTextureImage(accumulating.getPasses().direct.getOutput());
        const std::vector<glm::vec4> coverage =
            readTextureTopDown(accumulating.getPasses().direct.getOutput());
        if (f == 0) {
            first = frame;
            firstDirect = direct;
        }
        for (size_t i = 0; i < mean.pixels.size(); ++i) {
            if (coverage[i].w > 0.5f) {
                mean.pixels[i] += frame.pixels[i];
                surfaceFrames[i] += 1.0f;
            }
            meanDirect.pixels[i] += direct.pixels[i] / float(kFrames);
        }
    }
    int partlySeen = 0; // pixels whose centre saw a surface in some frames only
    for (size_t i = 0; i < mean.pixels.size(); ++i) {
        if (surfaceFrames[i] > 0.0f) mean.pixels[i] /= surfaceFrames[i];
        if (surfaceFrames[i] > 0.0f && surfaceFrames[i] < float(kFrames)) ++partlySeen;
    }
    // The box's outline at 48 px crosses about 100 pixels, some of which the offsets move across.
    EXPECT_GT(partlySeen, 5);
    const Image accumulated = readTextureImage(accumulating.getAov(Aov::Indirect));
    const Image accumulatedDirect = readTextureImage(accumulating.getAov(Aov::Direct));
    EXPECT_EQ(accumulating.getPasses().accumulate.getAccumulatedFrames(), uint32_t(kFrames));
    // Only float rounding of the running mean differs from the plain mean.
    EXPECT_LT(computeMaxRelativeDifference(accumulated, mean), 1e-4);
    EXPECT_LT(computeMaxRelativeDifference(accumulatedDirect, meanDirect), 1e-4);
    // And the frames did differ: new photons each frame (a fixed seed would pass the lines
    // above), and new offsets (edges of the direct light move).
    EXPECT_GT(computeMaxRelativeDifference(first, mean), 0.05);
    EXPECT_GT(computeMaxRelativeDifference(firstDirect, meanDirect), 0.05);
    // Frame 0 is the plain frame: the same as a runner without accumulation.
    FrameRunner plain(scene, makeSettings(scene, 0, 7), gl::TimingMethod::CpuFinish);
    // (Atomic appends and float sums on the GPU may order the same photons differently.)
    EXPECT_LT(computeMaxRelativeDifference(renderIndirect(plain, 1), first), 1e-4);
    // The history is full: the image holds, to the last bit, and stays at kFrames frames.
    const Image held = renderIndirect(accumulating, 2);
    EXPECT_EQ(held.pixels, accumulated.pixels);
    EXPECT_EQ(accumulating.getPasses().accumulate.getAccumulatedFrames(), uint32_t(kFrames));
}

// The moving cube's room at kSize: the cube in front of the back wall, so that a move uncovers
// wall behind it.
Scene loadMovingCube() {
    return loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/moving_cube.json");
}

// Each pixel's history length and surface (instance + 1, 0 where nothing is), top row first.
struct HistoryPixels {
    std::vector<float> length;
    std::vector<int> surface;
};

HistoryPixels readHistory(const FrameRunner& runner) {
    HistoryPixels h;
    for (const glm::vec4& t : readTextureTopDown(runner.getPasses().accumulate.getHistoryLength()))
        h.length.push_back(t.x);
    for (const glm::vec4& t :
         readTextureTopDown(runner.getPasses().gbuffer.getGBuffer().getChannel("position")))
        h.surface.push_back(int(t.w + 0.5f));
    return h;
}

TEST_F(AccumulateTest, CameraMoveReprojectsTheIndirectHistory) {
    constexpr int kFrames = 16;
    Scene scene = loadMovingCube();
    FrameRunner runner(scene, makeSettings(scene, kFrames, 1), gl::TimingMethod::CpuFinish);
    renderIndirect(runner, kFrames);
    // A step to the side and forward: the cube's edge uncovers some wall, the rest of the room
    // is seen again from a little elsewhere.
    const glm::vec3 step(0.15f, 0.0f, 0.1f);
    scene.camera.position += step;
    scene.camera.target += step;
    const Image moved = renderIndirect(runner, 1);
    const Image own = readTextureImage(runner.getPasses().upsample.getOutput());
    const HistoryPixels history = readHistory(runner);
    EXPECT_EQ(runner.getPasses().accumulate.getAccumulatedFrames(),
              1u); // the still view's count starts anew
    // The direct light starts anew too (shadows move with objects; a still camera refines it).
    EXPECT_EQ(readTextureImage(runner.getAov(Aov::Direct)).pixels,
              readTextureImage(runner.getPasses().direct.getOutput()).pixels);
    int kept = 0;
    int uncovered = 0;
    int surfaces = 0;
    for (size_t i = 0; i < history.length.size(); ++i) {
        if (history.surface[i] == 0) continue;
        ++surfaces;
        if (history.length[i] > 1.5f) {
            // A history of kFrames still frames, kept: kFrames of this frame's weight 1 / kFrames.
            EXPECT_EQ(history.length[i], float(kFrames)) << i;
            ++kept;
            continue;
        }
        ++uncovered;
        // Started anew: this frame's own light, nothing of what the pixel showed before.
        EXPECT_EQ(moved.pixels[i], own.pixels[i]) << i;
    }
    std::printf("%d surface pixels: %d kept their history, %d started anew\n", surfaces, kept,
                uncovered);
    EXPECT_GT(kept, surfaces * 9 / 10); // the room, seen again
    EXPECT_GT(uncovered, 0);            // the wall behind the cube's edge, and the image's edge
    // The light kept is closer to the converged light of the new view than one frame is. The
    // converged and the single frame have other seeds than the history's, so that no photon is
    // shared with the image under test.
    Image converged;
    Image single;
    {
        FrameRunner other(scene, makeSettings(scene, 4 * kFrames, 1001),
                          gl::TimingMethod::CpuFinish);
        converged = renderIndirect(other, 4 * kFrames);
        FrameRunner once(scene, makeSettings(scene, 0, 2001), gl::TimingMethod::CpuFinish);
        single = renderIndirect(once, 1);
    }
    const double movedError = computeRelRmse(moved, converged, kRelRmseBlock);
    const double singleError = computeRelRmse(single, converged, kRelRmseBlock);
    std::printf("rel RMSE against %d frames of the new view: after the move %.4f, one frame %.4f\n",
                4 * kFrames, movedError, singleError);
    EXPECT_LT(movedError, 0.6 * singleError);
}

TEST_F(AccumulateTest, MovingObjectKeepsItsHistoryWhereItsReprojectionHolds) {
    constexpr int kFrames = 8;
    Scene scene = loadMovingCube();
    ASSERT_EQ(scene.instanceAnimations.size(), 1u);
    const uint32_t cube = scene.instanceAnimations[0].instanceIndex;
    FrameRunner runner(scene, makeSettings(scene, kFrames, 1), gl::TimingMethod::CpuFinish);
    renderIndirect(runner, kFrames);
    const HistoryPixels before = readHistory(runner);
    // Toward the camera (its front face leaves its plane: without the cube's own motion its
    // pixels would be rejected) and to the side (wall uncovered behind it, several pixels wide).
    scene.instances[cube].worldFromObject =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.4f, 0.0f, -0.15f)) *
        scene.instances[cube].worldFromObject;
    runner.updateScene();
    const Image moved = renderIndirect(runner, 1);
    const Image own = readTextureImage(runner.getPasses().upsample.getOutput());
    const HistoryPixels after = readHistory(runner);
    const int cubeSurface = int(cube) + 1;
    // Hidden by the cube in the last frame, it and its neighbours (the history's four pixels
    // around a point may reach one pixel over, to room that was seen).
    const auto wasHidden = [&](int x, int y) {
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int qx = std::clamp(x + dx, 0, kSize - 1);
                const int qy = std::clamp(y + dy, 0, kSize - 1);
                if (before.surface[size_t(qy * kSize + qx)] != cubeSurface) return false;
            }
        return true;
    };
    int cubePixels = 0;
    int cubeKept = 0;
    int uncovered = 0;
    int roomKept = 0;
    int roomPixels = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const auto i = size_t(y * kSize + x);
            const bool kept = after.length[i] > 1.5f;
            if (after.surface[i] == cubeSurface) {
                ++cubePixels;
                cubeKept += kept ? 1 : 0;
            } else if (wasHidden(x, y)) {
                ++uncovered; // what shows now was hidden: this frame's own light only
                EXPECT_FALSE(kept) << x << ", " << y;
                EXPECT_EQ(moved.pixels[i], own.pixels[i]) << x << ", " << y;
            } else if (before.surface[i] != cubeSurface) {
                ++roomPixels;
                roomKept += kept ? 1 : 0;
            }
        }
    std::printf("cube %d px (%d kept), uncovered %d px, room %d px (%d kept)\n", cubePixels,
                cubeKept, uncovered, roomPixels, roomKept);
    EXPECT_GT(cubePixels, 20);
    EXPECT_GT(cubeKept, cubePixels * 3 / 4); // its edges may land off it in the last frame
    EXPECT_GT(uncovered, 5);
    EXPECT_GT(roomKept, roomPixels * 9 / 10);
}

TEST_F(AccumulateTest, LightSwitchLeavesNoStaleLight) {
    Scene scene = loadCornell();
    FrameRunner runner(scene, makeSettings(scene, 16, 1), gl::TimingMethod::CpuFinish);
    renderIndirect(runner, 4);
    // The spot switched off (the viewer's light edit): no light at all the next frame, although
    // nothing else changed and every pixel's history would reproject.
    scene.lights[0].intensity = glm::vec3(0.0f);
    runner.updateScene();
    const Image dark = renderIndirect(runner, 1);
    double largest = 0.0;
    for (const glm::vec3& p : dark.pixels)
        largest = std::max(largest, double(std::max({p.x, p.y, p.z})));
    EXPECT_EQ(largest, 0.0) << "light of the frames before the switch";
    const Image direct = readTextureImage(runner.getAov(Aov::Direct));
    for (const glm::vec3& p : direct.pixels)
        largest = std::max(largest, double(std::max({p.x, p.y, p.z})));
    EXPECT_EQ(largest, 0.0) << "direct light of the frames before the switch";
    // A moved light: the history starts anew as well (every pixel's length 1 where this frame
    // sees a surface, 0 where it sees the background).
    renderIndirect(runner, 3);
    scene.lights[0].intensity = glm::vec3(1.0f);
    scene.lights[0].position.x += 0.05f;
    runner.updateScene();
    renderIndirect(runner, 1);
    const std::vector<glm::vec4> lengths =
        readTextureTopDown(runner.getPasses().accumulate.getHistoryLength());
    const std::vector<glm::vec4> coverage =
        readTextureTopDown(runner.getPasses().direct.getOutput());
    int surfaces = 0;
    for (size_t i = 0; i < lengths.size(); ++i) {
        const bool surface = coverage[i].w > 0.5f;
        surfaces += surface ? 1 : 0;
        ASSERT_EQ(lengths[i].x, surface ? 1.0f : 0.0f);
    }
    EXPECT_GT(surfaces, int(lengths.size()) / 2); // the box fills most of the view
}

// The Cornell box against a coloured background, where compose.frag mixes a silhouette pixel's
// surface and the background by the surface's coverage (the direct light's alpha): the direct
// light is the pixel's mean already (0 where it saw the background), the indirect light the
// surface's own, weighed by the coverage.
Scene loadCornellOnBackground() {
    Scene scene = loadCornell();
    scene.background = glm::vec3(0.2f, 0.3f, 0.4f);
    return scene;
}

struct CoverageCheck {
    int partial = 0;                // pixels partly covered
    double leftOutIndirect = 0.0;   // (1 - coverage) x their indirect light (mean over RGB), summed
    double largestDifference = 0.0; // of the total from the mix above
};

CoverageCheck checkCoverageMix(const FrameRunner& runner, const Scene& scene) {
    const Image total = readTextureImage(runner.getAov(Aov::Total));
    const std::vector<glm::vec4> direct = readTextureTopDown(runner.getAov(Aov::Direct));
    const Image indirect = readTextureImage(runner.getAov(Aov::Indirect));
    CoverageCheck check;
    for (size_t i = 0; i < total.pixels.size(); ++i) {
        const float c = direct[i].w;
        if (c > 0.01f && c < 0.99f) {
            ++check.partial;
            const glm::vec3 left = (1.0f - c) * indirect.pixels[i];
            check.leftOutIndirect += double(left.x + left.y + left.z) / 3.0;
        }
        const glm::vec3 expected =
            scene.background * (1.0f - c) +
            (c > 0.0f ? glm::vec3(direct[i]) + c * indirect.pixels[i] : glm::vec3(0.0f));
        check.largestDifference =
            std::max(check.largestDifference, double(glm::length(total.pixels[i] - expected)));
    }
    std::printf("%d pixels partly covered, indirect light they leave out %.3f, largest "
                "difference %.2e\n",
                check.partial, check.leftOutIndirect, check.largestDifference);
    return check;
}

TEST_F(AccumulateTest, SilhouettesAgainstTheBackgroundAreAntiAliased) {
    // Over frames with sub-pixel offsets a silhouette pixel is partly surface, partly
    // background, and the total mixes the two by the surface's coverage instead of taking the
    // last frame's G-buffer's word for it (the frames that saw the background add nothing to
    // the surface's indirect light).
    const Scene scene = loadCornellOnBackground();
    FrameRunner runner(scene, makeSettings(scene, 8, 1), gl::TimingMethod::CpuFinish);
    for (int f = 0; f < 8; ++f)
        runner.renderFrame();
    const CoverageCheck check = checkCoverageMix(runner, scene);
    // 48 x 48 px: the box's outline crosses about 100 pixels; one frame has none partly covered.
    EXPECT_GT(check.partial, 20);
    EXPECT_LT(check.largestDifference, 1e-5); // float rounding (the Cornell box emits nothing)
}

TEST_F(AccumulateTest, OneFrameWeighsTheSurfacesIndirectLightByItsCoverage) {
    // One frame with edge_samples: a silhouette pixel's direct light is the mean over its rays
    // and its alpha their share that hit a surface; the indirect light, the surface's at the
    // pixel's centre, covers that share alone. Adding it whole brightens every silhouette
    // against the background by (1 - coverage) of it.
    const Scene scene = loadCornellOnBackground();
    Settings settings = withSettings(makeSettings(scene, 0, 1), {{"edge_samples", 16}});
    FrameRunner runner(scene, settings, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    const CoverageCheck check = checkCoverageMix(runner, scene);
    // 48 x 48 px: the box's outline crosses about 100 pixels, and its front edges hold light.
    EXPECT_GT(check.partial, 20);
    EXPECT_GT(check.leftOutIndirect, 1e-3);
    EXPECT_LT(check.largestDifference, 1e-5); // float rounding (the Cornell box emits nothing)
}

TEST_F(AccumulateTest, LightCamerasMoveInsideATexelSoShadowEdgesConverge) {
    // The sun's patch on the floor of the courtyard's room, drawn from 64-texel shadow maps (the
    // sun's view fitted to the room: about 8 cm texels, several pixels at 48 px): frame 0 draws it
    // in texel-sized steps, the accumulated frames (light cameras moved inside a texel each
    // frame) approach the patch 1,024-texel maps draw.
    Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/courtyard.json");
    selectCamera(scene, "room");
    auto render = [&scene](int shadowMap, int frames, Image* first) {
        Settings s = withSettings(
            scene.settings,
            {{"width", kSize}, {"height", kSize}, {"bounces", 0}, {"shadow_map_size", shadowMap}});
        // Half the default: the normal offset moves the patch's edges by a share of a texel,
        // the same in every frame, which no jitter undoes.
        s = withSettings(s, {{"shadow_bias", 0.5f}, {"accumulate", frames}});
        FrameRunner runner(scene, s, gl::TimingMethod::CpuFinish);
        for (int f = 0; f < frames; ++f) {
            runner.renderFrame();
            if (f == 0 && first) *first = readTextureImage(runner.getPasses().direct.getOutput());
        }
        return readTextureImage(runner.getAov(Aov::Direct));
    };
    constexpr int kFrames = 16;
    const Image fine = render(1024, kFrames, nullptr);
    Image coarseFirst;
    const Image coarse = render(64, kFrames, &coarseFirst);
    const double firstError = computeRelRmse(coarseFirst, fine, kRelRmseBlock);
    const double accumulatedError = computeRelRmse(coarse, fine, kRelRmseBlock);
    std::printf("sun patch from 64 texel maps against 1024: frame 0 %.4f, %d frames %.4f\n",
                firstError, kFrames, accumulatedError);
    EXPECT_GT(firstError, 0.05); // the steps are there to remove
    // Measured 0.247 -> 0.114; the camera's own sub-pixel offsets alone (light cameras held)
    // leave the steps where they are: 0.252 -> 0.220.
    EXPECT_LT(accumulatedError, 0.65 * firstError);
}

TEST(AccumulateJitter, LightOffsetsInsideATexelApartFromThePixels) {
    EXPECT_EQ(computeShadowJitter(0), glm::vec2(0.0f)); // frame 0 is the plain frame
    for (uint32_t f = 1; f < 64; ++f) {
        const glm::vec2 j = computeShadowJitter(f);
        EXPECT_TRUE(j.x >= -0.5f && j.x < 0.5f && j.y >= -0.5f && j.y < 0.5f) << f;
        EXPECT_NE(j, computePixelJitter(f)) << f; // not in step with the camera's
    }
    // 1/5 and 1/7 minus 1/2, to float rounding.
    EXPECT_NEAR(computeShadowJitter(1).x, -0.3f, 1e-6f);
    EXPECT_NEAR(computeShadowJitter(1).y, 1.0f / 7.0f - 0.5f, 1e-6f);
}

TEST(AccumulateJitter, HaltonOffsetsInsideThePixel) {
    EXPECT_EQ(computePixelJitter(0), glm::vec2(0.0f)); // the first frame is the plain one
    // 1/2, 1/3 and 1/4, 2/3 minus 1/2, to float rounding.
    EXPECT_NEAR(computePixelJitter(1).x, 0.0f, 1e-6f);
    EXPECT_NEAR(computePixelJitter(1).y, -1.0f / 6.0f, 1e-6f);
    EXPECT_NEAR(computePixelJitter(2).x, -0.25f, 1e-6f);
    EXPECT_NEAR(computePixelJitter(2).y, 1.0f / 6.0f, 1e-6f);
    for (uint32_t f = 1; f < 64; ++f) {
        const glm::vec2 j = computePixelJitter(f);
        EXPECT_TRUE(j.x >= -0.5f && j.x < 0.5f && j.y >= -0.5f && j.y < 0.5f) << f;
    }
}

TEST(AccumulateWeight, RunningMean) {
    EXPECT_EQ(computeAccumulateWeight(0, 5), 1.0f);   // off
    EXPECT_EQ(computeAccumulateWeight(8, 0), 1.0f);   // empty history
    EXPECT_EQ(computeAccumulateWeight(8, 1), 0.5f);   // second frame: mean of two
    EXPECT_EQ(computeAccumulateWeight(8, 7), 0.125f); // the eighth
}

TEST(AccumulateProgressive, RadiiShrinkAndTheFilterNarrowsWithFrames) {
    // Off, and frame 0: the settings as they are.
    for (const ProgressiveStep step :
         {computeProgressiveStep(0, 9, 3), computeProgressiveStep(32, 0, 3)}) {
        EXPECT_EQ(step.radiusFactor, 1.0f);
        EXPECT_EQ(step.neighbourFactor, 1.0f);
        EXPECT_GT(step.travelRadiusFactor, 0.0f); // every frame
        EXPECT_TRUE(step.spreadStrongPhotons);
        EXPECT_EQ(step.denoiseIterations, 3);
    }
    // r_i^2 / r_0^2 = prod_{j<i} (j + alpha) / (j + 1), of order i^(alpha - 1): strictly
    // falling, slower than the 1 / i that would keep as few photons per disc as one frame has.
    float previous = 1.0f;
    for (uint32_t i = 1; i < 64; ++i) {
        const ProgressiveStep step = computeProgressiveStep(64, i, 3);
        EXPECT_LT(step.radiusFactor, previous) << i;
        EXPECT_GT(step.radiusFactor * step.radiusFactor, 1.0f / float(i + 1)) << i;
        EXPECT_GT(step.travelRadiusFactor, 0.0f) << i;
        EXPECT_FALSE(step.spreadStrongPhotons) << i;
        // Fewer photons a disc than one frame's: the average takes their noise down.
        EXPECT_LT(step.neighbourFactor, 1.0f) << i;
        EXPECT_GT(step.neighbourFactor, 0.0f) << i;
        previous = step.radiusFactor;
    }
    // The second frame: (0 + alpha) / 1.
    const float alpha = computeProgressiveStep(64, 1, 3).radiusFactor;
    EXPECT_GT(alpha * alpha, 0.5f);
    EXPECT_LT(alpha * alpha, 1.0f);
    // One a-trous iteration fewer at 4, 16, 64 frames (frame index 3, 15, 63), never below 0.
    EXPECT_EQ(computeProgressiveStep(64, 2, 3).denoiseIterations, 3);
    EXPECT_EQ(computeProgressiveStep(64, 3, 3).denoiseIterations, 2);
    EXPECT_EQ(computeProgressiveStep(64, 15, 3).denoiseIterations, 1);
    EXPECT_EQ(computeProgressiveStep(64, 63, 3).denoiseIterations, 0);
    EXPECT_EQ(computeProgressiveStep(64, 63, 2).denoiseIterations, 0);
}

} // namespace
} // namespace ispm::test
