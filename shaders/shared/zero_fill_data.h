// The interface of shaders/util/zero_fill.comp (ZeroFill), shared by C++ and GLSL.
#ifndef ISPM_ZERO_FILL_DATA_H
#define ISPM_ZERO_FILL_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

// The range being zeroed: a storage binding above every product binding (shared/*.h), as the
// debug queries' are.
ISPM_CONST int kBindingZeroFill = 32;
// 16 bytes per invocation; 256 a group keeps a 64 MiB chunk within one dispatch's 65,535 groups.
ISPM_CONST uint kZeroFillGroupSize = 256u;

ISPM_NAMESPACE_END

#endif
