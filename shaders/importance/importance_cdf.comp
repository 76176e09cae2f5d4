// Importance tables: one workgroup per light view, one invocation per map row. Each texel's
// probability is a mix of the power the light sends through it (the uniform floor: every texel the
// light reaches keeps a share) and that power times the gathered importance:
//   p = (1 - a) base / sum(base) + a base imp / sum(base imp),  a = importance share,
// base = solid angle x spot falloff (perspective) or 1 (orthographic), imp the gathered hits per
// sample averaged over frames (importance_frames: this frame's blended into the history). Texels the light sends
// nothing through (outside a spot's outer cone) get no photon at all. Writes the conditional CDF
// of every row and the marginal CDF of the rows (layout in shared/importance_data.h).
#include "lib/scene_buffers.glsl"
#include "lib/frame_constants.glsl"
#include "lib/lights.glsl"
#include "shared/importance_data.h"

layout(local_size_x = kImportanceSize) in;

layout(std140, binding = kBindingImportanceParams) uniform ImportanceParamsBlock {
    ImportanceParams params;
};
layout(std430, binding = kBindingImportanceHits) readonly buffer ImportanceHits { uint importanceHits[]; };
layout(std430, binding = kBindingImportanceRows) coherent buffer ImportanceRows { vec2 importanceRows[]; };
layout(std430, binding = kBindingImportanceHistory) buffer ImportanceHistory { float importanceHistory[]; };
layout(std430, binding = kBindingImportanceCdf) writeonly buffer ImportanceCdf { float importanceCdf[]; };
layout(rgba32f, binding = kImageImportancePdf) uniform writeonly image2DArray uPdfMap;

shared float sRowBase[kImportanceSize];
shared float sRowWeighted[kImportanceSize];
shared float sRowMass[kImportanceSize];

// Power the light sends through map texel (column, row), up to a factor common to the view.
// Spot falloff is taken as its largest value at the texel's centre and corners, so a texel the cone
// touches anywhere keeps a probability (the photon's own power uses the exact falloff).
float computeBase(GpuLightView view, GpuLight light, uint column, uint row) {
    if (view.info.y == 1u) return 1.0; // orthographic: equal areas, equal power
    float t = 0.5 * view.axisTexel.w * frame.lightResolutionPx;
    vec2 uv = (vec2(column, row) + 0.5) / float(kImportanceSize);
    vec2 p = (uv * 2.0 - 1.0) * t;
    float solidAngle = computePlaneSolidAngleDensity(p);
    if (light.views.z != kLightSpot) return solidAngle;
    float halfTexel = t / float(kImportanceSize);
    float falloff = 0.0;
    for (int i = 0; i < 5; ++i) {
        vec2 corner = i == 4 ? vec2(0.0) : vec2((i & 1) == 0 ? -1.0 : 1.0, (i & 2) == 0 ? -1.0 : 1.0);
        vec2 q = p + corner * halfTexel;
        float cosAngle = 1.0 / sqrt(1.0 + dot(q, q));
        falloff = max(falloff, computeSpotFalloffCos(cosAngle, light.power.w, light.directionCos.w));
    }
    return solidAngle * falloff;
}

// The gathered importance around a texel at two scales: a tent over 5 x 5 texels (a few gather
// hits mark a region, not single texels) plus half a tent over 13 x 13 texels, so that the
// surroundings of what the gather found (a yard seen through a door, hit by a few rays) get
// photons of moderate power instead of the floor's rare, strong ones. Texels off the map are left
// out of the weights. Each tent is the product of one along the row and one along the column, and
// so is the sum of its weights over the (rectangular) part on the map: the rows are filtered first
// (filterRow), then the columns (filterColumn), 2 x (5 + 13) reads a texel instead of 194.
const int kSharpRadius = 2;
const int kWideRadius = 6;
const float kWideWeight = 0.5;

// The hits of texels (column - r .. column + r, row) under a tent of radius r, normalised.
float filterRow(uint viewIndex, int column, uint row, int radius) {
    float sum = 0.0;
    float weights = 0.0;
    for (int dx = -radius; dx <= radius; ++dx) {
        int at = column + dx;
        if (at < 0 || at >= int(kImportanceSize)) continue;
        float w = float(radius + 1 - abs(dx));
        sum += w * importanceHistory[viewIndex * kImportanceTexels + row * kImportanceSize + uint(at)];
        weights += w;
    }
    return sum / weights;
}

