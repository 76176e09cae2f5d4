// Shared by the post passes (app/render/post_pass.cpp).

// Depth blur (DepthBlurPass): how much of a pixel's light its circle of confusion of radius r
// gives a pixel `dist` away: 1 inside, 0 outside, a linear ramp one pixel wide across the rim (so
// the disc grows smoothly with r; r = 0 keeps the light in its own pixel). The coc step sums it
// over the whole disc, the gather uses the same weights: each pixel's light is spread with
// weights that sum to one. What falls beyond the image is mirrored back in (half-sample
// symmetric, as the bloom's edges), so no light leaves the image and a uniform region stays
// uniform up to its edge.
float computeDiscWeight(float dist, float radiusPx) {
    float rim = 1.5 + 0.25 * radiusPx;
    return 1.0 - smoothstep(radiusPx - 0.5 * rim, radiusPx + 0.5 * rim, dist);
}

// Where light beyond the image along one axis of n pixels lands: x itself inside [0, n), mirrored
// at the edges outside (repeatedly, for images narrower than a disc).
int mirrorIndex(int x, int n) {
    int period = 2 * n;
    int m = x - period * int(floor(float(x) / float(period)));
    return m < n ? m : period - 1 - m;
}
