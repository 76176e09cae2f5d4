// The light cameras' G-buffer channels (2D arrays, one layer per light view).
#include "../shared/scene_data.h"

layout(binding = kUnitLightGBufferFirst + GBUFFER_POSITION) uniform sampler2DArray uLightPosition;
layout(binding = kUnitLightGBufferFirst + GBUFFER_NORMAL) uniform sampler2DArray uLightNormal;
layout(binding = kUnitLightGBufferFirst + GBUFFER_DIFFUSE) uniform sampler2DArray uLightDiffuse;
layout(binding = kUnitLightGBufferFirst + GBUFFER_SPECULAR) uniform sampler2DArray uLightSpecular;
layout(binding = kUnitLightGBufferFirst + GBUFFER_TRANSMISSIVE) uniform sampler2DArray uLightTransmissive;
