// Where image-space photon mapping fails, measured: light leaking through a thin wall, energy lost
// at edges and corners, frame-to-frame flicker between seeds, and pixels no photon reaches. Each
// test prints its numbers and bounds today's behaviour, so a change that moves them shows up here.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"
#include "support/render_support.h"

#include "image/metrics.h"
#include "render/readback.h"
#include "render/reference_pass.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ispm::test {
namespace {

class FailureModeTest : public GlTest {};

constexpr int kSize = 48;           // px: small enough for llvmpipe, splats a few pixels wide
constexpr int kShadowMapSize = 512; // px: shadows sharp enough at 48 px
constexpr float kOnPlaneM = 1e-3f;  // a G-buffer position this close to a plane lies on it

// What one frame gives the measurements: radiance and the G-buffer under each pixel (row 0 top).
struct FrameImages {
    Image direct;
    Image indirect;
    Image total;
    Image position; // world, metres
    Image normal;   // world, turned toward the camera
    Image diffuse;  // reflectance; zero where no surface was hit (the scenes have no black walls)
};

FrameImages renderFrameImages(const Scene& scene, const Settings& settings) {
    FrameRunner runner(scene, settings, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    const GBuffer& g = runner.getPasses().gbuffer.getGBuffer();
    return {readTextureImage(runner.getAov(Aov::Direct)),
            readTextureImage(runner.getAov(Aov::Indirect)),
            readTextureImage(runner.getAov(Aov::Total)),
            readTextureImage(g.getChannel("position")),
            readTextureImage(g.getChannel("normal")),
            readTextureImage(g.getChannel("diffuse"))};
}

bool isSurface(const FrameImages& f, size_t i) {
    const glm::vec3 d = f.diffuse.pixels[i];
    return d.x + d.y + d.z > 0.0f;
}

double computeMeanValue(const glm::vec3& v) {
    return (double(v.x) + double(v.y) + double(v.z)) / 3.0;
}

// `base` at the tests' size and light cameras, 2 bounces, `photons` and `seed`.
Settings makeFailureSettings(const Settings& base, int photons, int seed) {
    Settings s = base;
    // The splats as they are: these tests measure how the method fails, not how a filter hides
    // it (the derived filter would span a third of a 48 px image).
    s = withSettings(s, {{"denoise", 0},
                         {"width", kSize},
                         {"height", kSize},
                         {"bounces", 2},
                         {"photons", photons},
                         {"shadow_map_size", kShadowMapSize},
                         {"seed", seed}});
    return s;
}

Settings makeCornellSettings(const Scene& scene, int photons, int seed) {
    return makeFailureSettings(scene.settings, photons, seed);
}

Scene loadCornell() {
    return loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
}

// ---------------------------------------------------------------------------------------------
// 1. Light leak through a thin wall.

constexpr float kRoomHalfM = 1.0f; // each room is a 2 m cube
constexpr float kWallGapM = 0.02f; // the shared wall: two faces 2 cm apart at x = -+1 cm
constexpr float kFloorY = -kRoomHalfM;

// Room A (x < 0) holds a point light; room B (x > 0) is sealed from it by a wall 2 cm thick.
// `inRoomA` puts the camera in A, else in B; the two cameras mirror each other across x = 0 and
// look at the foot of the shared wall.
Scene makeTwoRooms(bool inRoomA) {
    Scene scene;
    scene.sourcePath = "two rooms";
    Material m;
    m.name = "walls";
    m.diffuse = glm::vec3(0.7f);
    scene.materials.push_back(m);
    Mesh mesh;
    mesh.name = "rooms";
    const float h = kRoomHalfM;
    const float g = 0.5f * kWallGapM;
    addBox(mesh, {-g - 2.0f * h, -h, -h}, {-g, h, h});
    addBox(mesh, {g, -h, -h}, {g + 2.0f * h, h, h});
    scene.meshes.push_back(mesh);
    scene.instances.push_back({0, glm::mat4(1.0f)});
    Light light;
    light.type = LightType::Point;
    light.position = {-g - h, 0.3f, 0.1f}; // room A's centre, a little off so nothing is symmetric
    light.intensity = glm::vec3(2.0f);
    scene.lights.push_back(light);
    const float side = inRoomA ? -1.0f : 1.0f;
    // From the far side of the room, down at the foot of the shared wall: ~48 pixels of floor
    // lie within 10 cm of the wall.
    scene.camera.position = {side * 1.8f, 0.0f, 0.0f};
    scene.camera.target = {side * 0.2f, -0.8f, 0.0f};
    return scene;
}

// Mean indirect radiance over floor pixels whose distance to the shared wall's face is in
// [nearM, farM), and how many there were.
double computeFloorStripMean(const FrameImages& f, float nearM, float farM, int& count) {
    double sum = 0.0;
    count = 0;
    for (size_t i = 0; i < f.position.pixels.size(); ++i) {
        const glm::vec3 p = f.position.pixels[i];
        if (!isSurface(f, i) || std::abs(p.y - kFloorY) > kOnPlaneM) continue;
        const float fromWall = std::abs(p.x) - 0.5f * kWallGapM;
        if (fromWall < nearM || fromWall >= farM) continue;
        sum += computeMeanValue(f.indirect.pixels[i]);
        ++count;
    }
    return count > 0 ? sum / count : 0.0;
}

constexpr int kLeakPhotons = 20000; // derived splat radii 8-31 cm, all wider than the wall
constexpr float kLeakStripM = 0.1f; // the floor next to the wall, where splats could reach across
constexpr float kLeakFarM = 0.5f;   // farther than any splat reaches at radius_scale 1

// The thin wall's leak: room B's floor strip over room A's, with `radiusMode` and `splatClip`
// (settings names) at `scale`; room A's strip and room B's far floor in `stripA`, `farB`.
double measureThinWallLeak(const char* radiusMode, const char* splatClip, float scale,
                           double& stripA, double& farB) {
    Settings settings = withSettings(
        makeFailureSettings(Settings{}, kLeakPhotons, 1),
        {{"radius_scale", scale}, {"radius_mode", radiusMode}, {"splat_clip", splatClip}});
    const FrameImages a = renderFrameImages(makeTwoRooms(true), settings);
    const FrameImages b = renderFrameImages(makeTwoRooms(false), settings);
    // Shadow maps keep every bit of direct light in room A.
    double directB = 0.0;
    for (const glm::vec3& p : b.direct.pixels)
        directB = std::max(directB, computeMeanValue(p));
    EXPECT_EQ(directB, 0.0) << "direct light reached room B";
    int countA = 0;
    int countB = 0;
    int countFar = 0;
    stripA = computeFloorStripMean(a, 0.0f, kLeakStripM, countA);
    const double stripB = computeFloorStripMean(b, 0.0f, kLeakStripM, countB);
    farB = computeFloorStripMean(b, kLeakFarM, 2.0f * kRoomHalfM, countFar);
    EXPECT_GT(countA, 10);
    EXPECT_GT(countB, 10);
    EXPECT_GT(stripA, 0.0);
    const double leak = stripA > 0.0 ? stripB / stripA : 1.0;
    std::printf("thin wall, radius_mode %s, splat_clip %s, radius_scale %.0f: room A floor strip "
                "%.4g (%d px), room B strip %.4g (%d px), leak ratio %.3f; room B floor > %.1f m "
                "from wall %.3g\n",
                radiusMode, splatClip, double(scale), stripA, countA, stripB, countB, leak,
                double(kLeakFarM), farB);
    return leak;
}

// A photon on room A's floor and a pixel on room B's floor share a normal and a plane, so
// without a visibility test every splat wider than the wall's 2 cm reaches through (room B's
// strip got 30% of room A's light at radius_scale 1, 76% at 4). Each splat is clipped where rays
// in its surface plane hit a wall (shared/splat_clip.h): measured 0.000 at both scales. 0.05 is
// the bound the method is held to; a clip that misses the wall fails it.
constexpr double kMaxLeakRatio = 0.05;

TEST_F(FailureModeTest, LightLeaksThroughThinWall) {
    double leak[2] = {0.0, 0.0};
    const float scales[2] = {1.0f, 4.0f};
    for (int k = 0; k < 2; ++k) {
        double stripA = 0.0;
        double farB = 0.0;
        leak[k] = measureThinWallLeak("density", "auto", scales[k], stripA, farB);
        // Nothing reaches half a metre into room B at radius_scale 1: any light there is not a leak
        // through the wall but a bug in emission or tracing.
        if (k == 0) {
            EXPECT_EQ(farB, 0.0);
        }
    }
    EXPECT_LT(leak[0], kMaxLeakRatio);
    EXPECT_GE(leak[1], leak[0]);
}

// The thesis's travel radii and the path-density radii draw whole discs by default (splat_clip
// auto): they leak (measured 0.29 travel, 0.40 path density at radius_scale 1), and their discs
// lose what falls beyond the wall on room A's side (its strip 0.16 / 0.15 against 0.23 clipped).
// splat_clip on clips them as the density radii are: no leak, and room A's strip keeps its light
// (more than 1.2x the unclipped: a clip that drops the renormalisation fails).
TEST_F(FailureModeTest, TravelRadiiLeakUnlessClipped) {
    constexpr double kMinLeakUnclipped = 0.1; // the failure is there to be measured
    constexpr double kMinStripGain = 1.2;     // measured 1.38 (travel) and 1.52 (path density)
    for (const char* mode : {"travel", "path_density"}) {
        double stripWhole = 0.0;
        double stripClipped = 0.0;
        double farB = 0.0;
        const double whole = measureThinWallLeak(mode, "auto", 1.0f, stripWhole, farB);
        const double clipped = measureThinWallLeak(mode, "on", 1.0f, stripClipped, farB);
        EXPECT_GT(whole, kMinLeakUnclipped) << mode;
        EXPECT_LT(clipped, kMaxLeakRatio) << mode;
        EXPECT_GT(stripClipped, kMinStripGain * stripWhole) << mode;
    }
}

// ---------------------------------------------------------------------------------------------
// 2. Edges and corners: a splat that reaches past an edge loses what falls off the surface, and
// pixels near an edge gather from photons on one side only.

constexpr int kEdgeWindowPx = 6;       // searched for edges around each pixel: ~7 cm at 48 px
constexpr float kEdgeNormalDot = 0.9f; // neighbours whose normals differ more lie across an edge

// Mean ratio of `image` to `reference` over the pixels of `mask`, the channels averaged.
double computeMaskedRatio(const Image& image, const Image& reference, const PixelMask& mask) {
    return computeMeanValue(glm::vec3(computeMeanRatio(image, reference, &mask)));
}

// The frame's indirect light against the reference's over two bands of its surface pixels, by a
// distance each is given (metres from an edge; negative: in neither band): nearer than nearM,
// farther than farM.
struct BandRatios {
    double near = 0.0;
    double far = 0.0;
    size_t nearCount = 0;
    size_t farCount = 0;
};
BandRatios measureBandRatios(const FrameImages& f, const Image& reference,
                             const std::vector<float>& distance, float nearM, float farM) {
    PixelMask nearMask(distance.size(), 0);
    PixelMask farMask(distance.size(), 0);
    BandRatios r;
    for (size_t i = 0; i < distance.size(); ++i) {
        if (!isSurface(f, i) || distance[i] < 0.0f) continue;
        if (distance[i] < nearM) {
            nearMask[i] = 1;
            ++r.nearCount;
        } else if (distance[i] > farM) {
            farMask[i] = 1;
            ++r.farCount;
        }
    }
    r.near = computeMaskedRatio(f.indirect, reference, nearMask);
    r.far = computeMaskedRatio(f.indirect, reference, farMask);
    return r;
}

// Width of pixel (x, y) on its surface, metres: the distance to a horizontal neighbour on the
// same surface (the largest footprint in the image when neither neighbour is).
float computePixelFootprint(const FrameImages& f, int x, int y) {
    constexpr float kFallbackM = 0.02f; // the widest footprint in the 48 px Cornell view
    const int w = f.position.width;
    const size_t i = size_t(y * w + x);
    for (int nx : {x + 1, x - 1}) {
        if (nx < 0 || nx >= w) continue;
        const size_t j = size_t(y * w + nx);
        if (isSurface(f, j) && glm::dot(f.normal.pixels[i], f.normal.pixels[j]) >= kEdgeNormalDot) {
            return glm::length(f.position.pixels[i] - f.position.pixels[j]);
        }
    }
    return kFallbackM;
}

// Per pixel, the world distance to the nearest neighbour (within the window) on another surface:
// another normal, or no surface at all (the open front of the box). +inf where none is found.
std::vector<float> computeEdgeDistances(const FrameImages& f) {
    const int w = f.position.width;
    const int h = f.position.height;
    std::vector<float> out(f.position.pixels.size(), std::numeric_limits<float>::infinity());
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y * w + x);
            if (!isSurface(f, i)) continue;
            const float footprint = computePixelFootprint(f, x, y);
            for (int dy = -kEdgeWindowPx; dy <= kEdgeWindowPx; ++dy) {
                for (int dx = -kEdgeWindowPx; dx <= kEdgeWindowPx; ++dx) {
                    const int nx = x + dx;
                    const int ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const size_t j = size_t(ny * w + nx);
                    float d = 0.0f;
                    if (!isSurface(f, j)) {
                        // No position there: the open front of the box. Count pixels, each as
                        // wide as this one's footprint on its surface.
                        d = footprint * float(std::max(std::abs(dx), std::abs(dy)));
                    } else if (glm::dot(f.normal.pixels[i], f.normal.pixels[j]) < kEdgeNormalDot) {
                        d = glm::length(f.position.pixels[i] - f.position.pixels[j]);
                    } else {
                        continue;
                    }
                    out[i] = std::min(out[i], d);
                }
            }
        }
    }
    return out;
}

