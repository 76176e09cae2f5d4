// Splats drawn into a buffer of 1/2 or 1/4 of the image's resolution and brought back by the
// joint-bilateral upsample (UpsamplePass) are as close to the converged image (eight seeds
// averaged at full resolution) as full-resolution splats of the same photons, keep their energy,
// and carry no colour across an edge (the red wall's light stays off the white wall beside it)
// nor light across a depth edge (a wall seen through a window keeps its own).
#include "support/gl_fixture.h"

#include "image/metrics.h"
#include "render/frame.h"
#include "render/readback.h"
#include "render/splat_pass.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace ispm::test {
namespace {

constexpr int kSize = 128; // px: splats several pixels wide, four-pixel blocks at 1/4

struct SplatImages {
    Image indirect;
    Image diffuse; // the viewer G-buffer's reflectance, row 0 at the top like indirect
};

// The scene's settings at kSize, 20,000 photons, splats at `resolution`, unfiltered.
Settings makeSplatSettings(const Scene& scene, const std::string& resolution) {
    Settings s =
        withSettings(scene.settings, {{"width", kSize}, {"height", kSize}, {"photons", 20000}});
    // The splats alone: the filter would smooth both images alike and hide the upsample's errors.
    s = withSettings(s, {{"denoise", 0}, {"splat_resolution", resolution}});
    return s;
}

SplatImages renderCornell(const std::string& resolution, int seed = 1, float radiusScale = 1.0f) {
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    Settings s = withSettings(
        makeSplatSettings(scene, resolution),
        {{"bounces", 2}, {"shadow_map_size", 512}, {"seed", seed}, {"radius_scale", radiusScale}});
    FrameRunner runner(scene, s, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    return {readTextureImage(runner.getAov(Aov::Indirect)),
            readTextureImage(runner.getPasses().gbuffer.getGBuffer().getChannel("diffuse"))};
}

bool isRed(const glm::vec3& d) {
    return d.x > 2.0f * d.y && d.x > 0.1f;
}
bool isWhite(const glm::vec3& d) {
    return d.x > 0.1f && std::abs(d.x - d.y) < 0.1f * d.x;
}

// Mean red / green of the indirect light over the white-wall pixels within 2 px of a red-wall
// pixel (the left wall's edge with the back wall, floor and ceiling).
double computeWhiteBesideRedRatio(const SplatImages& f) {
    double red = 0.0;
    double green = 0.0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (!isWhite(f.diffuse.at(x, y))) continue;
            bool besideRed = false;
            for (int dy = -2; dy <= 2; ++dy) {
                for (int dx = -2; dx <= 2; ++dx) {
                    const int qx = x + dx;
                    const int qy = y + dy;
                    if (qx >= 0 && qy >= 0 && qx < kSize && qy < kSize &&
                        isRed(f.diffuse.at(qx, qy)))
                        besideRed = true;
                }
            }
            if (!besideRed) continue;
            red += double(f.indirect.at(x, y).x);
            green += double(f.indirect.at(x, y).y);
        }
    }
    EXPECT_GT(green, 0.0) << "no lit white pixel beside the red wall";
    return green > 0.0 ? red / green : 0.0;
}

double sumLight(const Image& image) {
    double sum = 0.0;
    for (const glm::vec3& p : image.pixels)
        sum += double(p.x) + double(p.y) + double(p.z);
    EXPECT_GT(sum, 0.0) << "no indirect light";
    return sum;
}

class SplatResolutionTest : public GlTest {};

