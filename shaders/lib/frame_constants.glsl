// The per-frame uniform block (layout in shared/scene_data.h).
#include "../shared/scene_data.h"

layout(std140, binding = kBindingFrameConstants) uniform FrameConstantsBlock {
    FrameConstants frame;
};

// The viewer G-buffer pixel that pixel `p` of a buffer `divisor` times smaller than the image
// stands for (splat_resolution): the middle of its block, inside the image. The splat shades
// it, the filter and the upsample weigh by it.
ivec2 getBlockGBufferPixel(ivec2 p, int divisor) {
    return min(p * divisor + divisor / 2, ivec2(frame.imageSize.xy) - 1);
}
