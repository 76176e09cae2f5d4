// The viewer's debug view: one texture of the frame stretched over the scene region. Display
// values pass through; linear values and G-buffer channels are scaled, biased and gamma-encoded.
#ifdef TEXTURE_ARRAY
layout(binding = 0) uniform sampler2DArray uSource;
// A light view's channels other than position hold values only where position.w marks a surface
// (the light views clear position and depth alone): uMasked shows black elsewhere.
layout(binding = 1) uniform sampler2DArray uPosition;
layout(location = 2) uniform int uMasked;
#else
layout(binding = 0) uniform sampler2D uSource;
#endif

layout(location = 0) uniform vec4 uRegion;    // origin x, y and size in window pixels
layout(location = 1) uniform vec4 uTransform; // scale, bias, 1/gamma (0: none), array layer

layout(location = 0) out vec4 outColor;

void main() {
    vec2 uv = (gl_FragCoord.xy - uRegion.xy) / uRegion.zw;
#ifdef TEXTURE_ARRAY
    vec3 c = textureLod(uSource, vec3(uv, uTransform.w), 0.0).rgb;
    if (uMasked != 0 && textureLod(uPosition, vec3(uv, uTransform.w), 0.0).w < 0.5) c = vec3(0.0);
#else
    vec3 c = textureLod(uSource, uv, 0.0).rgb;
#endif
    c = c * uTransform.x + uTransform.y;
    if (uTransform.z > 0.0) c = pow(max(c, vec3(0.0)), vec3(uTransform.z));
    outColor = vec4(c, 1.0);
}