TEST_F(SplatResolutionTest, SubsampledSplatsKeepTheFullResolutionImage) {
    constexpr int kSeeds = 8;
    const SplatImages full = renderCornell("1");
    Image converged = full.indirect;
    for (int seed = 2; seed <= kSeeds; ++seed) {
        const Image more = renderCornell("1", seed).indirect;
        for (size_t i = 0; i < converged.pixels.size(); ++i)
            converged.pixels[i] += more.pixels[i];
    }
    for (glm::vec3& p : converged.pixels)
        p /= float(kSeeds);
    const double fullEnergy = computeEnergyRatio(full.indirect, converged);
    const double fullError = computeRelRmse(full.indirect, converged, kRelRmseBlock);
    const double fullBeside = computeWhiteBesideRedRatio(full);
    std::printf("splat_resolution 1 against %d seeds: energy %.4f, rel RMSE (4x4) %.4f; white wall "
                "beside the red one, red / green %.4f\n",
                kSeeds, fullEnergy, fullError, fullBeside);
    for (const char* resolution : {"1/2", "1/4"}) {
        const SplatImages sub = renderCornell(resolution);
        const double energy = computeEnergyRatio(sub.indirect, converged);
        const double error = computeRelRmse(sub.indirect, converged, kRelRmseBlock);
        const double beside = computeWhiteBesideRedRatio(sub);
        std::printf("splat_resolution %s: energy %.4f, rel RMSE (4x4) %.4f, red / green %.4f\n",
                    resolution, energy, error, beside);
        // The same photons, sampled by a buffer pixel every d pixels: the blotches of one frame
        // (a few pixels wide at 128 px) are sampled afresh, so against full resolution's energy
        // the light moves by as much as from seed to seed (measured 1.003 and 1.033 of it; at 1/4
        // 1.007 and 1.024 with seeds 2 and 3; 32 x 32 buffer pixels sample each blotch once).
        EXPECT_NEAR(energy / fullEnergy, 1.0, 0.045) << resolution;
        // Sampling adds some of one frame's noise, the bilinear taps smooth some away: measured
        // 0.99 and 1.35 of full resolution's error with discs of 0.45 sqrt(photons) (a tent over
        // 4 x 4 buffer pixels measured 0.97 and 1.41; with it, 0.89 and 1.14 at 0.3, 0.86 and
        // 1.01 at 0.11): the wider the discs, the smoother the full-resolution image, while
        // 32 x 32 buffer pixels sample it as coarsely as before.
        EXPECT_LT(error, (std::string(resolution) == "1/2" ? 1.1 : 1.5) * fullError) << resolution;
        // Light is read as irradiance and multiplied by each pixel's own reflectance, and only
        // from the pixel's own surface: the white wall next to the red one does not turn red.
        // A plain tent without the G-buffer tests and the reflectance measured 1.88 and 2.10
        // against 1.41 and 1.45 here (full resolution 1.42).
        EXPECT_NEAR(beside / fullBeside, 1.0, 0.03) << resolution;
    }
}

TEST_F(SplatResolutionTest, DiscsOfAPixelKeepTheirEnergy) {
    // Discs shrunk to one or two buffer pixels (accumulated frames shrink them) keep the light
    // that the same resolution gives full-size discs: the rasteriser samples each buffer pixel
    // where the fragment stage shades it (the G-buffer pixel inside its block, not the block's
    // centre), else the discs lose the light near their rims. Sums over all pixels:
    // computeEnergyRatio counts only those the reference lights, and small discs leave gaps.
    constexpr float kSmall = 0.5f;
    const double fullShrunk = sumLight(renderCornell("1", 1, kSmall).indirect) /
                              sumLight(renderCornell("1", 1, 1.0f).indirect);
    for (const char* resolution : {"1/2", "1/4"}) {
        const double shrunk = sumLight(renderCornell(resolution, 1, kSmall).indirect) /
                              sumLight(renderCornell(resolution, 1, 1.0f).indirect);
        std::printf("radius_scale %.1f against 1, splat_resolution %s: light %.4f (full "
                    "resolution %.4f)\n",
                    double(kSmall), resolution, shrunk, fullShrunk);
        // The same photons summed over other pixels: measured within 0.8%; sampled half an image
        // pixel off, the shrunk discs lost 15% (1/2) and 14% (1/4).
        EXPECT_NEAR(shrunk, fullShrunk, 0.02) << resolution;
    }
}

