// Emissive triangles as lights (shared/emitter_data.h, docs/design.md "Emitters"): a point on
// them picked by power, what it sends toward a shaded point and its pdf per solid angle, and
// next-event estimation with a shadow ray through the BVH. direct.frag, edge_shade.comp, the
// specular pass and the path tracer shade with it. Needs scene_buffers.glsl,
// frame_constants.glsl, bvh.glsl and brdf.glsl included before.
#include "../shared/emitter_data.h"
#include "../shared/photon_scatter.h"

layout(std430, binding = kBindingEmitters) readonly buffer SceneEmitters { GpuEmitter emitters[]; };

// The first row whose cumulative pick probability exceeds u (binary search over the table).
uint findEmitter(float u) {
    uint lo = 0u;
    uint hi = frame.emitterCount - 1u;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (emitters[mid].p0Cdf.w <= u) lo = mid + 1u;
        else hi = mid;
    }
    return lo;
}

// The radiance an emitter of `emission` (GpuMaterial::emission: w = two-sided) sends along a ray
// that meets it with cosine `cosToNormal` between the ray's reversed direction and the
// triangle's winding normal: nothing from the back of a one-sided emitter.
vec3 computeEmittedRadiance(vec4 emission, float cosToNormal) {
    return (cosToNormal > 0.0 || emission.w > 0.5) ? emission.rgb : vec3(0.0);
}

// Solid angle of a triangle whose corners lie in the unit directions a, b, c from the viewpoint
// (Van Oosterom and Strackee 1983: stable for small triangles, where the angle sum is not).
float computeTriangleSolidAngle(vec3 a, vec3 b, vec3 c) {
    float numerator = abs(dot(a, cross(b, c)));
    float denominator = 1.0 + dot(a, b) + dot(b, c) + dot(c, a);
    return 2.0 * atan(numerator, denominator);
}

// Triangles seen under a solid angle in this range are sampled uniformly over it (Arvo 1995), so
// a large emitter near the point (a ceiling panel, a glowing wall) is sampled by the directions
// it fills, not by its area; outside it, by area (a tiny or far triangle, where the spherical
// construction loses float precision, or one the point almost lies on).
const float kMinSphericalSampleSr = 1e-3;
const float kMaxSphericalSampleSr = 6.0;

bool isSampledBySolidAngle(float solidAngle) {
    return solidAngle >= kMinSphericalSampleSr && solidAngle <= kMaxSphericalSampleSr;
}

// A uniformly distributed direction inside the spherical triangle (a, b, c) of area
// `solidAngle` (Arvo 1995, "Stratified sampling of spherical triangles"): u.x chooses the area
// of the sub-triangle (a, b, c'), u.y the point along the arc from b to c'.
vec3 sampleSphericalTriangle(vec3 a, vec3 b, vec3 c, float solidAngle, vec2 u) {
    vec3 nab = normalize(cross(a, b));
    vec3 nac = normalize(cross(a, c));
    float alpha = acos(clamp(dot(nab, nac), -1.0, 1.0)); // the angle at a
    float subArea = u.x * solidAngle;
    float s = sin(subArea - alpha);
    float t = cos(subArea - alpha);
    float cosAlpha = cos(alpha);
    float sinAlpha = sin(alpha);
    float uu = t - cosAlpha;
    float vv = s + sinAlpha * dot(a, b);
    float q = clamp(((vv * t - uu * s) * cosAlpha - vv) / ((vv * s + uu * t) * sinAlpha), -1.0, 1.0);
    vec3 cp = q * a + sqrt(max(1.0 - q * q, 0.0)) * normalize(c - dot(c, a) * a);
    float z = 1.0 - u.y * (1.0 - dot(cp, b));
    vec3 across = cp - dot(cp, b) * b;
    float acrossLength = length(across);
    if (!(acrossLength > 0.0)) return b;
    return z * b + sqrt(max(1.0 - z * z, 0.0)) * (across / acrossLength);
}