TEST_F(FailureModeTest, CornersAndEdgesLoseIndirectEnergy) {
    constexpr int kReferenceSpp = 64;
    constexpr float kCornerM = 0.02f; // about the median splat radius at 50k photons
    constexpr float kMiddleM = 0.06f; // beyond the largest splat radius (radius_max ~5 cm)
    constexpr int kSeeds = 6;         // 209 corner pixels: one frame's ratio moves by ~5%
    const Scene scene = loadCornell();
    // One reference for every frame: its noise is the same for all of them.
    const Image reference =
        renderReferenceIndirect(scene, makeCornellSettings(scene, 50000, 1), kReferenceSpp);
    double cornerSum = 0.0;
    double middleSum = 0.0;
    for (int seed = 1; seed <= kSeeds; ++seed) {
        const Settings settings = makeCornellSettings(scene, 50000, seed);
        const FrameImages f = renderFrameImages(scene, settings);
        const BandRatios r =
            measureBandRatios(f, reference, computeEdgeDistances(f), kCornerM, kMiddleM);
        ASSERT_GT(r.nearCount, 50u);
        ASSERT_GT(r.farCount, 50u);
        std::printf("corners, seed %d: ispm / reference indirect: within %.0f cm of an edge %.3f "
                    "(%zu px), more than %.0f cm %.3f (%zu px)\n",
                    seed, double(kCornerM) * 100.0, r.near, r.nearCount, double(kMiddleM) * 100.0,
                    r.far, r.farCount);
        cornerSum += r.near;
        middleSum += r.far;
    }
    const double cornerRatio = cornerSum / kSeeds;
    const double middleRatio = middleSum / kSeeds;
    // Unclipped splats lost the part of their disc past an edge: corner 0.897 against middle 0.945
    // (seed 1), 0.848 against 0.965 (seed 2), 0.91 of the middle on average. Clipped at walls
    // and renormalised per pixel (shared/splat_clip.h): seeds 1 and 2 measured corner 1.014 and
    // 0.937 against middle 0.989 and 0.984 with pcg numbers (wider discs lose more: 0.95 of the
    // middle with 0.29 sqrt(photons) neighbours, 0.93 with 0.4). With the default sobol
    // numbers, seeds 1..6 gave corners 0.94..1.03, middle 0.98..0.99, 0.98 of the middle on
    // average (0.95 when roulette and lobe shared their first bit: no grazing directions). With
    // each density block's area taken from its photons' span (a block at a corner no longer
    // counts the air beyond the wall) and 0.3 sqrt(photons) neighbours: corners 1.00..1.08,
    // middle 0.98..0.99, 1.03 of the middle on average.
    // Mid-wall light is right to 10% (splat blur and both images' noise); the corners are held
    // to the middle within 5% on average, which the unclipped splats fail.
    constexpr double kMiddleTolerance = 0.1;
    constexpr double kCornerToMiddleTolerance = 0.05;
    EXPECT_NEAR(middleRatio, 1.0, kMiddleTolerance);
    EXPECT_NEAR(cornerRatio / middleRatio, 1.0, kCornerToMiddleTolerance);
}