// filterRow's results of rows (row - r .. row + r) under a tent of radius r, normalised: the
// 2D tent's mean.
float filterColumn(uint viewIndex, uint column, int row, int radius, int component) {
    float sum = 0.0;
    float weights = 0.0;
    for (int dy = -radius; dy <= radius; ++dy) {
        int at = row + dy;
        if (at < 0 || at >= int(kImportanceSize)) continue;
        float w = float(radius + 1 - abs(dy));
        sum += w * importanceRows[viewIndex * kImportanceTexels + uint(at) * kImportanceSize + column][component];
        weights += w;
    }
    return sum / weights;
}

float getImportance(uint viewIndex, uint column, uint row) {
    if (params.importanceShare <= 0.0) return 0.0; // nothing aimed: the hits were not gathered
    return filterColumn(viewIndex, column, int(row), kSharpRadius, 0) +
           kWideWeight * filterColumn(viewIndex, column, int(row), kWideRadius, 1);
}

void main() {
    uint viewIndex = gl_WorkGroupID.x;
    uint row = gl_LocalInvocationID.x;
    GpuLightView view = lightViews[viewIndex];
    GpuLight light = lights[view.info.x];
    uint first = viewIndex * kImportanceTexels + row * kImportanceSize;
    if (params.importanceShare > 0.0) {
        // This frame's hits, per gather sample, into the maps' average (importance_frames): the
        // invocation's own row, which its row filter reads next.
        for (uint c = 0u; c < kImportanceSize; ++c) {
            float hits = float(importanceHits[first + c]) * params.hitScale;
            float kept = params.historyWeight < 1.0 ? importanceHistory[first + c] : 0.0;
            importanceHistory[first + c] = mix(kept, hits, params.historyWeight);
        }
        for (uint c = 0u; c < kImportanceSize; ++c) {
            importanceRows[first + c] = vec2(filterRow(viewIndex, int(c), row, kSharpRadius),
                                             filterRow(viewIndex, int(c), row, kWideRadius));
        }
    }
    // Every row's filtered hits are in before any column is read (one workgroup per view).
    memoryBarrierBuffer();
    barrier();
    // Each texel's base and importance, computed once.
    float base[kImportanceSize];
    float importance[kImportanceSize];
    float rowBase = 0.0;
    float rowWeighted = 0.0;
    for (uint c = 0u; c < kImportanceSize; ++c) {
        base[c] = computeBase(view, light, c, row);
        importance[c] = getImportance(viewIndex, c, row);
        rowBase += base[c];
        rowWeighted += base[c] * importance[c];
    }
    sRowBase[row] = rowBase;
    sRowWeighted[row] = rowWeighted;
    barrier();
    float totalBase = 0.0;
    float totalWeighted = 0.0;
    for (uint r = 0u; r < kImportanceSize; ++r) {
        totalBase += sRowBase[r];
        totalWeighted += sRowWeighted[r];
    }
    // Without gathered importance (nothing of it visible) the floor takes everything.
    float share = totalWeighted > 0.0 ? params.importanceShare : 0.0;
    float baseScale = totalBase > 0.0 ? (1.0 - share) / totalBase : 0.0;
    float weightedScale = totalWeighted > 0.0 ? share / totalWeighted : 0.0;

    // Conditional CDF of this row; a row of no mass gets a uniform one (it is never chosen).
    float rowMass = baseScale * rowBase + weightedScale * rowWeighted;
    float running = 0.0;
    for (uint c = 0u; c < kImportanceSize; ++c) {
        float p = base[c] * (baseScale + weightedScale * importance[c]);
        // The texel's probability (the view's sum to 1), shown relative to a uniform map.
        float relative = p * float(kImportanceTexels);
        imageStore(uPdfMap, ivec3(c, row, viewIndex), vec4(vec3(relative), 1.0));
        running += rowMass > 0.0 ? p / rowMass : 1.0 / float(kImportanceSize);
        importanceCdf[first + c] = c + 1u == kImportanceSize ? 1.0 : min(running, 1.0);
    }
    sRowMass[row] = rowMass;
    barrier();
    if (row != 0u) return;
    uint marginal = params.lightViewCount * kImportanceTexels + viewIndex * kImportanceSize;
    float total = 0.0;
    for (uint r = 0u; r < kImportanceSize; ++r) total += sRowMass[r];
    running = 0.0;
    for (uint r = 0u; r < kImportanceSize; ++r) {
        running += total > 0.0 ? sRowMass[r] / total : 1.0 / float(kImportanceSize);
        importanceCdf[marginal + r] = r + 1u == kImportanceSize ? 1.0 : min(running, 1.0);
    }
}
