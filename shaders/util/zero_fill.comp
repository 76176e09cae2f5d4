// Zeroes the storage range bound at kBindingZeroFill, 16 bytes an invocation (ZeroFill).
#include "shared/zero_fill_data.h"

layout(local_size_x = kZeroFillGroupSize) in;

layout(std430, binding = kBindingZeroFill) writeonly buffer Target { uvec4 words[]; };

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index < uint(words.length())) words[index] = uvec4(0u);
}
