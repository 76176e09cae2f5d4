// ZeroFill: both methods zero exactly the range asked for, across the compute fill's 64 MiB
// chunks, and Auto picks the clear on llvmpipe.
#include "support/gl_fixture.h"

#include "render/zero_fill.h"

#include <algorithm>
#include <vector>

namespace ispm::test {
namespace {

class ZeroFillTest : public GlTest {};

constexpr uint32_t kMarker = 0xDEADBEEFu;

// A buffer of `words` markers, zero-filled over its first `zeroWords` by `method`; returns it.
std::vector<uint32_t> fillAndRead(ZeroFill::Method method, size_t words, size_t zeroWords) {
    const std::vector<uint32_t> markers(words, kMarker);
    const gl::Buffer buffer = gl::Buffer::fromSpan<uint32_t>("zero fill target", markers);
    ZeroFill(method).fill(buffer, zeroWords * sizeof(uint32_t));
    return buffer.read<uint32_t>(words);
}

TEST_F(ZeroFillTest, BothMethodsZeroExactlyTheRange) {
    constexpr size_t kWords = 1000;
    constexpr size_t kZeroWords = 996; // a multiple of 4 words (16 bytes); 4 markers stay
    for (ZeroFill::Method method : {ZeroFill::Method::Clear, ZeroFill::Method::Compute}) {
        const std::vector<uint32_t> words = fillAndRead(method, kWords, kZeroWords);
        EXPECT_TRUE(std::all_of(words.begin(), words.begin() + kZeroWords,
                                [](uint32_t w) { return w == 0u; }));
        EXPECT_TRUE(std::all_of(words.begin() + kZeroWords, words.end(),
                                [](uint32_t w) { return w == kMarker; }));
    }
}

TEST_F(ZeroFillTest, ComputeFillCrossesItsChunks) {
    // 64 MiB chunks: this range takes a whole one and part of a second.
    constexpr size_t kChunkWords = (size_t(1) << 26) / sizeof(uint32_t);
    constexpr size_t kWords = kChunkWords + 4096;
    constexpr size_t kZeroWords = kChunkWords + 2048;
    const std::vector<uint32_t> words = fillAndRead(ZeroFill::Method::Compute, kWords, kZeroWords);
    const auto firstMarker = std::find(words.begin(), words.end(), kMarker);
    EXPECT_EQ(size_t(firstMarker - words.begin()), kZeroWords);
    EXPECT_TRUE(std::all_of(firstMarker, words.end(), [](uint32_t w) { return w == kMarker; }));
}

TEST_F(ZeroFillTest, AutoClearsOnSoftwareRenderersAndFillsOnGpus) {
    // Auto follows the context's renderer: the clear on llvmpipe (the tests' renderer,
    // docs/design.md "The test renderer (llvmpipe)"), the compute fill on a GPU; the explicit
    // methods are what they say.
    const bool software = getTestContext().getInfo().isSoftware;
    EXPECT_EQ(ZeroFill().usesCompute(), !software);
    EXPECT_TRUE(ZeroFill(ZeroFill::Method::Compute).usesCompute());
    EXPECT_FALSE(ZeroFill(ZeroFill::Method::Clear).usesCompute());
}

} // namespace
} // namespace ispm::test
