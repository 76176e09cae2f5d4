// Random numbers and the photon scattering decision, written once for GLSL (emit and trace
// passes) and C++ (the CPU reference the tests compare against).
// Russian roulette picks diffuse, specular or transmissive with probabilities equal to the mean
// reflectances at the photon's angle of incidence (the diffuse/specular split follows Schlick's
// Fresnel, shared/surface_brdf.h) and scales the power by f cos / pdf, so the estimate is
// unbiased.
#ifndef ISPM_PHOTON_SCATTER_H
#define ISPM_PHOTON_SCATTER_H

#include "host_device.h"
#include "surface_brdf.h"

ISPM_NAMESPACE_BEGIN

ISPM_CONST uint kRngPcg = 0u;
ISPM_CONST uint kRngLcg = 1u;
ISPM_CONST uint kRngSobol = 2u; // the first bounce from computeSobolNumbers, later ones pcg
// Which numbers a photon gets from frame to frame (`rng`; FrameRunner, photon_trace.comp).
ISPM_CONST uint kRngFixed = 0u;
ISPM_CONST uint kRngPerFrame = 1u;
ISPM_CONST uint kRngObjectSpace = 2u;

// Bounce slot of seedRandom for the Sobol scrambling seed of a light view (photon = view).
ISPM_CONST uint kSobolScrambleSlot = 0xfffffffeu;

ISPM_CONST uint kScatterAbsorbed = 0u;
ISPM_CONST uint kScatterDiffuse = 1u;
ISPM_CONST uint kScatterSpecular = 2u;
ISPM_CONST uint kScatterReflect = 3u; // Fresnel reflection off a transmissive surface
ISPM_CONST uint kScatterRefract = 4u;

ISPM_CONST float kTwoPiF = 6.28318530717958f;