// A wall 2 m wide and 2 m high on a sunlit yard, seen from the front: the sky above its top, the
// yard behind its sides. Its face (z = 0, facing -z) is lit by the yard's bounce.
constexpr float kYardWallHalfWidthM = 1.0f;
constexpr float kYardWallHeightM = 2.0f;
Scene makeWallInYard() {
    Scene scene;
    scene.sourcePath = "wall in a yard";
    Material ground;
    ground.name = "ground";
    ground.diffuse = glm::vec3(0.5f);
    Material wall;
    wall.name = "wall";
    wall.diffuse = glm::vec3(0.7f);
    scene.materials = {ground, wall};
    Mesh yard;
    yard.name = "yard";
    addBox(yard, {-6.0f, -0.1f, -6.0f}, {6.0f, 0.0f, 6.0f});
    Mesh block;
    block.name = "wall";
    addBox(block, {-kYardWallHalfWidthM, 0.0f, 0.0f},
           {kYardWallHalfWidthM, kYardWallHeightM, 0.2f});
    block.triangleMaterials.assign(block.triangles.size(), 1); // the wall's material
    scene.meshes = {yard, block};
    scene.instances = {{0, glm::mat4(1.0f)}, {1, glm::mat4(1.0f)}};
    Light sun;
    sun.type = LightType::Sun;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.6f)); // onto the yard and the face
    sun.irradiance = glm::vec3(3.0f);
    scene.lights.push_back(sun);
    scene.camera.position = {0.0f, 1.2f, -3.5f};
    scene.camera.target = {0.0f, 1.0f, 0.0f};
    scene.camera.fovYDeg = 50.0f;
    return scene;
}

