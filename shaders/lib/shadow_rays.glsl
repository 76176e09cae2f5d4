// Shadows by ray (setting shadows ray): a point sees a light when nothing lies on the segment
// between them, the path tracer's test (reference.comp). Needs lights.glsl and bvh.glsl included
// before.

// 1 if the light sample `s` reaches the surface point (positionW, normalW), else 0. normalW faces
// the light's side; the ray leaves that far off the surface (computeRayOffset, at least floorM,
// GpuScene::getRayEpsilon) and stops as far short of the light.
float computeRayVisibility(vec3 positionW, vec3 normalW, LightSample s, float floorM) {
    float offset = computeRayOffset(positionW, floorM);
    return isRayBlocked(positionW + normalW * offset, s.wi, s.distanceM - 2.0 * offset) ? 0.0 : 1.0;
}
