// The viewer G-buffer's channels (app/render/gbuffer.cpp's table, bound from kUnitGBufferFirst
// on), declared once for every pass that reads them; a pass uses the ones it needs.
layout(binding = kUnitGBufferFirst + GBUFFER_POSITION) uniform sampler2D uPosition;
layout(binding = kUnitGBufferFirst + GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = kUnitGBufferFirst + GBUFFER_DIFFUSE) uniform sampler2D uDiffuse;
layout(binding = kUnitGBufferFirst + GBUFFER_SPECULAR) uniform sampler2D uSpecular;
layout(binding = kUnitGBufferFirst + GBUFFER_TRANSMISSIVE) uniform sampler2D uTransmissive;
layout(binding = kUnitGBufferFirst + GBUFFER_EMISSION) uniform sampler2D uEmission;
layout(binding = kUnitGBufferFirst + GBUFFER_VELOCITY) uniform sampler2D uVelocity;