// Discs without clip lines (splat_clip off) reach past a wall's top into the sky and past its
// sides into the yard behind, and the light they take there is lost: the face's rim came out
// darker than its middle. surface_ends divides each photon's power by the share of its disc the
// viewer G-buffer shows a surface for, which keeps that light on the face.
TEST_F(FailureModeTest, SurfaceEndsKeepTheLightAtAWallsRim) {
    constexpr int kReferenceSpp = 64;
    constexpr float kRimM = 0.3f; // the face within this of its top or sides
    constexpr int kSeeds = 4;
    const Scene scene = makeWallInYard();
    const Settings base = makeFailureSettings(scene.settings, 50000, 1);
    const Image reference = renderReferenceIndirect(scene, base, kReferenceSpp);
    double rimToMiddle[2] = {0.0, 0.0}; // surface_ends off, on
    for (int on = 0; on < 2; ++on) {
        for (int seed = 1; seed <= kSeeds; ++seed) {
            Settings settings =
                withSettings(makeFailureSettings(scene.settings, 50000, seed),
                             {{"splat_clip", "off"}, {"surface_ends", on == 1 ? "on" : "off"}});
            const FrameImages f = renderFrameImages(scene, settings);
            // The face's pixels by their distance from its top or sides; the foot (a corner with
            // the yard, not an edge seen past) belongs to neither band.
            std::vector<float> fromRim(f.position.pixels.size(), -1.0f);
            for (size_t i = 0; i < fromRim.size(); ++i) {
                const glm::vec3 p = f.position.pixels[i];
                if (std::abs(p.z) > kOnPlaneM || f.normal.pixels[i].z > -0.9f || p.y < kRimM)
                    continue;
                fromRim[i] = std::min(kYardWallHalfWidthM - std::abs(p.x), kYardWallHeightM - p.y);
            }
            const BandRatios r = measureBandRatios(f, reference, fromRim, kRimM, 2.0f * kRimM);
            ASSERT_GT(r.nearCount, 50u);
            ASSERT_GT(r.farCount, 50u);
            std::printf("wall in a yard, surface_ends %s, seed %d: ispm / reference indirect on "
                        "the face's rim %.3f (%zu px), middle %.3f (%zu px)\n",
                        on == 1 ? "on" : "off", seed, r.near, r.nearCount, r.far, r.farCount);
            rimToMiddle[on] += r.near / r.far / kSeeds;
        }
    }
    std::printf("rim / middle: surface_ends off %.3f, on %.3f\n", rimToMiddle[0], rimToMiddle[1]);
    // Seeds 1-4 measured the rim at 0.720 of the middle without (0.61-0.75 a seed) and 0.856
    // with (0.74-0.94; the same seeds: 1.13-1.30 times as much as without). Not 1: each photon
    // keeps its power on the face, but a pixel on the rim still gathers from photons on one side
    // only. Held: the loss shows without (under 0.8), and surface_ends takes back a third of it
    // (at least 1.1 times the rim's share: the seeds' spread is about 0.05 on the mean).
    constexpr double kRimLossShows = 0.8;
    constexpr double kRimGain = 1.1;
    EXPECT_LT(rimToMiddle[0], kRimLossShows);
    EXPECT_GT(rimToMiddle[1], kRimGain * rimToMiddle[0]);
}

