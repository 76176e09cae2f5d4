// Flat-coloured photon points (see photon_points.vert), hidden behind the surface the viewer
// sees at their pixel: photons lie on surfaces, so the test compares distances from the camera.
#include "lib/frame_constants.glsl"

layout(binding = 0) uniform sampler2D uPosition; // viewer G-buffer position, w >= 1 on a surface

in vec3 vColor;
in vec3 vPositionW;

layout(location = 0) out vec4 outColor;

// Relative slack: a photon on the visible surface must pass despite round-off and the G-buffer's
// pixel footprint on slanted surfaces.
const float kDepthSlack = 0.02;

void main() {
    vec4 surface = texelFetch(uPosition, ivec2(gl_FragCoord.xy), 0);
    vec3 eye = frame.cameraPosW;
    if (surface.w > 0.0 &&
        distance(eye, vPositionW) > distance(eye, surface.xyz) * (1.0 + kDepthSlack)) {
        discard;
    }
    outColor = vec4(vColor, 1.0);
}