// PCG-family integer hash (Jarzynski and Olano 2020, "pcg" output permutation).
ISPM_INLINE uint hashPcg(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Stateless: the same photon, bounce and frame seed always draw the same numbers.
ISPM_INLINE uint seedRandom(uint photon, uint bounce, uint frameSeed) {
    return hashPcg(photon ^ hashPcg(bounce ^ hashPcg(frameSeed)));
}

// Next number in [0, 1) with 24 bits. kRngLcg steps a linear congruential generator (Numerical
// Recipes constants); kRngPcg re-hashes the state.
ISPM_INLINE float nextRandom(ISPM_INOUT(uint) state, uint mode) {
    if (mode == kRngLcg) {
        state = 1664525u * state + 1013904223u;
    } else {
        state = hashPcg(state);
    }
    return float(state >> 8u) * (1.0f / 16777216.0f);
}

// Z order of a grid cell (bits of x and y interleaved, 16 each): cells close in the grid get
// close indices, so any run of indices covers a compact patch of the light view.
ISPM_INLINE uint spreadBits16(uint v) {
    v &= 0xffffu;
    v = (v | (v << 8u)) & 0x00ff00ffu;
    v = (v | (v << 4u)) & 0x0f0f0f0fu;
    v = (v | (v << 2u)) & 0x33333333u;
    v = (v | (v << 1u)) & 0x55555555u;
    return v;
}
ISPM_INLINE uint computeZOrder(uvec2 cell) {
    return spreadBits16(cell.x) | (spreadBits16(cell.y) << 1u);
}

ISPM_INLINE uint reverseBits32(uint v) {
    v = ((v >> 1u) & 0x55555555u) | ((v & 0x55555555u) << 1u);
    v = ((v >> 2u) & 0x33333333u) | ((v & 0x33333333u) << 2u);
    v = ((v >> 4u) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4u);
    v = ((v >> 8u) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8u);
    return (v >> 16u) | (v << 16u);
}

// Nested uniform (Owen) scrambling of a 32-bit fraction: each bit is flipped by a hash of the
// bits above it (the Laine-Karras construction with Vegdahl's constants, as in Burley 2020,
// "Practical Hash-based Owen Scrambling"). Scrambled points stay a net and each is uniform.
ISPM_INLINE uint scrambleOwen(uint v, uint seed) {
    v = reverseBits32(v);
    v ^= v * 0x3d20adeau;
    v += seed;
    v *= (seed >> 16u) | 1u;
    v ^= v * 0x05526c56u;
    v ^= v * 0x53a22864u;
    return reverseBits32(v);
}

// Sobol points of one index in the first three dimensions (direction numbers of the
// polynomials 1, x + 1 and x^2 + x + 1), unscrambled, as 32-bit fractions.
ISPM_INLINE uvec3 computeSobolBits(uint index) {
    uvec3 bits = uvec3(0u);
    uint v0 = 0x80000000u;
    uint v1 = 0x80000000u;
    uint v2 = 0x80000000u;
    uint v2Before = 0u; // dimension 2's direction number one step back
    for (uint bit = 0u; bit < 32u; ++bit) {
        if ((index & (1u << bit)) != 0u) bits ^= uvec3(v0, v1, v2);
        v0 >>= 1u;
        v1 ^= v1 >> 1u;
        uint next = bit == 0u ? 0xc0000000u : v2 ^ v2Before ^ (v2Before >> 2u);
        v2Before = v2;
        v2 = next;
    }
    return bits;
}

// The first bounce's three numbers (roulette, then the lobe's two) for the photon of Z-order
// index `index`, from Sobol points Owen-scrambled per dimension with seeds from `seed`: the
// roulette takes dimension 0 of the index, the lobe dimensions 1 and 2 of the index shuffled
// within its aligned run (Owen scrambling of the index's own bits). Any aligned run of 4^k
// indices is a square patch of grid cells and maps onto itself, so in each dimension, and in
// the lobe's pair, the patch's numbers are stratified: its photons survive the roulette in the
// right proportion and leave in well spread directions. The shuffle keeps the decision and the
// direction apart (unshuffled, all three share the index's low bit: the survivors of a roulette
// near 1/2 would all leave within 45 degrees of the normal). Each number stays uniform, so the
// estimate stays unbiased.
ISPM_INLINE vec3 computeSobolNumbers(uint index, uint seed) {
    uint s0 = hashPcg(seed);
    uint s1 = hashPcg(s0);
    uint s2 = hashPcg(s1);
    uint s3 = hashPcg(s2);
    uint roulette = computeSobolBits(index).x;
    uvec3 lobe = computeSobolBits(scrambleOwen(index, s3));
    uvec3 bits =
        uvec3(scrambleOwen(roulette, s0), scrambleOwen(lobe.y, s1), scrambleOwen(lobe.z, s2));
    return vec3(bits >> 8u) * (1.0f / 16777216.0f);
}

// An orthonormal basis around unit n (Duff et al. 2017).
ISPM_INLINE void buildBasis(vec3 n, ISPM_OUT(vec3) t, ISPM_OUT(vec3) b) {
    float s = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

// Cosine-weighted direction around unit n.
ISPM_INLINE vec3 sampleCosine(vec3 n, float u1, float u2) {
    vec3 t;
    vec3 b;
    buildBasis(n, t, b);
    float r = sqrt(u1);
    float phi = kTwoPiF * u2;
    float z = sqrt(max(0.0f, 1.0f - u1));
    return normalize(t * (r * cos(phi)) + b * (r * sin(phi)) + n * z);
}

// Direction with density (e + 1) / (2 pi) cos^e(alpha) around unit axis.
ISPM_INLINE vec3 samplePhongLobe(vec3 axis, float exponent, float u1, float u2) {
    vec3 t;
    vec3 b;
    buildBasis(axis, t, b);
    float cosAlpha = pow(u1, 1.0f / (exponent + 1.0f));
    float sinAlpha = sqrt(max(0.0f, 1.0f - cosAlpha * cosAlpha));
    float phi = kTwoPiF * u2;
    return normalize(t * (sinAlpha * cos(phi)) + b * (sinAlpha * sin(phi)) + axis * cosAlpha);
}

// Unpolarised Fresnel reflectance of a dielectric; eta = n_incident / n_transmitted.
ISPM_INLINE float computeFresnel(float cosIncident, float eta) {
    float sin2T = eta * eta * max(0.0f, 1.0f - cosIncident * cosIncident);
    if (sin2T >= 1.0f) return 1.0f; // total internal reflection
    float cosT = sqrt(1.0f - sin2T);
    float rs = (eta * cosIncident - cosT) / (eta * cosIncident + cosT);
    float rp = (cosIncident - eta * cosT) / (cosIncident + eta * cosT);
    return 0.5f * (rs * rs + rp * rp);
}

ISPM_INLINE float computeMean(vec3 v) {
    return (v.x + v.y + v.z) * (1.0f / 3.0f);
}

// The material's albedo as scatterSurfaceWith's lobe choice sums it: the means of its diffuse,
// specular and transmissive reflectance. 1 / this as selectScale always picks a lobe.
ISPM_INLINE float computeLobeAlbedo(vec3 diffuse, vec4 specular, vec4 transmissive) {
    return computeMean(diffuse) + computeMean(vec3(specular)) + computeMean(vec3(transmissive));
}

// Scatters a path travelling along `dir` that hit a surface with unit normal `n` facing the side
// it came from. `entering`: it hit the front face (for the index of refraction). A lobe is chosen
// with probability (its mean reflectance at this incidence) x selectScale, and the weight is
// multiplied by f cos / pdf of the direction drawn, so its expectation is the lobe's reflectance.
// The diffuse and specular reflectances add up to the material's at every angle, so
// selectScale = 1 is Russian roulette on the albedo (photons: absorbed paths end) and
// selectScale = 1 / (sum of the material's means) always picks a lobe (camera paths of the
// reference, which apply their own roulette). Updates dir and weight; returns the kScatter* event.
// `numbers`: (u for the lobe, u1 and u2 for its direction).
ISPM_INLINE uint scatterSurfaceWith(ISPM_INOUT(vec3) dir, ISPM_INOUT(vec3) weight, vec3 n,
                                    vec3 diffuse, vec4 specular, vec4 transmissive, bool entering,
                                    vec3 numbers, float selectScale) {
    vec3 rhoS = vec3(specular);
    float cosIn = clamp(-dot(dir, n), 0.0f, 1.0f);
    float pd = computeMean(computeDiffuseAlbedo(diffuse, rhoS, cosIn)) * selectScale;
    float ps = computeMean(computeSpecularAlbedo(diffuse, rhoS, cosIn)) * selectScale;
    float pt = computeMean(vec3(transmissive)) * selectScale;
    float u = numbers.x;
    float u1 = numbers.y;
    float u2 = numbers.z;
    if (u < pd) {
        vec3 out_ = sampleCosine(n, u1, u2);
        if (hasSpecularLobe(rhoS)) {
            // f cos / pdf with pdf = cos / pi: pi f.
            vec3 f = evaluateDiffuseLobe(diffuse, rhoS, cosIn, dot(out_, n));
            weight = weight * (f * (1.0f / (kInvPiF * pd)));
        } else {
            weight = weight * (diffuse / pd); // Lambert: pi f = rho_d
        }
        dir = out_;
        return kScatterDiffuse;
    }
    if (u < pd + ps) {
        float exponent = specular.w;
        vec3 out_ = samplePhongLobe(reflect(dir, n), exponent, u1, u2);
        float cosOut = dot(out_, n);
        if (cosOut <= 0.0f) return kScatterAbsorbed; // the lobe dipped below the surface
        // f cos / pdf for the normalised Phong lobe: rho_s (e + 2) / (e + 1) cos(theta_out),
        // rho_s the specular reflectance of this pair of directions.
        vec3 albedo = computePairSpecularAlbedo(diffuse, rhoS, -dir, out_);
        weight = weight * (albedo / ps) * ((exponent + 2.0f) / (exponent + 1.0f) * cosOut);
        dir = out_;
        return kScatterSpecular;
    }
    if (u < pd + ps + pt) {
        float ior = transmissive.w;
        float eta = entering ? 1.0f / ior : ior;
        float fresnel = computeFresnel(cosIn, eta);
        weight = weight * (vec3(transmissive) / pt);
        if (u1 < fresnel) {
            dir = reflect(dir, n);
            return kScatterReflect;
        }
        float sin2T = eta * eta * (1.0f - cosIn * cosIn);
        dir = normalize(dir * eta + n * (eta * cosIn - sqrt(1.0f - sin2T)));
        return kScatterRefract;
    }
    return kScatterAbsorbed;
}

// The density per solid angle with which scatterSurfaceWith draws the direction `out_` for a path
// along `dir` (its diffuse and Phong lobes; the transmissive lobe's directions are deltas and
// have none): what the path tracer weighs a BSDF-sampled ray that hits an emitter with against
// light sampling (multiple importance sampling).
ISPM_INLINE float computeScatterPdf(vec3 dir, vec3 n, vec3 diffuse, vec4 specular, vec3 out_,
                                    float selectScale) {
    float cosOut = dot(out_, n);
    if (cosOut <= 0.0f) return 0.0f;
    vec3 rhoS = vec3(specular);
    float cosIn = clamp(-dot(dir, n), 0.0f, 1.0f);
    float pd = computeMean(computeDiffuseAlbedo(diffuse, rhoS, cosIn)) * selectScale;
    float pdf = pd * cosOut * kInvPiF;
    float ps = computeMean(computeSpecularAlbedo(diffuse, rhoS, cosIn)) * selectScale;
    float cosAlpha = dot(out_, reflect(dir, n));
    if (ps > 0.0f && cosAlpha > 0.0f) {
        float exponent = specular.w;
        pdf += ps * (exponent + 1.0f) / kTwoPiF * pow(cosAlpha, exponent);
    }
    return pdf;
}

// The power heuristic (Veach 1997, beta = 2): the weight of a sample drawn with pdf `chosen`
// where another strategy would have drawn it with pdf `other`.
ISPM_INLINE float computeMisWeight(float chosen, float other) {
    float a = chosen * chosen;
    float b = other * other;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

// Radiance across a refracting surface changes with the square of the index ratio (L / n^2 is
// what is conserved); flux does not. A camera path carries radiance backwards along its own
// direction, so at a refraction its throughput takes (n_incident / n_transmitted)^2 = eta^2 of
// that direction: 1 / ior^2 entering glass, ior^2 leaving it. Photons and light paths carry flux
// and take nothing.
ISPM_INLINE float computeRefractedRadianceScale(bool entering, float ior) {
    float eta = entering ? 1.0f / ior : ior;
    return eta * eta;
}

// The same with three numbers drawn from `rng`.
ISPM_INLINE uint scatterSurface(ISPM_INOUT(vec3) dir, ISPM_INOUT(vec3) weight, vec3 n, vec3 diffuse,
                                vec4 specular, vec4 transmissive, bool entering,
                                ISPM_INOUT(uint) rng, uint mode, float selectScale) {
    float u = nextRandom(rng, mode);
    float u1 = nextRandom(rng, mode);
    float u2 = nextRandom(rng, mode);
    return scatterSurfaceWith(dir, weight, n, diffuse, specular, transmissive, entering,
                              vec3(u, u1, u2), selectScale);
}

// Whether a path scattered (by scatterSurface with a shading normal) into `dir` leaves on the
// side of its event against the geometric normal `n` facing the side it came from: a
// reflection above the surface, a refraction below. A shading normal's lobe can reach across
// the surface; such a path ends (absorbed), so no light passes through it. With n as the
// shading normal (flat surfaces) every sampled direction passes.
ISPM_INLINE bool isScatterOnGeometricSide(uint event, vec3 dir, vec3 n) {
    float side = dot(dir, n);
    return event == kScatterRefract ? side <= 0.0f : side >= 0.0f;
}

// A light path (photons, the light tracer) scattered with a shading normal carries flux, which
// crossed the surface by the geometric normal: Veach's adjoint correction (thesis 1997, eq. 5.19)
// |toPrevious.shading| |toNext.n| / (|toPrevious.n| |toNext.shading|) multiplies its weight, so
// that it reaches the same light as a camera path would gather. 1 where shading is n.
ISPM_INLINE float computeShadingAdjoint(vec3 toPrevious, vec3 toNext, vec3 n, vec3 shading) {
    float denominator = abs(dot(toPrevious, n)) * abs(dot(toNext, shading));
    if (!(denominator > 0.0f)) return 0.0f;
    return abs(dot(toPrevious, shading)) * abs(dot(toNext, n)) / denominator;
}

// Photons: Russian roulette on the albedo, absorbed photons end.
ISPM_INLINE uint scatterPhoton(ISPM_INOUT(vec3) dir, ISPM_INOUT(vec3) power, vec3 n, vec3 diffuse,
                               vec4 specular, vec4 transmissive, bool entering,
                               ISPM_INOUT(uint) rng, uint mode) {
    return scatterSurface(dir, power, n, diffuse, specular, transmissive, entering, rng, mode,
                          1.0f);
}

// Path density: how much the scattering so far has concentrated the photon's path, relative to
// a diffuse bounce (1). A Phong lobe concentrates by about (e + 2) / 2 relative to the cosine lobe;
// mirror reflection and refraction are treated as a fixed strong focus. The splat radius in
// `path_density` mode shrinks with its square root, so caustics stay sharp.
ISPM_CONST float kDeltaConcentration = 16.0f;

ISPM_INLINE float updatePathDensity(float density, uint event, float exponent) {
    if (event == kScatterDiffuse) return 1.0f;
    if (event == kScatterSpecular) return density * (exponent + 2.0f) * 0.5f;
    if (event == kScatterReflect || event == kScatterRefract) return density * kDeltaConcentration;
    return density;
}

ISPM_NAMESPACE_END

#endif