// ---------------------------------------------------------------------------------------------
// 3. Flicker: two frames that differ only in their seed, as consecutive frames of a still scene
// do when the seed changes per frame.

double measureSeedFlicker(const Scene& scene, Settings settings, Aov aov) {
    settings.set("seed", 1, "test");
    const Image a = renderAov(scene, settings, aov);
    settings.set("seed", 2, "test");
    const Image b = renderAov(scene, settings, aov);
    return computeRelMse(b, a);
}

TEST_F(FailureModeTest, FlickerBetweenSeeds) {
    constexpr float kFixedRadiusM = 0.03f; // the derived radius at ~25k photons, held fixed
    const Scene scene = loadCornell();
    const int counts[2] = {10000, 50000};
    double derived[2] = {};
    double fixed[2] = {};
    double total[2] = {};
    for (int k = 0; k < 2; ++k) {
        Settings s = makeCornellSettings(scene, counts[k], 1);
        derived[k] = measureSeedFlicker(scene, s, Aov::Indirect);
        total[k] = measureSeedFlicker(scene, s, Aov::Total);
        s = withSettings(s, {{"radius_min", kFixedRadiusM}, {"radius_max", kFixedRadiusM}});
        fixed[k] = measureSeedFlicker(scene, s, Aov::Indirect);
        std::printf("flicker, %d photons: indirect relMSE seed 1 vs 2 %.4f (derived radii), "
                    "%.4f (radius fixed at %.0f cm); total %.4f\n",
                    counts[k], derived[k], fixed[k], double(kFixedRadiusM) * 100.0, total[k]);
    }
    // Measured (denoise off): at a fixed radius relMSE falls 0.188 -> 0.032 (5.8x for 5x
    // photons: 1/N). Density radii hold 0.11 sqrt(photons) photons a disc (16 at 10k, 25 at 50k),
    // so they fall too: 0.097 -> 0.048 (2.0x). (Travel radii, which hold ~32 whatever the budget,
    // did not fall at all: 0.040 -> 0.046.) The whole frame (direct light is identical in both)
    // flickers 0.078 and 0.041.
    constexpr double kMinFixedRadiusGain = 3.0; // 1/N predicts 5
    constexpr double kMaxDerivedFlicker = 0.07; // at 50k photons
    constexpr double kMaxTotalFlicker = 0.05;   // at 50k photons
    EXPECT_GT(fixed[0] / fixed[1], kMinFixedRadiusGain);
    EXPECT_LT(derived[1], kMaxDerivedFlicker);
    EXPECT_LT(derived[1], derived[0] / 1.5) << "more photons must steady the density radii";
    EXPECT_LT(total[1], kMaxTotalFlicker);
}

