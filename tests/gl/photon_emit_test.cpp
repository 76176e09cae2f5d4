// Photon emission against a CPU oracle: the bounce buffer written by transform feedback must hold
// exactly the photons that a CPU re-derivation of photon_emit.geom's rules predicts, at awkward
// budgets (1, 7, 1000, 12345 photons), for a spot, a point light (six views) and the sun. The
// oracle warps each grid cell through the importance tables the frame built (read back) with its
// own inverse-CDF search in double, and gives it the power density of the view over the pdf. It
// calls none of the code under test: the random stream (PCG hash, Jarzynski and Olano 2020), the
// grid's shift, the basis (Duff et al. 2017) and the scatter rules are written again below, in
// double, from their statements.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"

#include "core/strings.h"
#include "render/frame.h"
#include "scene/scene.h"
#include "support/test_settings.h"

#include <shared/importance_data.h>
#include <shared/photon_data.h>
#include <shared/photon_scatter.h> // constants only (event codes, kDeltaConcentration)

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace ispm::test {
namespace {

// Odd, so that no texel edge falls on the centre of the view or of a map texel; photons that land
// within round-off of a texel edge anyway are marginal (either texel is right).
constexpr int kLightResolution = 63;
constexpr int kImageSize = 16;     // the viewer image plays no part here: keep it cheap
constexpr uint32_t kSeed = 12345u; // any fixed seed: the GPU and the oracle draw the same numbers
constexpr uint32_t kBudgets[] = {1u, 7u, 1000u, 12345u};

// Two float implementations of the same math (the GPU's sin/cos/pow/sqrt differ from libm by a
// few ulp, the oracle's power is computed in double): 1e-4 relative is far above that noise and
// far below any real mistake (a wrong texel, branch, factor or sign).
constexpr double kRelativeTolerance = 1e-4;
// Absolute round-off of the cosine between a float direction and the spot axis (a few ulps of 1).
constexpr double kCosineRoundOff = 4.0 * double(FLT_EPSILON);
// Absolute round-off of a sampled unit direction (float sin, cos and pow on either side; the
// largest seen is 4e-7).
constexpr double kDirectionRoundOff = 2e-6;
// A decision whose operands lie this close to its threshold may go either way on the GPU.
constexpr double kMarginalGap = 1e-5;
// At most this fraction of photons may differ, and only those with a marginal decision.
constexpr double kMaxFlipFraction = 1e-3;

// ---------------------------------------------------------------------------------------------
// Scenes: one floor and three walls of different materials so every scatter branch is taken.

void addQuad(Scene& scene, const std::array<glm::vec3, 4>& corners, uint32_t material) {
    Mesh mesh;
    mesh.name = strCat("quad ", scene.meshes.size());
    mesh.positions.assign(corners.begin(), corners.end());
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    mesh.triangleMaterials = {material, material};
    scene.instances.push_back({static_cast<uint32_t>(scene.meshes.size()), glm::mat4(1.0f)});
    scene.meshes.push_back(std::move(mesh));
}

Material makeMaterial(const char* name, glm::vec3 diffuse) {
    Material m;
    m.name = name;
    m.diffuse = diffuse;
    return m;
}

// An open room (no ceiling, no front wall): some light-camera texels see nothing.
Scene makeRoomScene(const Light& light) {
    Scene scene;
    scene.sourcePath = "photon emit test room";
    scene.camera.position = {0.0f, 1.0f, 3.0f};
    scene.camera.target = {0.0f, 0.5f, 0.0f};
    scene.materials.push_back(makeMaterial("floor", {0.6f, 0.5f, 0.4f}));
    Material glossy = makeMaterial("glossy", glm::vec3(0.3f));
    glossy.specular = glm::vec3(0.4f, 0.45f, 0.5f);
    glossy.phongExponent = 20.0f;
    scene.materials.push_back(glossy);
    Material glass = makeMaterial("glass", glm::vec3(0.15f));
    glass.transmissive = glm::vec3(0.6f, 0.7f, 0.65f);
    glass.ior = 1.5f;
    scene.materials.push_back(glass);
    scene.materials.push_back(makeMaterial("green", {0.2f, 0.7f, 0.2f}));
    constexpr float s = 2.0f; // half size of the room (m)
    constexpr float h = 2.5f; // wall height (m)
    addQuad(scene, {{{-s, 0, -s}, {-s, 0, s}, {s, 0, s}, {s, 0, -s}}}, 0);   // floor
    addQuad(scene, {{{-s, 0, -s}, {s, 0, -s}, {s, h, -s}, {-s, h, -s}}}, 1); // back
    addQuad(scene, {{{-s, 0, s}, {-s, 0, -s}, {-s, h, -s}, {-s, h, s}}}, 2); // left
    addQuad(scene, {{{s, 0, -s}, {s, 0, s}, {s, h, s}, {s, h, -s}}}, 3);     // right
    scene.lights.push_back(light);
    return scene;
}

Light makeSpot() {
    Light light;
    light.type = LightType::Spot;
    light.position = {0.8f, 2.0f, 1.2f};
    light.direction = glm::normalize(glm::vec3(-1.5f, -1.6f, -2.0f));
    light.intensity = {20.0f, 15.0f, 10.0f};
    light.innerDeg = 25.0f;
    light.outerDeg = 45.0f;
    return light;
}

Light makePoint(glm::vec3 position, glm::vec3 intensity) {
    Light light;
    light.type = LightType::Point;
    light.position = position;
    light.intensity = intensity;
    return light;
}

Light makeSun() {
    Light light;
    light.type = LightType::Sun;
    // Through the glass wall from outside (its back face, leaving the medium), steep enough
    // (sin 0.55 < 1 / 1.5) that some photons refract rather than all reflecting totally.
    light.direction = glm::normalize(glm::vec3(1.0f, -0.6f, -0.3f));
    light.irradiance = {3.0f, 2.5f, 2.0f};
    return light;
}

// A closed box around the point: every texel of every cube face sees a surface.
Scene makeClosedBoxScene(const Light& light) {
    Scene scene;
    scene.sourcePath = "photon emit test closed box";
    scene.camera.position = {0.0f, 0.0f, 0.5f};
    scene.camera.target = {0.0f, 0.0f, -1.0f};
    // Reflectance 1: Russian roulette keeps every photon and leaves its power unchanged.
    scene.materials.push_back(makeMaterial("white", glm::vec3(1.0f)));
    Mesh mesh;
    mesh.name = "box";
    constexpr float s = 1.0f;
    for (int i = 0; i < 8; ++i) {
        mesh.positions.push_back({(i & 1) ? s : -s, (i & 2) ? s : -s, (i & 4) ? s : -s});
    }
    // Shared corners make the faces watertight under the rasteriser's edge rules.
    const std::array<std::array<uint32_t, 4>, 6> faces = {
        {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}}};
    for (const auto& f : faces) {
        mesh.triangles.push_back({f[0], f[1], f[2]});
        mesh.triangles.push_back({f[0], f[2], f[3]});
        mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {0u, 0u});
    }
    scene.meshes.push_back(std::move(mesh));
    scene.instances.push_back({0, glm::mat4(1.0f)});
    scene.lights.push_back(light);
    return scene;
}

