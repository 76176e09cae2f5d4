// Parameter blocks of one pass for several draws or dispatches (a light view's grid, a splat
// draw, a filter iteration): one uniform buffer holds them all, each at its own multiple of
// kStride, and each draw binds its block by range at gpu::kBindingPassParams. Uploaded once per
// frame, so no draw waits for the one before it to read its block.
#pragma once

#include "gl/objects.h"

#include <shared/scene_data.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace ispm {

template <typename T> class ParamBlocks {
  public:
    // The largest UNIFORM_BUFFER_OFFSET_ALIGNMENT the GL allows an implementation to require.
    static constexpr size_t kStride = 256;
    static_assert(sizeof(T) <= kStride);

    explicit ParamBlocks(std::string label) : mLabel(std::move(label)) {}

    void upload(std::span<const T> blocks) {
        std::vector<uint8_t> bytes(std::max<size_t>(blocks.size(), 1) * kStride, 0);
        for (size_t i = 0; i < blocks.size(); ++i)
            std::memcpy(bytes.data() + i * kStride, &blocks[i], sizeof(T));
        if (mBuffer.getSize() < bytes.size()) mBuffer = gl::Buffer(mLabel, bytes.size());
        mBuffer.upload(0, bytes.size(), bytes.data());
    }

    void bind(size_t index) const {
        mBuffer.bindRange(gl::BufferTarget::Uniform, gpu::kBindingPassParams, index * kStride,
                          sizeof(T));
    }

  private:
    std::string mLabel;
    gl::Buffer mBuffer;
};

} // namespace ispm
