// ZeroFill: glClearNamedBufferSubData, or zero_fill.comp over 64 MiB ranges of the buffer.
#include "render/zero_fill.h"

#include "gl/context.h"
#include "gl/state.h"

#include <shared/zero_fill_data.h>

#include <algorithm>
#include <cassert>

namespace ispm {
namespace {

// One dispatch's range: 2^22 invocations of 16 bytes in 16,384 groups, under every GL's
// minimum storage block size (2^27 bytes) and group count (65,535).
constexpr size_t kChunkBytes = size_t(1) << 26;
constexpr size_t kWordBytes = 16;

} // namespace

ZeroFill::ZeroFill(Method method)
    : mCompute(method == Method::Compute ||
               (method == Method::Auto && !gl::isCurrentRendererSoftware())) {
    if (mCompute) {
        mProgram = ReloadableProgram(
            {.label = "zero fill", .stages = {{gl::ShaderStage::Compute, "util/zero_fill.comp"}}});
    }
}

void ZeroFill::fill(const gl::Buffer& buffer, size_t bytes) const {
    assert(bytes % kWordBytes == 0 && bytes <= buffer.getSize());
    if (bytes == 0) return;
    if (!mCompute) {
        buffer.clearRangeToZero(0, bytes);
        return;
    }
    mProgram.use();
    for (size_t offset = 0; offset < bytes; offset += kChunkBytes) {
        const size_t chunk = std::min(kChunkBytes, bytes - offset);
        buffer.bindRange(gl::BufferTarget::Storage, gpu::kBindingZeroFill, offset, chunk);
        const size_t invocations = chunk / kWordBytes;
        gl::dispatchCompute(
            unsigned((invocations + gpu::kZeroFillGroupSize - 1) / gpu::kZeroFillGroupSize));
    }
    gl::memoryBarrier(gl::Barrier::Storage | gl::Barrier::Command | gl::Barrier::BufferUpdate);
}

void ZeroFill::reloadIfChanged(ShaderReloadReport& report) {
    if (mCompute) mProgram.reloadIfChanged(report);
}

} // namespace ispm
