// Importance-driven emission, shared by C++ and GLSL: every light view gets a coarse map of where
// its photons matter to the viewer this frame, built on the GPU from the viewer's G-buffer, and the
// emission grid is warped through the map's inverse CDF (docs/design.md "Where photons go").
#ifndef ISPM_IMPORTANCE_DATA_H
#define ISPM_IMPORTANCE_DATA_H

#include "host_device.h"
#include "photon_scatter.h"

ISPM_NAMESPACE_BEGIN

// Map texels across (and down) one light view: the CDF build is one workgroup of this many rows
// per view. 128 keeps a 1 m door a texel wide under a sun view 128 m across (a 200 m yard: room
// rel RMSE 0.52 with 64, 0.40 with 128); the gather's hits are spread by the maps' filters.
ISPM_CONST uint kImportanceSize = 128u;
ISPM_CONST uint kImportanceTexels = kImportanceSize * kImportanceSize;

// Gathered importance is summed with integer atomics in these units per hit (fixed point), so a
// map texel holds up to 2^32 / 256 = 16 million hits.
ISPM_CONST float kImportanceFixedPoint = 256.0f;

ISPM_CONST uint kImportanceGroupSize = 64u;

// Per map texel and light view: the gathered importance (uint, fixed point; view-major), and the
// sampling tables built from it: for view v, conditional CDFs of the columns within each row at
// [v * texels + row * size + column] (inclusive, the row's last entry 1), then the marginal CDF of
// the rows at [views * texels + v * size + row] (inclusive, last 1).
ISPM_CONST int kBindingImportanceHits = 15;
ISPM_CONST int kBindingImportanceCdf = 16;
// The CDF build's scratch: per view and texel, the gathered importance filtered along its row by
// the two tents (vec2, sharp and wide; the columns' pass of the separable filters reads them).
ISPM_CONST int kBindingImportanceRows = 30;
// Per view and texel: the maps' gathered importance per sample, averaged over frames (float; the
// CDF build blends each frame's hits into it, importance_frames).
ISPM_CONST int kBindingImportanceHistory = 31;
// Image unit of the emission pdf per map texel (relative to uniform: 1), for the viewer.
ISPM_CONST int kImageImportancePdf = 0;

// Where in its cell each grid point of a light view sits this frame ([0,1)^2, the same for every
// cell of the view): a random shift of the whole grid by the frame seed keeps it stratified and
// makes every frame an unbiased estimate, so frames with other seeds sample other first hits.
ISPM_INLINE vec2 computeGridJitter(uint view, uint frameSeed) {
    uint state = seedRandom(view, 0xffffffffu, frameSeed);
    float x = nextRandom(state, kRngPcg);
    return vec2(x, nextRandom(state, kRngPcg));
}

// Solid angle per unit area of a perspective light view's image plane (at unit distance from
// the eye) at plane point p: 1 / (1 + |p|^2)^(3/2). Emission (photon power) and the importance
// tables (each texel's share of the light's power) both integrate it.
ISPM_INLINE float computePlaneSolidAngleDensity(vec2 p) {
    float r2 = 1.0f + dot(p, p);
    return 1.0f / (r2 * sqrt(r2));
}

// Parameters of the importance passes (std140 uniform block).
struct ImportanceParams {
    uvec2 gatherSamples; // gather samples across and down the image
    uint lightViewCount;
    uint seed;             // the frame's
    float importanceShare; // 1 - the uniform floor
    float visibleWeight;   // weight of a visible point
    float bounceWeight;    // weight of a point one bounce away
    float rayOffsetM;
    // Weight of this frame's samples in the maps (1: built anew; else 1 / importance_frames).
    float historyWeight;
    float hitScale; // from a texel's hits to importance per gather sample
    // Weight of a point two bounces away from a visible point that no light reaches.
    float unlitWeight;
    float padding0;
};
ISPM_STATIC_ASSERT_SIZE(ImportanceParams, 48);
ISPM_CONST int kBindingImportanceParams = 1; // uniform buffer

ISPM_NAMESPACE_END

#endif