Settings makeSettings(uint32_t photons) {
    Settings settings = makeTestSettings({{"width", kImageSize},
                                          {"height", kImageSize},
                                          {"shadow_map_size", kLightResolution},
                                          {"photons", photons},
                                          {"bounces", 1},
                                          {"seed", kSeed}});
    return settings;
}

// ---------------------------------------------------------------------------------------------
// The oracle. It re-derives photon_emit.geom's rules from their statement
// (docs/design.md "Units and conventions"), independently of the shader's code: same texel per
// grid cell, power = intensity x spot falloff x exact cell solid angle (or irradiance x cell
// area), then the first bounce by the oracle's scatterOracle with the photon's own random stream.

// The oracle's own random stream: the PCG RXS-M-XS hash of Jarzynski and Olano (2020), seeded
// by hashing frame seed, bounce and photon in turn; each number is the top 24 bits over 2^24.
uint32_t hashOracle(uint32_t v) {
    const uint32_t state = v * 747796405u + 2891336453u;
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

uint32_t seedOracle(uint32_t photon, uint32_t bounce, uint32_t frameSeed) {
    return hashOracle(photon ^ hashOracle(bounce ^ hashOracle(frameSeed)));
}

// pcg: the state is hashed again; lcg: the Numerical Recipes linear congruential step.
double nextOracle(uint32_t& state, uint32_t mode) {
    state = mode == gpu::kRngLcg ? 1664525u * state + 1013904223u : hashOracle(state);
    return double(state >> 8u) / 16777216.0;
}

// The grid's shift inside its cells this frame: two numbers of the view's own stream (bounce
// slot 0xffffffff).
glm::dvec2 computeOracleGridShift(uint32_t view, uint32_t frameSeed) {
    uint32_t state = seedOracle(view, 0xffffffffu, frameSeed);
    const double x = nextOracle(state, gpu::kRngPcg);
    return {x, nextOracle(state, gpu::kRngPcg)};
}

// sobol: the Sobol sequence's first three dimensions by the Bratley-Fox recurrence on the
// direction integers m_k of the primitive polynomials 1 (m_k = 1), x + 1 (m_1 = 1) and
// x^2 + x + 1 (m_1 = 1, m_2 = 3): m_k = 2 a_1 m_{k-1} xor ... xor 2^s m_{k-s} xor m_{k-s}; the
// point of index i xors m_k 2^(32-k) over the set bits k-1 of i.
std::array<std::array<uint32_t, 32>, 3> makeOracleSobolDirections() {
    std::array<std::array<uint32_t, 32>, 3> v{};
    for (int k = 1; k <= 32; ++k) {
        std::array<uint64_t, 3> m{};
        m[0] = 1;
        if (k == 1) {
            m[1] = 1;
            m[2] = 1;
        } else {
            const uint64_t m1 = uint64_t(v[1][k - 2]) >> (32 - (k - 1));
            m[1] = (2 * m1) ^ m1; // s = 1: 2^1 m_{k-1} xor m_{k-1}
            if (k == 2) {
                m[2] = 3;
            } else {
                const uint64_t back1 = uint64_t(v[2][k - 2]) >> (32 - (k - 1));
                const uint64_t back2 = uint64_t(v[2][k - 3]) >> (32 - (k - 2));
                m[2] = (2 * back1) ^ (4 * back2) ^ back2; // s = 2, a_1 = 1
            }
        }
        for (int d = 0; d < 3; ++d)
            v[d][k - 1] = static_cast<uint32_t>(m[d] << (32 - k));
    }
    return v;
}

// Bits of a 32-bit word in reverse order, one at a time.
uint32_t reverseOracleBits(uint32_t v) {
    uint32_t r = 0;
    for (int i = 0; i < 32; ++i)
        r |= ((v >> i) & 1u) << (31 - i);
    return r;
}

// Owen scrambling by the hash of Burley (2020) with Vegdahl's constants, from its statement.
uint32_t scrambleOracle(uint32_t v, uint32_t seed) {
    uint32_t x = reverseOracleBits(v);
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return reverseOracleBits(x);
}

// The cell's place on the Z-order curve: bit b of x to bit 2b, bit b of y to bit 2b + 1.
uint32_t computeOracleZOrder(glm::uvec2 cell) {
    uint32_t z = 0;
    for (int b = 0; b < 16; ++b)
        z |= ((cell.x >> b) & 1u) << (2 * b) | ((cell.y >> b) & 1u) << (2 * b + 1);
    return z;
}

// The first bounce's numbers (roulette, then the lobe's two) for a photon: pcg and lcg draw
// them in turn from the photon's stream; sobol takes Sobol points of the Z-order index, each
// dimension scrambled by its own seed (hashes of the view's stream, slot 0xfffffffe).
std::array<double, 3> drawOracleNumbers(uint32_t photon, glm::uvec2 cell, uint32_t view,
                                        uint32_t frameSeed, uint32_t mode) {
    std::array<double, 3> numbers{};
    if (mode != gpu::kRngSobol) {
        uint32_t rng = seedOracle(photon, 0u, frameSeed);
        for (double& u : numbers)
            u = nextOracle(rng, mode);
        return numbers;
    }
    static const std::array<std::array<uint32_t, 32>, 3> directions = makeOracleSobolDirections();
    std::array<uint32_t, 4> seeds{};
    uint32_t seed = seedOracle(view, 0xfffffffeu, frameSeed);
    for (uint32_t& s : seeds) {
        seed = hashOracle(seed);
        s = seed;
    }
    // Dimension 0 of the cell's index, dimensions 1 and 2 of the index scrambled by seeds[3].
    const uint32_t index = computeOracleZOrder(cell);
    const uint32_t shuffled = scrambleOracle(index, seeds[3]);
    for (int d = 0; d < 3; ++d) {
        const uint32_t at = d == 0 ? index : shuffled;
        uint32_t x = 0;
        for (int k = 0; k < 32; ++k) {
            if ((at >> k) & 1u) x ^= directions[d][k];
        }
        numbers[d] = double(scrambleOracle(x, seeds[d]) >> 8) / 16777216.0;
    }
    return numbers;
}

// Duff et al. (2017): an orthonormal basis (t, b) around unit n.
void buildOracleBasis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    const double sign = n.z >= 0.0 ? 1.0 : -1.0;
    const double a = -1.0 / (sign + n.z);
    const double c = n.x * n.y * a;
    t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
    b = {c, sign + n.y * n.y * a, -n.y};
}

// A direction at polar cosine cosAlpha and azimuth 2 pi u2 around `axis`.
glm::dvec3 makeOracleDirection(const glm::dvec3& axis, double cosAlpha, double u2) {
    glm::dvec3 t;
    glm::dvec3 b;
    buildOracleBasis(axis, t, b);
    const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - cosAlpha * cosAlpha));
    const double phi = 2.0 * glm::pi<double>() * u2;
    return glm::normalize(t * (sinAlpha * std::cos(phi)) + b * (sinAlpha * std::sin(phi)) +
                          axis * cosAlpha);
}

