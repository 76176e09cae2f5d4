// The first bounce's Sobol numbers (shared/photon_scatter.h): a square patch of emission-grid
// cells takes stratified numbers in every dimension, whatever the scrambling seed; each number is
// uniform over seeds. The emission test (tests/gl/photon_emit_test.cpp) checks the exact values
// against an oracle; this checks the property the photons rely on.
#include <shared/photon_scatter.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace ispm {
namespace {

// The numbers of the 2^k x 2^k patch of cells whose corner is `corner` (a multiple of 2^k).
std::vector<glm::vec3> drawPatch(glm::uvec2 corner, uint32_t k, uint32_t seed) {
    std::vector<glm::vec3> numbers;
    const uint32_t side = 1u << k;
    for (uint32_t y = 0; y < side; ++y) {
        for (uint32_t x = 0; x < side; ++x) {
            const uint32_t index = gpu::computeZOrder(corner + glm::uvec2(x, y));
            numbers.push_back(gpu::computeSobolNumbers(index, seed));
        }
    }
    return numbers;
}

TEST(PhotonNumbers, SquarePatchIsStratifiedInEachDimension) {
    // A patch of n = 4^k cells: in every dimension, exactly one number in each of the n intervals
    // [i/n, (i+1)/n). Independent random numbers leave about n/e intervals empty.
    for (uint32_t k : {1u, 2u, 3u, 5u}) {
        const uint32_t side = 1u << k;
        const uint32_t n = side * side;
        for (glm::uvec2 corner :
             {glm::uvec2(0, 0), glm::uvec2(3, 5) * side, glm::uvec2(41, 17) * side}) {
            for (uint32_t seed : {1u, 0x9e3779b9u, 12345u}) {
                const std::vector<glm::vec3> numbers = drawPatch(corner, k, seed);
                for (int d = 0; d < 3; ++d) {
                    std::vector<int> hits(n, 0);
                    for (const glm::vec3& u : numbers) {
                        ASSERT_GE(u[d], 0.0f);
                        ASSERT_LT(u[d], 1.0f);
                        ++hits[static_cast<size_t>(u[d] * float(n))];
                    }
                    for (uint32_t i = 0; i < n; ++i) {
                        EXPECT_EQ(hits[i], 1)
                            << "k " << k << ", corner " << corner.x << "," << corner.y << ", seed "
                            << seed << ", dimension " << d << ", interval " << i;
                    }
                }
            }
        }
    }
}

TEST(PhotonNumbers, DirectionPairIsStratifiedInTwoDimensions) {
    // The lobe's two numbers over a 16 x 16 patch (256 points): one in each cell of the 16 x 16
    // grid of the unit square. Independent numbers leave about 94 cells empty.
    const uint32_t k = 4;
    for (uint32_t seed : {7u, 99u, 0xdeadbeefu}) {
        const std::vector<glm::vec3> numbers = drawPatch(glm::uvec2(32, 16), k, seed);
        std::array<int, 256> hits{};
        for (const glm::vec3& u : numbers)
            ++hits[static_cast<size_t>(u.y * 16.0f) * 16 + static_cast<size_t>(u.z * 16.0f)];
        int empty = 0;
        for (int h : hits)
            empty += h == 0 ? 1 : 0;
        EXPECT_EQ(empty, 0) << "seed " << seed;
    }
}

TEST(PhotonNumbers, RouletteAndLobeAreIndependent) {
    // Within a 16 x 16 patch, the photons whose roulette number is below 1/2 (survivors at
    // albedo 1/2) take lobe numbers u1 on both sides of 1/2: 64 of 128 expected, binomial
    // standard deviation 5.7; 40..88 is four of them. Sobol points of one index share their
    // first bit in every dimension, which would give 0 or 128.
    for (uint32_t seed : {3u, 1000u, 0xabcdef01u, 77777u}) {
        const std::vector<glm::vec3> numbers = drawPatch(glm::uvec2(16, 48), 4, seed);
        int survivors = 0;
        int low = 0;
        for (const glm::vec3& u : numbers) {
            if (u.x >= 0.5f) continue;
            ++survivors;
            low += u.y < 0.5f ? 1 : 0;
        }
        EXPECT_EQ(survivors, 128) << "seed " << seed; // stratified: exactly half
        EXPECT_GE(low, 40) << "seed " << seed;
        EXPECT_LE(low, 88) << "seed " << seed;
    }
}

TEST(PhotonNumbers, EachNumberIsUniformOverSeeds) {
    // One cell's numbers over 20,000 seeds: mean 1/2 and variance 1/12 in each dimension.
    // Standard errors: mean 0.002, variance 0.0005; 5 of them allowed.
    constexpr int kSeeds = 20000;
    for (glm::uvec2 cell : {glm::uvec2(0, 0), glm::uvec2(5, 9)}) {
        glm::dvec3 sum(0.0);
        glm::dvec3 sumSq(0.0);
        for (int s = 0; s < kSeeds; ++s) {
            const glm::dvec3 u(
                gpu::computeSobolNumbers(gpu::computeZOrder(cell), gpu::hashPcg(uint32_t(s))));
            sum += u;
            sumSq += u * u;
        }
        const glm::dvec3 mean = sum / double(kSeeds);
        const glm::dvec3 variance = sumSq / double(kSeeds) - mean * mean;
        for (int d = 0; d < 3; ++d) {
            EXPECT_NEAR(mean[d], 0.5, 0.01) << "dimension " << d;
            EXPECT_NEAR(variance[d], 1.0 / 12.0, 0.0025) << "dimension " << d;
        }
    }
}

TEST(PhotonNumbers, ZOrderKeepsPatchesTogether) {
    // A 2^k x 2^k aligned patch covers one run of 4^k indices starting at a multiple of 4^k.
    const uint32_t k = 3;
    const uint32_t side = 1u << k;
    const glm::uvec2 corner(5 * side, 2 * side);
    uint32_t lo = UINT32_MAX;
    uint32_t hi = 0;
    for (uint32_t y = 0; y < side; ++y) {
        for (uint32_t x = 0; x < side; ++x) {
            const uint32_t z = gpu::computeZOrder(corner + glm::uvec2(x, y));
            lo = std::min(lo, z);
            hi = std::max(hi, z);
        }
    }
    EXPECT_EQ(hi - lo + 1, side * side);
    EXPECT_EQ(lo % (side * side), 0u);
    EXPECT_EQ(gpu::computeZOrder(glm::uvec2(1, 0)), 1u);
    EXPECT_EQ(gpu::computeZOrder(glm::uvec2(0, 1)), 2u);
    EXPECT_EQ(gpu::computeZOrder(glm::uvec2(65535, 65535)), 0xffffffffu);
}

} // namespace
} // namespace ispm