// Travel radii under importance sampling (the default share 0.75): photons from the map's floor
// arrive with up to 4x their unaimed power and splat whole discs of it, blotches that
// move from seed to seed. widen_strong draws them sqrt(power / mean) times wider (at most 2x).
TEST_F(FailureModeTest, WideningStrongPhotonsSteadiesTravelRadii) {
    const Scene scene = loadCornell();
    double flicker[2] = {};
    double energy[2] = {};
    const char* choices[2] = {"off", "on"};
    for (int k = 0; k < 2; ++k) {
        Settings s = withSettings(makeCornellSettings(scene, 10000, 1),
                                  {{"radius_mode", "travel"}, {"widen_strong", choices[k]}});
        flicker[k] = measureSeedFlicker(scene, s, Aov::Indirect);
        const FrameImages f = renderFrameImages(scene, s);
        for (const glm::vec3& p : f.indirect.pixels)
            energy[k] += computeMeanValue(p);
        std::printf("travel radii, widen_strong %s: indirect relMSE seed 1 vs 2 %.4f, indirect "
                    "sum %.4g\n",
                    choices[k], flicker[k], energy[k]);
    }
    // Measured 0.0243 -> 0.0124 (2.0x), the indirect light's sum 0.977 of the unwidened: a wider
    // disc keeps its power but for what falls off an edge.
    constexpr double kMinFlickerGain = 1.5;
    constexpr double kMaxEnergyChange = 0.05;
    ASSERT_GT(energy[0], 0.0);
    EXPECT_GT(flicker[0] / flicker[1], kMinFlickerGain);
    EXPECT_NEAR(energy[1] / energy[0], 1.0, kMaxEnergyChange);
}

