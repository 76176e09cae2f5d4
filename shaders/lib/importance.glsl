// Sampling a light view through its importance tables (importance_cdf.comp): a point of the unit
// square (a cell of the emission grid) goes through the inverse marginal CDF of the map's rows and
// the inverse conditional CDF of the chosen row's columns, to a light-view position whose density
// over the unit square is returned too. Regular grid points stay stratified: neighbours in the
// grid stay neighbours in the view.
#include "../shared/importance_data.h"

layout(std430, binding = kBindingImportanceCdf) readonly buffer ImportanceCdf { float importanceCdf[]; };

// Smallest i in [0, kImportanceSize) with cdf[first + i] > u (the last entry is 1 > u).
uint findCdfInterval(uint first, float u) {
    uint lo = 0u;
    uint hi = kImportanceSize - 1u;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (importanceCdf[first + mid] > u) {
            hi = mid;
        } else {
            lo = mid + 1u;
        }
    }
    return lo;
}

// `u` in [0,1)^2 -> light-view uv in [0,1]^2; `pdf` = density of the result over the unit square.
vec2 warpByImportance(uint view, uint viewCount, vec2 u, out float pdf) {
    uint marginal = viewCount * kImportanceTexels + view * kImportanceSize;
    uint row = findCdfInterval(marginal, u.y);
    float rowLo = row > 0u ? importanceCdf[marginal + row - 1u] : 0.0;
    float rowP = importanceCdf[marginal + row] - rowLo;
    uint conditional = view * kImportanceTexels + row * kImportanceSize;
    uint column = findCdfInterval(conditional, u.x);
    float columnLo = column > 0u ? importanceCdf[conditional + column - 1u] : 0.0;
    float columnP = importanceCdf[conditional + column] - columnLo;
    pdf = rowP * columnP * float(kImportanceTexels);
    vec2 within = vec2((u.x - columnLo) / max(columnP, 1e-30), (u.y - rowLo) / max(rowP, 1e-30));
    return (vec2(column, row) + clamp(within, 0.0, 1.0)) / float(kImportanceSize);
}