double computeOracleMean(const glm::dvec3& v) {
    return (v.x + v.y + v.z) / 3.0;
}

// Unpolarised Fresnel reflectance of a dielectric, eta = n_incident / n_transmitted.
double computeOracleFresnel(double cosI, double eta) {
    const double sin2T = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
    if (sin2T >= 1.0) return 1.0;
    const double cosT = std::sqrt(1.0 - sin2T);
    const double rs = (eta * cosI - cosT) / (eta * cosI + cosT);
    const double rp = (cosI - eta * cosT) / (cosI + eta * cosT);
    return 0.5 * (rs * rs + rp * rp);
}

// Schlick's weight (1 - cos)^5 of the material's Fresnel split (docs/scene-format.md): 0 on a
// material without specular.
double computeOracleSchlick(double cosTheta, const glm::dvec4& specular) {
    if (glm::dvec3(specular) == glm::dvec3(0.0)) return 0.0;
    return std::pow(1.0 - std::clamp(cosTheta, 0.0, 1.0), 5.0);
}

// The lobes' reflectances for a photon arriving at cos(theta): diffuse rho_d (1 - g), specular
// rho_s + rho_d g.
glm::dvec3 computeOracleDiffuseAlbedo(const glm::dvec3& diffuse, const glm::dvec4& specular,
                                      double cosTheta) {
    return diffuse * (1.0 - computeOracleSchlick(cosTheta, specular));
}
glm::dvec3 computeOracleSpecularAlbedo(const glm::dvec3& diffuse, const glm::dvec4& specular,
                                       double cosTheta) {
    return glm::dvec3(specular) + diffuse * computeOracleSchlick(cosTheta, specular);
}

// The first bounce by its statement (docs/design.md "Frame, as data flows"; docs/scene-format.md):
// Russian roulette on the mean reflectance of the diffuse, specular and transmissive lobes at the
// photon's incidence in that order with u, then the lobe's direction from (u1, u2): cosine-weighted
// (weight: the coupled lobe 21/20 rho_d (1 - g_in)(1 - g_out) / p_d, or rho_d / p_d without
// specular); the normalised Phong lobe around the mirror direction (absorbed below the surface;
// weight rho_s(h) (e + 2) / (e + 1) cos(out) / p_s, rho_s(h) the specular reflectance at the half
// vector's angle); Fresnel reflection or refraction by u1. The weight is divided by the lobe's
// probability. With first_bounce weighted every lobe's probability is divided by the surface's
// albedo (the means of its diffuse, specular and transmissive reflectance summed), so they sum to
// 1 and only a Phong lobe below the surface absorbs.
double computeOracleSelectScale(const glm::dvec3& diffuse, const glm::dvec4& specular,
                                const glm::dvec4& transmissive, uint32_t firstBounce) {
    if (firstBounce != gpu::kFirstBounceWeighted) return 1.0;
    return 1.0 / (computeOracleMean(diffuse) + computeOracleMean(glm::dvec3(specular)) +
                  computeOracleMean(glm::dvec3(transmissive)));
}

uint32_t scatterOracle(glm::dvec3& dir, glm::dvec3& power, const glm::dvec3& n,
                       const glm::dvec3& diffuse, const glm::dvec4& specular,
                       const glm::dvec4& transmissive, bool entering,
                       const std::array<double, 3>& numbers, double selectScale) {
    constexpr double kCoupledScale = 21.0 / 20.0;
    const double cosIn = std::clamp(-glm::dot(dir, n), 0.0, 1.0);
    const double pd =
        computeOracleMean(computeOracleDiffuseAlbedo(diffuse, specular, cosIn)) * selectScale;
    const double ps =
        computeOracleMean(computeOracleSpecularAlbedo(diffuse, specular, cosIn)) * selectScale;
    const double pt = computeOracleMean(glm::dvec3(transmissive)) * selectScale;
    const auto [u, u1, u2] = numbers;
    if (u < pd) {
        dir = makeOracleDirection(n, std::sqrt(std::max(0.0, 1.0 - u1)), u2);
        if (glm::dvec3(specular) == glm::dvec3(0.0)) {
            power *= diffuse / pd;
        } else {
            power *= diffuse * (kCoupledScale * (1.0 - computeOracleSchlick(cosIn, specular)) *
                                (1.0 - computeOracleSchlick(glm::dot(dir, n), specular)) / pd);
        }
        return gpu::kScatterDiffuse;
    }
    if (u < pd + ps) {
        const double e = specular.w;
        const glm::dvec3 out =
            makeOracleDirection(glm::reflect(dir, n), std::pow(u1, 1.0 / (e + 1.0)), u2);
        const double cosOut = glm::dot(out, n);
        if (cosOut <= 0.0) return gpu::kScatterAbsorbed;
        const glm::dvec3 half = glm::normalize(out - dir);
        const glm::dvec3 rhoS = computeOracleSpecularAlbedo(diffuse, specular, glm::dot(out, half));
        power *= rhoS / ps * ((e + 2.0) / (e + 1.0) * cosOut);
        dir = out;
        return gpu::kScatterSpecular;
    }
    if (u < pd + ps + pt) {
        const double eta = entering ? 1.0 / transmissive.w : transmissive.w;
        const double cosI = std::clamp(-glm::dot(dir, n), 0.0, 1.0);
        power *= glm::dvec3(transmissive) / pt;
        if (u1 < computeOracleFresnel(cosI, eta)) {
            dir = glm::reflect(dir, n);
            return gpu::kScatterReflect;
        }
        const double sin2T = eta * eta * (1.0 - cosI * cosI);
        dir = glm::normalize(dir * eta + n * (eta * cosI - std::sqrt(1.0 - sin2T)));
        return gpu::kScatterRefract;
    }
    return gpu::kScatterAbsorbed;
}

// Path density after the first bounce: 1 after a diffuse bounce, (e + 2) / 2 after a Phong one,
// kDeltaConcentration after a mirror or refraction.
double computeOraclePathDensity(uint32_t event, double exponent) {
    if (event == gpu::kScatterSpecular) return (exponent + 2.0) * 0.5;
    if (event == gpu::kScatterReflect || event == gpu::kScatterRefract)
        return double(gpu::kDeltaConcentration);
    return 1.0;
}

struct ExpectedPhoton {
    gpu::BouncePhoton photon;
    uint32_t event = gpu::kScatterAbsorbed;
    // Relative power error allowed: kRelativeTolerance plus what float round-off of a grazing
    // Phong weight can add to this photon.
    double powerTolerance = kRelativeTolerance;
};

struct Reference {
    std::vector<ExpectedPhoton> photons;   // survivors, in emission order
    std::set<uint32_t> marginal;           // photons with a decision on its threshold
    glm::dvec3 emittedPowerW{0.0};         // cell powers before the bounce, summed
    std::array<uint32_t, 5> eventCounts{}; // by kScatter*, absorbed included
};