// The pdf per solid angle with which sampleEmitter picks a direction toward a point of the
// triangle (p0, p1, p2) of an emitter of `emission` (GpuMaterial::emission: w = two-sided), seen
// from `fromW` at distance `distanceM` and cosine `cosAtEmitter` to its normal: the triangle's
// pick probability over its solid angle, or over its area converted to solid angle. A
// BSDF-sampled ray that hits an emitter weighs both strategies with it (MIS).
float computeEmitterPdf(vec4 emission, vec3 fromW, vec3 p0, vec3 p1, vec3 p2, float distanceM,
                        float cosAtEmitter) {
    float perArea = computeEmitterWeightPerArea(emission.rgb, emission.w) / frame.emitterWeight;
    float solidAngle = computeTriangleSolidAngle(normalize(p0 - fromW), normalize(p1 - fromW),
                                                 normalize(p2 - fromW));
    if (isSampledBySolidAngle(solidAngle)) {
        float area = 0.5 * length(cross(p1 - p0, p2 - p0));
        return perArea * area / solidAngle;
    }
    return perArea * distanceM * distanceM / max(abs(cosAtEmitter), 1e-20);
}

struct EmitterSample {
    vec3 pointW;
    vec3 wi;          // unit direction from the shaded point toward it
    float distanceM;
    vec3 radiance;    // W/(m^2 sr) it sends back along -wi (0 from a one-sided emitter's back)
    float pdf;        // per solid angle at the shaded point (0: nothing to add)
    float offsetM;    // the ray offset at the emitter's point
    float cosAtEmitter; // between -wi and the emitter's winding normal
};

// A point on the emitters for the shaded point `positionW`, from three numbers in [0, 1): the
// triangle by power (u.x), then a direction uniform over the solid angle it fills, or a uniform
// point on it (u.yz; isSampledBySolidAngle).
EmitterSample sampleEmitter(vec3 positionW, vec3 u, float rayFloorM) {
    EmitterSample s;
    s.pdf = 0.0;
    GpuEmitter e = emitters[findEmitter(u.x)];
    vec3 p0 = e.p0Cdf.xyz;
    vec3 p1 = p0 + e.edge1Area.xyz;
    vec3 p2 = p0 + e.edge2Group.xyz;
    vec3 normal = normalize(cross(e.edge1Area.xyz, e.edge2Group.xyz));
    float perArea = computeEmitterWeightPerArea(e.radiance.rgb, e.radiance.w) / frame.emitterWeight;
    vec3 a = normalize(p0 - positionW);
    vec3 b = normalize(p1 - positionW);
    vec3 c = normalize(p2 - positionW);
    float solidAngle = computeTriangleSolidAngle(a, b, c);
    float cosAtEmitter;
    if (isSampledBySolidAngle(solidAngle)) {
        s.wi = sampleSphericalTriangle(a, b, c, solidAngle, u.yz);
        // Where the direction meets the triangle's plane.
        float along = dot(normal, s.wi);
        if (along == 0.0) return s;
        s.distanceM = dot(normal, p0 - positionW) / along;
        if (!(s.distanceM > 0.0)) return s;
        s.pointW = positionW + s.wi * s.distanceM;
        cosAtEmitter = -along;
        s.pdf = perArea * e.edge1Area.w / solidAngle;
    } else {
        float r = sqrt(u.y);
        s.pointW = p0 + e.edge1Area.xyz * (r * (1.0 - u.z)) + e.edge2Group.xyz * (r * u.z);
        vec3 toLight = s.pointW - positionW;
        float d2 = dot(toLight, toLight);
        s.distanceM = sqrt(d2);
        if (!(s.distanceM > 0.0)) return s;
        s.wi = toLight / s.distanceM;
        cosAtEmitter = -dot(normal, s.wi);
        if (cosAtEmitter == 0.0) return s;
        s.pdf = perArea * d2 / abs(cosAtEmitter);
    }
    s.radiance = computeEmittedRadiance(e.radiance, cosAtEmitter);
    s.offsetM = computeRayOffset(s.pointW, rayFloorM);
    s.cosAtEmitter = cosAtEmitter;
    return s;
}

