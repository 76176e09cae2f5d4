// The per-frame uniform block (layout in shared/scene_data.h).
#include "../shared/scene_data.h"

layout(std140, binding = kBindingFrameConstants) uniform FrameConstantsBlock {
    FrameConstants frame;
};