// The inverse CDF of one table row (kImportanceSize inclusive entries at `first`): the interval
// holding u, where u lies in it, and the interval's probability. `marginal` is set when u lies
// within round-off of an interval's end (the GPU's float search may pick the neighbour).
struct CdfPick {
    uint32_t index = 0;
    double within = 0.0;
    double probability = 0.0;
};

CdfPick pickInterval(const std::vector<float>& cdf, size_t first, double u, bool& marginal) {
    CdfPick pick;
    double lo = 0.0;
    for (uint32_t i = 0; i < gpu::kImportanceSize; ++i) {
        const double hi = double(cdf[first + i]);
        if (std::abs(u - hi) < kMarginalGap) marginal = true;
        if (hi > u) {
            pick.index = i;
            pick.probability = hi - lo;
            pick.within = (u - lo) / pick.probability;
            return pick;
        }
        lo = hi;
    }
    ADD_FAILURE() << "the CDF row at " << first << " ends below 1";
    return pick;
}

double computeSpotFalloffCos(double cosAngle, double cosInner, double cosOuter) {
    if (cosInner <= cosOuter) return cosAngle >= cosOuter ? 1.0 : 0.0;
    const double s = std::clamp((cosAngle - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
    return s * s * (3.0 - 2.0 * s);
}

// The light G-buffer of one view, read back (row 0 at the bottom: texel (x, y) at y * res + x).
struct LightTexels {
    std::vector<glm::vec4> position, normal, diffuse, specular, transmissive;
};

LightTexels readLightTexels(const GBuffer& gbuffer, int layer) {
    return {gbuffer.getChannel("position").readRgba(layer),
            gbuffer.getChannel("normal").readRgba(layer),
            gbuffer.getChannel("diffuse").readRgba(layer),
            gbuffer.getChannel("specular").readRgba(layer),
            gbuffer.getChannel("transmissive").readRgba(layer)};
}

// True when one of scatterPhoton's decisions for this photon is within round-off of its
// threshold.
bool isScatterMarginal(const glm::dvec3& dir, const glm::dvec3& n, const glm::dvec3& diffuse,
                       const glm::dvec4& specular, const glm::dvec4& transmissive, bool entering,
                       const std::array<double, 3>& numbers, double selectScale) {
    const auto [u, u1, u2] = numbers;
    const double cosIn = std::clamp(-glm::dot(dir, n), 0.0, 1.0);
    const double pd =
        computeOracleMean(computeOracleDiffuseAlbedo(diffuse, specular, cosIn)) * selectScale;
    const double ps =
        computeOracleMean(computeOracleSpecularAlbedo(diffuse, specular, cosIn)) * selectScale;
    const double pt = computeOracleMean(glm::dvec3(transmissive)) * selectScale;
    for (double threshold : {pd, pd + ps, pd + ps + pt}) {
        if (std::abs(u - threshold) < kMarginalGap) return true;
    }
    if (u >= pd && u < pd + ps) {
        const double e = specular.w;
        const glm::dvec3 lobe =
            makeOracleDirection(glm::reflect(dir, n), std::pow(u1, 1.0 / (e + 1.0)), u2);
        return std::abs(glm::dot(lobe, n)) < kMarginalGap; // the lobe grazes the surface
    }
    if (u >= pd + ps && u < pd + ps + pt) {
        const double eta = entering ? 1.0 / transmissive.w : transmissive.w;
        const double cosI = std::clamp(-glm::dot(dir, n), 0.0, 1.0);
        return std::abs(u1 - computeOracleFresnel(cosI, eta)) < kMarginalGap;
    }
    return false;
}

Reference computeReference(const FrameRunner& runner, const Scene& scene, uint32_t seed,
                           uint32_t rngMode, uint32_t firstBounce = gpu::kFirstBounceRoulette) {
    Reference ref;
    const std::vector<LightCamera>& cameras = runner.getPasses().scene.getLightCameras();
    const int res = runner.getPasses().scene.getLightResolution();
    const size_t views = cameras.size();
    const std::vector<float> cdf = runner.getPasses().importance.getCdf().read<float>(
        views * (gpu::kImportanceTexels + gpu::kImportanceSize));
    for (const EmissionGrid& grid : runner.getPasses().emit.getGrids()) {
        const LightCamera& cam = cameras[grid.viewIndex];
        const Light& light = scene.lights[cam.lightIndex];
        const LightTexels texels = readLightTexels(runner.getPasses().lightViews.getGBuffer(),
                                                   static_cast<int>(grid.viewIndex));
        const glm::dvec2 gridSize(grid.width, grid.height);
        for (uint32_t index = 0; index < grid.getCount(); ++index) {
            const uint32_t photon = grid.firstPhoton + index;
            // The cell's centre through the view's tables: row by the marginal CDF, column by the
            // row's conditional CDF.
            const glm::uvec2 cell(index % grid.width, index / grid.width);
            const glm::dvec2 jitter = computeOracleGridShift(grid.viewIndex, seed);
            const glm::dvec2 u = (glm::dvec2(cell) + jitter) / gridSize;
            bool marginal = false;
            const CdfPick row = pickInterval(
                cdf, views * gpu::kImportanceTexels + grid.viewIndex * gpu::kImportanceSize, u.y,
                marginal);
            const CdfPick column = pickInterval(
                cdf, grid.viewIndex * gpu::kImportanceTexels + row.index * gpu::kImportanceSize,
                u.x, marginal);
            const double pdf = row.probability * column.probability * gpu::kImportanceTexels;
            const glm::dvec2 uv =
                (glm::dvec2(column.index, row.index) + glm::dvec2(column.within, row.within)) /
                double(gpu::kImportanceSize);
            // The texel under it; within round-off of a texel's edge the GPU may take the other.
            const glm::dvec2 texelAt = uv * double(res);
            const glm::dvec2 edge = glm::abs(texelAt - glm::round(texelAt));
            if (std::min(edge.x, edge.y) < kMarginalGap * res) marginal = true;
            if (marginal) ref.marginal.insert(photon);
            const glm::ivec2 texel = glm::min(glm::ivec2(texelAt), glm::ivec2(res - 1));
            const size_t at = static_cast<size_t>(texel.y * res + texel.x);
            const glm::vec4 position = texels.position[at];
            if (position.w < 0.5f) continue; // the light sees nothing there

            // Power: the view's power density at uv over (photons x pdf), in double.
            const glm::dvec3 p(position);
            const double share = 1.0 / (double(grid.getCount()) * pdf);
            glm::dvec3 power;
            glm::dvec3 dir;
            double travelled = 0.0;
            double solidAngle = 0.0;
            double falloffTolerance = 0.0; // relative power error the spot falloff may add
            if (cam.isOrthographic) {
                const double widthM = double(cam.texelSizeM) * res;
                power = glm::dvec3(light.irradiance) * (widthM * widthM * share);
                dir = glm::dvec3(cam.axis);
                travelled = 0.0; // the sun's photons travel from their first hit
            } else {
                const double t = 0.5 * double(cam.texelPerDepth) * res; // tan(fov / 2)
                const glm::dvec2 q = (uv * 2.0 - 1.0) * t;
                const double r2 = 1.0 + glm::dot(q, q);
                solidAngle = 4.0 * t * t / (r2 * std::sqrt(r2)) * share;
                travelled = glm::length(p - glm::dvec3(cam.origin));
                dir = (p - glm::dvec3(cam.origin)) / travelled;
                double falloff = 1.0;
                if (light.type == LightType::Spot) {
                    // The cone's cosines as the light buffer holds them (float).
                    const float cosInner = std::cos(glm::radians(light.innerDeg));
                    const float cosOuter = std::cos(glm::radians(light.outerDeg));
                    const glm::dvec3 axis(glm::normalize(light.direction));
                    const double cosAngle = glm::dot(dir, axis);
                    falloff = computeSpotFalloffCos(cosAngle, double(cosInner), double(cosOuter));
                    // Near the outer edge S = s^2 (3 - 2 s) is tiny and steep: the float cosine's
                    // round-off becomes a large relative error, 6 s (1 - s) / S per unit of s.
                    const double span = double(cosInner) - double(cosOuter);
                    const double sv = std::clamp((cosAngle - double(cosOuter)) / span, 0.0, 1.0);
                    if (falloff > 0.0 && span > 0.0) {
                        falloffTolerance = kCosineRoundOff / span * 6.0 * sv * (1.0 - sv) / falloff;
                    }
                    if (std::abs(cosAngle - double(cosOuter)) < kMarginalGap) {
                        ref.marginal.insert(photon); // on the cone's edge: zero or not
                    }
                }
                power = glm::dvec3(light.intensity) * (falloff * std::abs(solidAngle));
            }
            if (power == glm::dvec3(0.0)) continue;
            ref.emittedPowerW += power;

            // The surface as the light G-buffer holds it (inputs, read back as floats).
            const glm::dvec3 n(glm::vec3(texels.normal[at]));
            const glm::dvec3 diffuse(glm::vec3(texels.diffuse[at]));
            const glm::dvec4 specular(texels.specular[at]);
            const glm::dvec4 transmissive(texels.transmissive[at]);
            const bool entering = texels.normal[at].w > 0.0f;
            glm::dvec3 bounceDir = glm::normalize(glm::dvec3(dir));
            glm::dvec3 bouncePower = power;
            const std::array<double, 3> numbers =
                drawOracleNumbers(photon, cell, grid.viewIndex, seed, rngMode);
            const double selectScale =
                computeOracleSelectScale(diffuse, specular, transmissive, firstBounce);
            if (isScatterMarginal(bounceDir, n, diffuse, specular, transmissive, entering, numbers,
                                  selectScale)) {
                ref.marginal.insert(photon);
            }
            const uint32_t event = scatterOracle(bounceDir, bouncePower, n, diffuse, specular,
                                                 transmissive, entering, numbers, selectScale);
            ++ref.eventCounts[event];
            if (event == gpu::kScatterAbsorbed) continue;
            ExpectedPhoton e;
            e.event = event;
            e.photon.positionDistance =
                glm::vec4(glm::vec3(position), static_cast<float>(travelled));
            e.photon.directionDensity =
                glm::vec4(glm::vec3(bounceDir), float(computeOraclePathDensity(event, specular.w)));
            e.photon.power = glm::vec4(glm::vec3(bouncePower), std::bit_cast<float>(photon));
            e.powerTolerance += falloffTolerance;
            if (event == gpu::kScatterSpecular) {
                // The Phong weight is proportional to cos(out): near grazing it magnifies the
                // direction's round-off.
                e.powerTolerance += kDirectionRoundOff / glm::dot(bounceDir, n);
            }
            ref.photons.push_back(e);
        }
    }
    return ref;
}

// ---------------------------------------------------------------------------------------------
// Comparison.

double computeRelativeError(const glm::dvec3& actual, const glm::dvec3& expected, double minScale) {
    return glm::length(actual - expected) / std::max(glm::length(expected), minScale);
}

// Why a GPU photon differs from the oracle's, or "" when it agrees.
std::string describeMismatch(const gpu::BouncePhoton& gpu, const ExpectedPhoton& cpu) {
    constexpr double kPositionScaleM = 1.0; // positions near the origin: compare to a metre
    const gpu::BouncePhoton& e = cpu.photon;
    const double positionError = computeRelativeError(
        glm::dvec3(gpu.positionDistance), glm::dvec3(e.positionDistance), kPositionScaleM);
    // Sun photons travel from their first hit (0): compare travel to a metre as well.
    const double travelError = std::abs(double(gpu.positionDistance.w - e.positionDistance.w)) /
                               std::max(double(e.positionDistance.w), kPositionScaleM);
    const double directionError =
        computeRelativeError(glm::dvec3(gpu.directionDensity), glm::dvec3(e.directionDensity), 1.0);
    const double densityError = std::abs(double(gpu.directionDensity.w - e.directionDensity.w)) /
                                double(e.directionDensity.w);
    const double powerError = computeRelativeError(glm::dvec3(gpu.power), glm::dvec3(e.power), 0.0);
    if (positionError > kRelativeTolerance) return strCat("position off by ", positionError);
    if (travelError > kRelativeTolerance) return strCat("travel distance off by ", travelError);
    if (directionError > kRelativeTolerance) return strCat("direction off by ", directionError);
    if (densityError > kRelativeTolerance) return strCat("density (event) off by ", densityError);
    if (powerError > cpu.powerTolerance) {
        return strCat("power off by ", powerError, " (allowed ", cpu.powerTolerance, ", event ",
                      cpu.event, ")");
    }
    return "";
}

struct Comparison {
    uint32_t gpuCount = 0;
    uint32_t tolerated = 0; // differing photons with a marginal decision
    double maxPowerError = 0.0;
};

// Compares the bounce buffer with the oracle; fails the test on any unexplained difference.
Comparison compareBounceBuffer(const FrameRunner& runner, const Reference& ref,
                               const std::string& what) {
    Comparison result;
    const PhotonCounts counts = readPhotonCounts(runner);
    result.gpuCount = counts.bounced;
    EXPECT_EQ(counts.emitted, countPhotons(runner.getPasses().emit.getGrids())) << what;
    const gl::Buffer& bounce = runner.getPasses().photons.getBounce();
    const std::vector<gpu::BouncePhoton> gpuPhotons =
        counts.bounced ? bounce.read<gpu::BouncePhoton>(counts.bounced)
                       : std::vector<gpu::BouncePhoton>{};

    std::map<uint32_t, const ExpectedPhoton*> expected;
    for (const ExpectedPhoton& e : ref.photons) {
        expected[std::bit_cast<uint32_t>(e.photon.power.w)] = &e;
    }
    auto isMarginal = [&](uint32_t photon) { return ref.marginal.contains(photon); };
    uint32_t failures = 0;
    constexpr uint32_t kMaxReported = 10;
    auto report = [&](uint32_t photon, const std::string& why) {
        if (isMarginal(photon)) {
            ++result.tolerated;
            return;
        }
        if (++failures <= kMaxReported) {
            ADD_FAILURE() << what << ": photon " << photon << ": " << why;
        }
    };
    // Transform feedback keeps primitive order within a draw and draws go in grid order, so the
    // photon indices must rise strictly, as the oracle's do.
    uint32_t previous = 0;
    for (size_t i = 0; i < gpuPhotons.size(); ++i) {
        const uint32_t photon = std::bit_cast<uint32_t>(gpuPhotons[i].power.w);
        if (i > 0) {
            EXPECT_GT(photon, previous) << what << ": bounce buffer out of emission order";
        }
        previous = photon;
        auto it = expected.find(photon);
        if (it == expected.end()) {
            report(photon, "written by the GPU, absorbed or skipped by the oracle");
            continue;
        }
        const ExpectedPhoton& e = *it->second;
        expected.erase(it);
        const std::string why = describeMismatch(gpuPhotons[i], e);
        if (!why.empty()) {
            report(photon, why);
            continue;
        }
        const double powerError =
            computeRelativeError(glm::dvec3(gpuPhotons[i].power), glm::dvec3(e.photon.power), 0.0);
        result.maxPowerError = std::max(result.maxPowerError, powerError);
    }
    for (auto it = expected.begin(); it != expected.end(); ++it) {
        report(it->first, "kept by the oracle, missing from the bounce buffer");
    }
    EXPECT_EQ(failures, 0u) << what;
    // Exactly equal unless a marginal decision went the other way (each flip moves the count
    // by at most one).
    EXPECT_LE(std::abs(int64_t(result.gpuCount) - int64_t(ref.photons.size())),
              int64_t(result.tolerated))
        << what << ": GPU wrote " << result.gpuCount << ", oracle kept " << ref.photons.size();
    EXPECT_LE(double(result.tolerated), kMaxFlipFraction * double(std::max(counts.emitted, 1u)))
        << what;
    return result;
}

class PhotonEmitTest : public GlTest {
  protected:
    // Renders `scene` at every budget and compares the bounce buffer with the oracle.
    // Returns the oracle's events over the budgets (kScatter*, absorbed included).
    std::array<uint32_t, 5> checkBudgets(const Scene& scene, const char* name, uint32_t rngMode,
                                         uint32_t firstBounce = gpu::kFirstBounceRoulette) {
        std::array<uint32_t, 5> events{};
        for (uint32_t photons : kBudgets) {
            Settings settings =
                withSettings(makeSettings(photons),
                             {{"rng_generator", std::string(kRngGeneratorChoices[rngMode])},
                              {"first_bounce", std::string(kFirstBounceChoices[firstBounce])}});
            FrameRunner runner(scene, settings, gl::TimingMethod::CpuFinish);
            runner.renderFrame();
            const Reference ref = computeReference(runner, scene, kSeed, rngMode, firstBounce);
            const std::string what = strCat(name, ", ", photons, " photons");
            const Comparison c = compareBounceBuffer(runner, ref, what);
            std::printf("[ emit     ] %s: emitted %u, bounced %u (oracle %zu), tolerated flips "
                        "%u, max power error %.2e\n",
                        what.c_str(), countPhotons(runner.getPasses().emit.getGrids()), c.gpuCount,
                        ref.photons.size(), c.tolerated, c.maxPowerError);
            for (size_t i = 0; i < events.size(); ++i)
                events[i] += ref.eventCounts[i];
        }
        // The comparison means something only if every branch of scatterPhoton was taken (the
        // weighted first bounce absorbs only where a Phong lobe dips below the surface).
        if (firstBounce == gpu::kFirstBounceRoulette) {
            EXPECT_GT(events[gpu::kScatterAbsorbed], 0u) << name;
        }
        EXPECT_GT(events[gpu::kScatterDiffuse], 0u) << name;
        EXPECT_GT(events[gpu::kScatterSpecular], 0u) << name;
        EXPECT_GT(events[gpu::kScatterReflect], 0u) << name;
        EXPECT_GT(events[gpu::kScatterRefract], 0u) << name;
        return events;
    }
};

TEST_F(PhotonEmitTest, SpotLightMatchesCpuReference) {
    checkBudgets(makeRoomScene(makeSpot()), "spot", gpu::kRngPcg);
}

TEST_F(PhotonEmitTest, PointLightSixViewsMatchCpuReference) {
    // The thesis's LCG here, PCG elsewhere: both random modes go through the same comparison.
    checkBudgets(makeRoomScene(makePoint({0.3f, 1.2f, 0.4f}, {5.0f, 6.0f, 7.0f})), "point",
                 gpu::kRngLcg);
}

TEST_F(PhotonEmitTest, SunMatchesCpuReference) {
    // The default generator, sobol: its scrambled Z-order points through the same comparison.
    checkBudgets(makeRoomScene(makeSun()), "sun", gpu::kRngSobol);
}

TEST_F(PhotonEmitTest, WeightedFirstBounceMatchesCpuReference) {
    // first_bounce weighted: the same oracle with the lobes' probabilities over the albedo, and
    // the power times the lobe's reflectance over that share. Against the roulette of the same
    // photons it keeps nearly all of them: the room's surfaces reflect about two thirds of what
    // meets them (measured: roulette absorbs 0.353 of the spot's photons, weighted none; only a
    // Phong lobe that dips below the surface could).
    const Scene scene = makeRoomScene(makeSpot());
    const std::array<uint32_t, 5> roulette = checkBudgets(scene, "spot, roulette", gpu::kRngPcg);
    const std::array<uint32_t, 5> weighted =
        checkBudgets(scene, "spot, weighted", gpu::kRngPcg, gpu::kFirstBounceWeighted);
    auto absorbedShare = [](const std::array<uint32_t, 5>& events) {
        uint32_t all = 0;
        for (uint32_t e : events)
            all += e;
        return double(events[gpu::kScatterAbsorbed]) / double(std::max(all, 1u));
    };
    std::printf("[ emit     ] absorbed at the first bounce: roulette %.4f, weighted %.4f\n",
                absorbedShare(roulette), absorbedShare(weighted));
    EXPECT_GT(absorbedShare(roulette), 0.2);
    EXPECT_LT(absorbedShare(weighted), 0.01);
}

TEST_F(PhotonEmitTest, SunTravelStartsAtTheFirstHit) {
    // The sun's photons land at many depths along its direction (floor and walls); their travel
    // distance is 0 at the first hit wherever that is (the thesis, 5.2.1.a), so one-bounce splat
    // radii do not depend on a plane fitted to the scene's bounds.
    const Scene scene = makeRoomScene(makeSun());
    FrameRunner runner(scene, makeSettings(12345), gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    const uint32_t bounced = readPhotonCounts(runner).bounced;
    ASSERT_GT(bounced, 1000u);
    const glm::vec3 axis = glm::normalize(scene.lights[0].direction);
    float nearest = FLT_MAX;
    float farthest = -FLT_MAX;
    for (const gpu::BouncePhoton& p :
         runner.getPasses().photons.getBounce().read<gpu::BouncePhoton>(bounced)) {
        EXPECT_EQ(p.positionDistance.w, 0.0f);
        const float depth = glm::dot(glm::vec3(p.positionDistance), axis);
        nearest = std::min(nearest, depth);
        farthest = std::max(farthest, depth);
    }
    EXPECT_GT(farthest - nearest, 1.0f) << "the first hits should lie at many depths";
}

// Sum of the powers the GPU wrote for a point light in a closed white box (reflectance 1 keeps
// every photon at its emitted power).
glm::dvec3 sumClosedBoxPower(float intensity, uint32_t photons, float importance, uint32_t seed,
                             Reference* reference) {
    const Scene scene = makeClosedBoxScene(makePoint({0.2f, -0.1f, 0.3f}, glm::vec3(intensity)));
    Settings settings =
        withSettings(makeSettings(photons), {{"importance", importance}, {"seed", seed}});
    FrameRunner runner(scene, settings, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    const uint32_t emitted = countPhotons(runner.getPasses().emit.getGrids());
    if (reference) {
        *reference = computeReference(runner, scene, seed, gpu::kRngSobol); // the default
        EXPECT_EQ(reference->photons.size(), emitted) << "every texel sees the box";
        const Comparison c = compareBounceBuffer(runner, *reference, "closed box");
        EXPECT_EQ(c.gpuCount, emitted);
    }
    const uint32_t bounced = readPhotonCounts(runner).bounced;
    EXPECT_EQ(bounced, emitted);
    glm::dvec3 sum(0.0);
    for (const gpu::BouncePhoton& p :
         runner.getPasses().photons.getBounce().read<gpu::BouncePhoton>(bounced)) {
        sum += glm::dvec3(p.power);
    }
    return sum;
}

TEST_F(PhotonEmitTest, PointLightInClosedBoxEmitsFourPiIntensity) {
    constexpr float kIntensity = 3.0f;  // W/sr
    constexpr uint32_t kPhotons = 6000; // 1000 per cube face
    const double expectedW = 4.0 * glm::pi<double>() * double(kIntensity);
    // Without importance every map texel's probability follows its solid angle: each photon
    // carries the power of the part of the sphere it stands for, a midpoint rule over the map
    // texels: with 1000 photons a face for its 16384 map texels each photon stands for about
    // sixteen of them, and the sum is a sparse quadrature of 4 pi I. Measured 0.99992 (oracle
    // and GPU alike); 5e-3 is far below a missing face (1/6) or a wrong factor.
    constexpr double kQuadratureTolerance = 5e-3;
    Reference ref;
    const glm::dvec3 gpuSum = sumClosedBoxPower(kIntensity, kPhotons, 0.0f, kSeed, &ref);
    for (int ch = 0; ch < 3; ++ch) {
        EXPECT_NEAR(ref.emittedPowerW[ch], expectedW, kQuadratureTolerance * expectedW);
        EXPECT_NEAR(gpuSum[ch], expectedW, kQuadratureTolerance * expectedW);
    }
    std::printf("[ emit     ] closed box: oracle %.7f W, GPU %.7f W, 4 pi I = %.7f W\n",
                ref.emittedPowerW.x, gpuSum.x, expectedW);
}

TEST_F(PhotonEmitTest, ImportanceKeepsEmittedPowerInExpectation) {
    // With the importance map on (the default share), photons crowd where the camera looks and
    // each carries power / pdf: one frame's total is an estimate of 4 pi I, right on average.
    constexpr float kIntensity = 3.0f;
    // 10,000 photons a face (a 100 x 100 grid over the 128 x 128 map).
    constexpr uint32_t kPhotons = 60000;
    constexpr uint32_t kSeeds = 8;
    const double expectedW = 4.0 * glm::pi<double>() * double(kIntensity);
    double sum = 0.0;
    for (uint32_t seed = 1; seed <= kSeeds; ++seed) {
        const double frameW = sumClosedBoxPower(kIntensity, kPhotons, 0.75f, seed, nullptr).x;
        std::printf("[ emit     ] importance on, seed %u: %.5f of 4 pi I\n", seed,
                    frameW / expectedW);
        sum += frameW;
    }
    // The bound: 0.5%. Measured per frame 0.996-1.008, 1.0018 over the 8 seeds (each
    // frame's grid sits at another offset in its cells, so frames average); a pdf off by a
    // constant, a missing uniform floor or power not divided by the pdf moves it by far more.
    EXPECT_NEAR(sum / kSeeds / expectedW, 1.0, 5e-3);
}

// Per light view and map texel, the probability the frame's tables give it (marginal times
// conditional; each view's sum to 1).
std::vector<double> readTexelProbabilities(const FrameRunner& runner) {
    const size_t views = runner.getPasses().scene.getLightCameras().size();
    const std::vector<float> cdf = runner.getPasses().importance.getCdf().read<float>(
        views * (gpu::kImportanceTexels + gpu::kImportanceSize));
    std::vector<double> p(views * gpu::kImportanceTexels);
    const auto step = [&cdf](size_t at, bool first) {
        return double(cdf[at]) - (first ? 0.0 : double(cdf[at - 1]));
    };
    for (size_t v = 0; v < views; ++v) {
        const size_t marginal = views * gpu::kImportanceTexels + v * gpu::kImportanceSize;
        for (size_t row = 0; row < gpu::kImportanceSize; ++row) {
            const double pRow = step(marginal + row, row == 0);
            const size_t first = v * gpu::kImportanceTexels + row * gpu::kImportanceSize;
            for (size_t c = 0; c < gpu::kImportanceSize; ++c) {
                p[first + c] = pRow * step(first + c, c == 0);
            }
        }
    }
    return p;
}

// Half the L1 distance of two sets of maps, averaged over the views (0: the same, 1: disjoint).
double computeMapDistance(const std::vector<double>& a, const std::vector<double>& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        sum += std::abs(a[i] - b[i]);
    return 0.5 * sum / double(a.size() / gpu::kImportanceTexels);
}

// Settings of the importance history tests: a 64 x 64 view of the closed box, only the aimed
// share (so the maps are the gathered importance alone), `samples` gather samples.
Settings makeHistorySettings(int samples, int frames, uint32_t seed) {
    Settings settings = withSettings(makeSettings(6000), {{"width", 64},
                                                          {"height", 64},
                                                          {"importance", 1.0},
                                                          {"importance_samples", samples},
                                                          {"importance_frames", frames},
                                                          {"seed", seed}});
    return settings;
}

// The maps after `frames` frames drawn with seeds seed, seed + 1, ... (a new seed alone keeps
// the history), each frame's samples blended in as importance_frames says.
std::vector<double> renderMaps(const Scene& scene, int samples, int importanceFrames, uint32_t seed,
                               int frames) {
    FrameRunner runner(scene, makeHistorySettings(samples, importanceFrames, seed),
                       gl::TimingMethod::CpuFinish);
    for (int i = 0; i < frames; ++i) {
        runner.setSettings(makeHistorySettings(samples, importanceFrames, seed + uint32_t(i)));
        runner.renderFrame();
    }
    return readTexelProbabilities(runner);
}

TEST_F(PhotonEmitTest, ImportanceMapsAverageOverFrames) {
    // The maps hold the gathered samples of several frames (importance_frames): after a few
    // frames at a quarter of the samples each, they are closer to a well-sampled map than one
    // frame's maps from all the samples, and far closer than one frame's quarter alone.
    const Scene scene = makeClosedBoxScene(makePoint({0.2f, -0.1f, 0.3f}, glm::vec3(3.0f)));
    constexpr int kSamples = 512;
    // The well-sampled maps: every pixel of the 64 x 64 image, its own seeds.
    const std::vector<double> truth = renderMaps(scene, 64 * 64, 1, 1000u, 1);
    double single = 0.0;
    double quarter = 0.0;
    double averaged = 0.0;
    constexpr uint32_t kSeeds = 3;
    for (uint32_t seed = 1; seed <= kSeeds; ++seed) {
        single += computeMapDistance(renderMaps(scene, kSamples, 1, 10u * seed, 8), truth);
        quarter += computeMapDistance(renderMaps(scene, kSamples / 4, 1, 10u * seed, 8), truth);
        averaged += computeMapDistance(renderMaps(scene, kSamples, 4, 10u * seed, 8), truth);
    }
    std::printf("[ emit     ] maps' distance to %d samples: %d samples %.4f, %d samples %.4f, "
                "%d a frame averaged over frames %.4f\n",
                64 * 64, kSamples, single / kSeeds, kSamples / 4, quarter / kSeeds, kSamples / 4,
                averaged / kSeeds);
    // An exponential average of weight 1/4 over frames of N/4 samples holds about 1.75 N: its
    // noise is that of more samples than one frame of N. Measured 0.516 against 0.612 (N) and
    // 0.755 (N/4; the distances include the reference maps' own noise, the same for all three).
    // A history ignored leaves the quarter's distance, one never blended in the first frame's.
    EXPECT_LT(averaged, 0.95 * single);
    EXPECT_LT(averaged, 0.8 * quarter);
}

// A table in the sun, wider than the floor beneath it, and a sunlit ground beside: the camera,
// under the table, sees the floor, which no light reaches; one bounce from it meets the table's
// underside (no light there either) or nothing; only a second bounce, down from the underside,
// meets a surface the sun lights: the ground beside.
Scene makeShadedFloorScene() {
    Scene scene;
    scene.sourcePath = "photon emit test shaded floor";
    scene.materials.push_back(makeMaterial("grey", glm::vec3(0.5f)));
    Mesh mesh;
    mesh.name = "floor, table and ground";
    addBox(mesh, {-2.0f, -0.2f, -2.0f}, {2.0f, 0.0f, 2.0f}); // the floor
    addBox(mesh, {-2.2f, 2.0f, -2.2f}, {2.2f, 3.0f, 2.2f});  // the table top, 1 m thick
    addBox(mesh, {2.5f, -0.2f, -2.0f}, {6.5f, 0.0f, 2.0f});  // the ground beside
    scene.meshes.push_back(std::move(mesh));
    scene.instances.push_back({0, glm::mat4(1.0f)});
    Light sun;
    sun.type = LightType::Sun;
    sun.direction = {0.0f, -1.0f, 0.0f};
    sun.irradiance = glm::vec3(100.0f);
    scene.lights.push_back(sun);
    scene.camera.position = {0.0f, 1.0f, 0.5f};
    scene.camera.target = {0.0f, 0.0f, -1.5f};
    scene.camera.fovYDeg = 40.0f;
    return scene;
}

TEST_F(PhotonEmitTest, UnlitViewAimsPhotonsTwoBouncesBack) {
    // What lights a point no light reaches arrives after two bounces or more, and the gather
    // follows a second bounce from such a point: the sun's map (the aimed share alone) gathers
    // importance on the ground beside the table. From the floor's first bounce alone it would
    // gather none and stay uniform (the floor's share takes everything).
    const Scene scene = makeShadedFloorScene();
    Settings settings =
        withSettings(makeSettings(4000), {{"width", 64}, {"height", 64}, {"importance", 1.0}});
    // The sun's visibility by ray, exact: a shadow map's bias would light the table's underside.
    settings.setEnum("shadows", "ray", "test");
    FrameRunner runner(scene, settings, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    const std::vector<double> p = readTexelProbabilities(runner);
    // View 0 is the sun's scene-wide view, the one that emits, looking straight down: a texel's
    // centre taken back through it gives the x of the ground it aims at.
    const glm::mat4 worldFromClip =
        glm::inverse(runner.getPasses().scene.getLightCameras()[0].getClipFromWorld());
    size_t nonzero = 0;
    double largest = 0.0;
    double beside = 0.0; // the mass on texels beyond the table's edge (x 2.2), where the ground is
    for (uint32_t row = 0; row < gpu::kImportanceSize; ++row) {
        for (uint32_t c = 0; c < gpu::kImportanceSize; ++c) {
            const double pTexel = p[row * gpu::kImportanceSize + c];
            const glm::vec2 ndc =
                (glm::vec2(c, row) + 0.5f) / float(gpu::kImportanceSize) * 2.0f - 1.0f;
            const glm::vec4 world = worldFromClip * glm::vec4(ndc, 0.0f, 1.0f);
            nonzero += pTexel > 0.0 ? 1 : 0;
            largest = std::max(largest, pTexel);
            beside += world.x / world.w > 2.2f ? pTexel : 0.0;
        }
    }
    std::printf("[ emit     ] shaded floor: %zu of %u texels aimed at, the largest %.1fx uniform, "
                "%.3f of the mass beside the table\n",
                nonzero, gpu::kImportanceTexels, largest * gpu::kImportanceTexels, beside);
    // A uniform map has every texel at 1x and 0.49 of its mass beside the table (the view spans
    // x -2.2 to 6.5). Measured: the maps' tents spread the ground's hits over 3,658 texels, the
    // largest 56x uniform, 0.996 of the mass beside the table (the rest the tents' spill).
    EXPECT_LT(nonzero, gpu::kImportanceTexels / 2);
    EXPECT_GT(largest * gpu::kImportanceTexels, 4.0);
    EXPECT_GT(beside, 0.9);
}

TEST_F(PhotonEmitTest, ImportanceHistoryStartsAnewWhenASettingChanges) {
    // A new seed alone keeps the maps' history; any other setting starts the maps anew, so
    // they are those of a fresh runner (bit for bit: the same samples, no history).
    const Scene scene = makeClosedBoxScene(makePoint({0.2f, -0.1f, 0.3f}, glm::vec3(3.0f)));
    FrameRunner runner(scene, makeHistorySettings(512, 4, 1u), gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    runner.setSettings(makeHistorySettings(512, 4, 2u));
    runner.renderFrame();
    const std::vector<double> blended = readTexelProbabilities(runner);
    const std::vector<double> fresh = renderMaps(scene, 512, 4, 2u, 1);
    EXPECT_GT(computeMapDistance(blended, fresh), 0.0) << "a new seed alone keeps the history";
    runner.setSettings(makeHistorySettings(384, 4, 2u));
    runner.renderFrame();
    EXPECT_EQ(computeMapDistance(readTexelProbabilities(runner), renderMaps(scene, 384, 4, 2u, 1)),
              0.0)
        << "another setting starts the maps anew";
}

} // namespace
} // namespace ispm::test
