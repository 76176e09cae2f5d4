// The backdrop of a photon-buffer image: the tone-mapped frame dimmed, so the points stand out
// while the scene stays recognisable.
layout(binding = 0) uniform sampler2D uDisplay; // display values (gamma-encoded RGBA8)

layout(location = 0) out vec4 outColor;

const float kBackdrop = 0.3; // of the display values

void main() {
    outColor = vec4(texelFetch(uDisplay, ivec2(gl_FragCoord.xy), 0).rgb * kBackdrop, 1.0);
}