// ---------------------------------------------------------------------------------------------
// 4. Sparse photons: surface pixels that no splat reaches stay black in the indirect image.

double measureUncoveredFraction(const Scene& scene, const Settings& settings) {
    const FrameImages f = renderFrameImages(scene, settings);
    size_t surface = 0;
    size_t dark = 0;
    for (size_t i = 0; i < f.indirect.pixels.size(); ++i) {
        if (!isSurface(f, i)) continue;
        ++surface;
        if (computeMeanValue(f.indirect.pixels[i]) <= 0.0) ++dark;
    }
    return surface > 0 ? double(dark) / double(surface) : 1.0;
}

TEST_F(FailureModeTest, SparsePhotonsLeaveUncoveredPixels) {
    const Scene scene = loadCornell();
    const int counts[3] = {2000, 10000, 50000};
    const float scales[2] = {1.0f, 0.5f};
    double dark[2][3] = {};
    double darkDensity[3] = {};
    for (int r = 0; r < 2; ++r) {
        for (int k = 0; k < 3; ++k) {
            Settings s = withSettings(makeCornellSettings(scene, counts[k], 1),
                                      {{"radius_mode", "travel"}, {"radius_scale", scales[r]}});
            dark[r][k] = measureUncoveredFraction(scene, s);
        }
        std::printf("uncovered surface pixels, travel radii, radius_scale %.1f: %.4f (2k) %.4f "
                    "(10k) %.4f (50k)\n",
                    double(scales[r]), dark[r][0], dark[r][1], dark[r][2]);
    }
    for (int k = 0; k < 3; ++k) {
        darkDensity[k] = measureUncoveredFraction(scene, makeCornellSettings(scene, counts[k], 1));
    }
    std::printf("uncovered surface pixels, density radii (the default): %.4f (2k) %.4f (10k) "
                "%.4f (50k)\n",
                darkDensity[0], darkDensity[1], darkDensity[2]);
    Settings s = makeCornellSettings(scene, 2000, 1);
    constexpr double kFixedRadiusM = 0.03; // the derived radius at ~25k photons
    s = withSettings(s, {{"radius_min", kFixedRadiusM}, {"radius_max", kFixedRadiusM}});
    const double fixed2k = measureUncoveredFraction(scene, s);
    s.set("photons", 50000, "test");
    const double fixed50k = measureUncoveredFraction(scene, s);
    std::printf("uncovered, radius fixed at 3 cm: %.4f (2k) %.4f (50k)\n", fixed2k, fixed50k);
    // Measured: travel radii leave 0, 0, 0.05% of surface pixels dark at 2k, 10k, 50k photons;
    // radius_scale 0.5 leaves 0.14%, 0.33%, 0.8% (2.0%, 0.7%, 2.1% before photons were aimed at
    // the view). The derived radius keeps the expected photons per
    // disc constant (32 at scale 1, 8 at 0.5), so more photons do not fill holes by themselves;
    // only a larger radius does. Density radii grow where photons are sparse: 0.05% dark at 10k
    // and 50k; at 2k 0.52% here (0.43% before unlit points' importance took a second bounce),
    // 0.05-3.7% over seeds 1-12 (`ispm render` at this size, shadow_map_size 256). At a fixed
    // 3 cm radius coverage grows with photons: 21-40% dark at 2k, 0.05-0.19% at 50k. Bounds sit
    // above each measurement.
    constexpr double kMaxDarkDerived = 0.005;
    constexpr double kMaxDarkDensity[3] = {0.01, 0.005, 0.005};
    constexpr double kMaxDarkHalfRadius = 0.05;
    constexpr double kMinDarkFixed2k = 0.2;
    constexpr double kMaxDarkFixed50k = 0.01;
    for (int k = 0; k < 3; ++k) {
        EXPECT_LT(dark[0][k], kMaxDarkDerived) << counts[k] << " photons";
        EXPECT_LT(dark[1][k], kMaxDarkHalfRadius) << counts[k] << " photons";
        EXPECT_GE(dark[1][k], dark[0][k]) << counts[k] << " photons";
        EXPECT_LT(darkDensity[k], kMaxDarkDensity[k]) << counts[k] << " photons, density radii";
    }
    // Halving travel radii opens holes somewhere (photons aimed by importance cover the 2k case).
    EXPECT_GT(dark[1][0] + dark[1][1] + dark[1][2], dark[0][0] + dark[0][1] + dark[0][2]);
    EXPECT_GT(fixed2k, kMinDarkFixed2k);
    EXPECT_LT(fixed50k, kMaxDarkFixed50k);
}

} // namespace
} // namespace ispm::test