// A sunlit wall with a window 2 m square, 8 m before the camera, and a closed room behind it
// whose back wall, 4 m behind, is seen through the window: the front wall's face takes the light
// the sunlit yard before it sends, the back wall only what comes in through the window. Returns the
// mean indirect light over the back wall's pixels at `resolution`, over that at 1 with the same
// photons.
double renderBackWallThroughWindow(const std::string& resolution) {
    const nlohmann::json doc = nlohmann::json::parse(R"({
        "camera": {"position": [0, 2, -8], "target": [0, 2, 0], "fov_y_deg": 50},
        "materials": {"grey": {"diffuse": [0.6, 0.6, 0.6]}},
        "objects": [
            {"type": "box", "material": "grey", "min": [-12, -0.1, -12], "max": [12, 0, 12]},
            {"type": "box", "material": "grey", "min": [-5, 0, 0], "max": [-1, 5, 0.2]},
            {"type": "box", "material": "grey", "min": [1, 0, 0], "max": [5, 5, 0.2]},
            {"type": "box", "material": "grey", "min": [-1, 0, 0], "max": [1, 1, 0.2]},
            {"type": "box", "material": "grey", "min": [-1, 3, 0], "max": [1, 5, 0.2]},
            {"type": "box", "material": "grey", "min": [-5, 0, 4], "max": [5, 5, 4.2]},
            {"type": "box", "material": "grey", "min": [-5, 5, 0], "max": [5, 5.2, 4.2]},
            {"type": "box", "material": "grey", "min": [-5.2, 0, 0], "max": [-5, 5, 4.2]},
            {"type": "box", "material": "grey", "min": [5, 0, 0], "max": [5.2, 5, 4.2]}
        ],
        "lights": [{"type": "sun", "direction": [0.3, -1, 0.3], "irradiance": [100, 100, 100]}]
    })");
    const Scene scene = parseScene(doc, "window.json", ".");
    auto render = [&](const std::string& r, Image* position) {
        Settings s = withSettings(makeSplatSettings(scene, r), {{"radius_mode", "path_density"}});
        FrameRunner runner(scene, s, gl::TimingMethod::CpuFinish);
        runner.renderFrame();
        if (position)
            *position =
                readTextureImage(runner.getPasses().gbuffer.getGBuffer().getChannel("position"));
        return readTextureImage(runner.getAov(Aov::Indirect));
    };
    Image position;
    const Image sub = render(resolution, &position);
    const Image full = render("1", nullptr);
    double light = 0.0;
    double lightFull = 0.0;
    int pixels = 0;
    for (size_t i = 0; i < position.pixels.size(); ++i) {
        if (position.pixels[i].z < 3.9f) continue; // the back wall's face, z = 4
        light += double(sub.pixels[i].x);
        lightFull += double(full.pixels[i].x);
        ++pixels;
    }
    std::printf("splat_resolution %s: %d px of the back wall, mean light %.4f against %.4f at "
                "full resolution\n",
                resolution.c_str(), pixels, light / std::max(pixels, 1),
                lightFull / std::max(pixels, 1));
    EXPECT_GT(pixels, 400) << "the window shows too little of the back wall";
    EXPECT_GT(lightFull, 0.0) << "no indirect light on the back wall";
    return lightFull > 0.0 ? light / lightFull : 0.0;
}

TEST_F(SplatResolutionTest, AWallSeenThroughAWindowKeepsItsOwnLight) {
    for (const char* resolution : {"1/2", "1/4"}) {
        const double ratio = renderBackWallThroughWindow(resolution);
        // The back wall's pixels next to the window's edges have buffer pixels on the front wall
        // among their four taps. Measured 1.000 at 1/2 and 1.004 at 1/4; when the plane test's
        // footprint was taken towards the pixel's right-hand neighbour alone (across the edge
        // for pixels at the window's right: a 4 m step as the footprint), the front wall's light
        // passed and the back wall read 1.064 and 1.130.
        EXPECT_NEAR(ratio, 1.0, 0.03) << resolution;
    }
}

TEST(SplatResolution, AutoHalvesFrom256Pixels) {
    Settings s;
    EXPECT_EQ(computeSplatDivisor(s, 255, 4096), 1);
    EXPECT_EQ(computeSplatDivisor(s, 256, 256), 2);
    s.setEnum("splat_resolution", "1/4", "test");
    EXPECT_EQ(computeSplatDivisor(s, 64, 64), 4);
    EXPECT_EQ(computeSplatSize(s, 65, 64), glm::ivec2(17, 16)); // rounded up
}

} // namespace
} // namespace ispm::test
