// Temporal accumulation (AccumulatePass): this frame's direct and indirect light mixed into their
// histories.
// - Direct light: a running mean of the frames of a still view (params.directWeight = 1 / frames);
//   1 after any motion, where shadows and highlights move with what moved.
// - Indirect light: each pixel keeps how many frames its history holds (its length). A still
//   view mixes the history at the same pixel with weight 1 / (length + 1), the length at most
//   params.historyCapFrames (a running mean from a reset; after motion the moving frames count as
//   a few). When the view or objects moved (params.moved), the history is fetched where this
//   pixel's surface was in the last frame: the point moved back with its instance's motion,
//   projected by the last frame's camera, the four history pixels around it kept where they show
//   the same surface (the same plane, a normal alike) and weighed bilinearly; none kept: the
//   history starts anew.
//   A frame whose pixel centre sees no surface adds nothing to it (the background's 0 is no
//   light of the surface): the history stays the surface's, and compose.frag weighs it by the
//   share of frames that saw it (the direct light's alpha).
#include "lib/frame_constants.glsl"
#include "lib/scene_buffers.glsl"

#include "lib/viewer_gbuffer.glsl"
layout(binding = kUnitDirect) uniform sampler2D uDirect;
layout(binding = kUnitIndirect) uniform sampler2D uIndirect;
layout(binding = kUnitHistoryDirect) uniform sampler2D uHistoryDirect;
layout(binding = kUnitHistoryIndirect) uniform sampler2D uHistoryIndirect;
layout(binding = kUnitHistoryLength) uniform sampler2D uHistoryLength;
layout(binding = kUnitHistoryPosition) uniform sampler2D uHistoryPosition;
layout(binding = kUnitHistoryNormal) uniform sampler2D uHistoryNormal;

layout(std430, binding = kBindingPreviousTransforms) readonly buffer PreviousTransforms {
    mat4 previousWorldFromObject[];
};

layout(std140, binding = kBindingPassParams) uniform AccumulateParamsBlock { AccumulateParams params; };

layout(location = 0) out vec4 outDirect;
layout(location = 1) out vec4 outIndirect;
layout(location = 2) out vec4 outLength;

// A history pixel shows this pixel's surface when its normal is within about 25 degrees and its
// plane passes within 1% of the distance to the camera of the point (a few pixels' depth
// footprint at grazing angles; another object behind or in front is farther off).
const float kNormalCos = 0.9;
const float kPlaneTolerance = 0.01;

struct History {
    vec3 indirect;
    float length;
};

History fetchReprojected(vec4 position, vec3 normal) {
    History none = History(vec3(0.0), 0.0);
    uint instance = uint(position.w + 0.5) - 1u;
    mat4 previousFromCurrent =
        previousWorldFromObject[instance] * instances[instance].objectFromWorld;
    vec3 p = (previousFromCurrent * vec4(position.xyz, 1.0)).xyz;
    vec3 n = normalize(transpose(inverse(mat3(previousFromCurrent))) * normal);
    vec4 clip = params.previousClipFromWorld * vec4(p, 1.0);
    if (clip.w <= 0.0) return none;
    vec2 size = frame.imageSizePx;
    vec2 f = (clip.xy / clip.w * 0.5 + 0.5) * size - 0.5;
    ivec2 base = ivec2(floor(f));
    vec2 t = f - vec2(base);
    float tolerance = kPlaneTolerance * distance(position.xyz, frame.cameraPosW);
    vec3 sum = vec3(0.0);
    float length = 0.0;
    float weights = 0.0;
    for (int i = 0; i < 4; ++i) {
        ivec2 o = ivec2(i & 1, i >> 1);
        ivec2 q = base + o;
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(size)))) continue;
        vec4 hp = texelFetch(uHistoryPosition, q, 0);
        vec3 hn = texelFetch(uHistoryNormal, q, 0).xyz;
        if (hp.w < 0.5 || dot(hn, n) < kNormalCos || abs(dot(p - hp.xyz, hn)) > tolerance)
            continue;
        vec2 w2 = mix(1.0 - t, t, vec2(o));
        float w = w2.x * w2.y;
        sum += w * texelFetch(uHistoryIndirect, q, 0).rgb;
        length += w * texelFetch(uHistoryLength, q, 0).r;
        weights += w;
    }
    // Taps kept with under 1% of the weight: too far off the point to speak for it.
    if (weights < 0.01) return none;
    return History(sum / weights, floor(length / weights + 0.5));
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    // Alpha too: the direct light's is the pixel's surface coverage (compose.frag).
    // A weight of 1 takes this frame's light as it is (mix would round it).
    vec4 direct = texelFetch(uDirect, pixel, 0);
    outDirect = params.directWeight >= 1.0 ? direct
                                     : mix(texelFetch(uHistoryDirect, pixel, 0), direct, params.directWeight);
    // A cap of 0 (a reset) reads no history at all: the textures may hold anything then.
    vec4 position = texelFetch(uPosition, pixel, 0);
    bool surface = position.w >= 0.5;
    History history = History(vec3(0.0), 0.0);
    if (params.historyCapFrames > 0.0 && params.moved == 0u) {
        history = History(texelFetch(uHistoryIndirect, pixel, 0).rgb,
                          texelFetch(uHistoryLength, pixel, 0).r);
    } else if (params.historyCapFrames > 0.0 && surface) {
        history = fetchReprojected(position, texelFetch(uNormal, pixel, 0).xyz);
    }
    float length = min(history.length, params.historyCapFrames);
    vec4 current = texelFetch(uIndirect, pixel, 0);
    // Where this frame's centre sees the background the history stays as it is.
    vec3 indirect = !surface        ? history.indirect
                    : length > 0.0 ? mix(history.indirect, current.rgb, 1.0 / (length + 1.0))
                                   : current.rgb;
    outIndirect = vec4(indirect, current.a);
    outLength = vec4(surface ? length + 1.0 : length, 0.0, 0.0, 0.0);
}