// Whether nothing lies between the shaded point (leaving along n, which faces wi's side) and
// the sampled point: the ray stops where it comes the emitter's ray offset near the emitter's
// plane, offset / cos before it, since a ray that meets a large emitter at a grazing angle finds
// its own plane's hit with an error that grows as 1 / cos.
bool isEmitterVisible(vec3 positionW, vec3 n, EmitterSample s, float rayFloorM) {
    float offset = computeRayOffset(positionW, rayFloorM);
    float tMax = s.distanceM - offset - s.offsetM / max(abs(s.cosAtEmitter), 1e-3);
    if (tMax <= 0.0) return true;
    return !isRayBlocked(positionW + n * offset, s.wi, tMax);
}

// BRDF x radiance x cos / pdf of one emitter sample, shadow ray included: the light arriving
// from the emitters at positionW, where n (the geometric normal) faces the viewer and decides
// the side, shading (turned to n's side, docs/design.md "Shading normals") gives the BRDF and its
// cosine, and wo points to the viewer.
vec3 shadeEmitterSample(EmitterSample s, vec3 positionW, vec3 n, vec3 shading, vec3 diffuse,
                        vec4 specular, vec3 wo, float rayFloorM) {
    float cosTheta = dot(shading, s.wi);
    if (!(s.pdf > 0.0) || cosTheta <= 0.0 || dot(n, s.wi) <= 0.0 ||
        all(equal(s.radiance, vec3(0.0)))) {
        return vec3(0.0);
    }
    if (!isEmitterVisible(positionW, n, s, rayFloorM)) return vec3(0.0);
    return evaluateBrdf(diffuse, specular, shading, s.wi, wo) * s.radiance * (cosTheta / s.pdf);
}

// Three stratified numbers for sample `index` of a pixel: Sobol points (a (0,2)-sequence in the
// first two dimensions), Owen-scrambled per dimension with the pixel's seeds; any 2^k
// consecutive samples of a pixel spread evenly over the emitters' power and their area.
vec3 computeEmitterNumbers(uint index, uvec3 seeds) {
    uvec3 bits = computeSobolBits(index);
    bits = uvec3(scrambleOwen(bits.x, seeds.x), scrambleOwen(bits.y, seeds.y),
                 scrambleOwen(bits.z, seeds.z));
    return vec3(bits >> 8u) * (1.0 / 16777216.0);
}

// Bounce slot of seedRandom for a viewer pixel's emitter samples (photon = pixel index).
const uint kEmitterSeedSlot = 0xfffffffcu;

// The scrambling seeds of a pixel (or any key) in this frame.
uvec3 computeEmitterSeeds(uint key, uint slot) {
    uint s0 = seedRandom(key, slot, frame.seed);
    uint s1 = hashPcg(s0);
    return uvec3(s0, s1, hashPcg(s1));
}

// Direct light from the emitters at a surface point (normals as shadeEmitterSample's), the mean
// of `samples` stratified samples (samples first..first + samples of the sequence seeded by
// `seeds`).
vec3 computeEmitterRadiance(vec3 positionW, vec3 n, vec3 shading, vec3 diffuse, vec4 specular,
                            vec3 wo, float rayFloorM, uint first, uint samples, uvec3 seeds) {
    if (frame.emitterCount == 0u || samples == 0u) return vec3(0.0);
    vec3 sum = vec3(0.0);
    for (uint i = 0u; i < samples; ++i) {
        EmitterSample s = sampleEmitter(positionW, computeEmitterNumbers(first + i, seeds), rayFloorM);
        sum += shadeEmitterSample(s, positionW, n, shading, diffuse, specular, wo, rayFloorM);
    }
    return sum / float(samples);
}
