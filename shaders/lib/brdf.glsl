// Reflection models: Lambert (rho / pi) plus normalised Phong around the mirror direction,
// rho_s (n + 2) / (2 pi) cos^n(alpha), which reflects at most rho_s of the incident power.
#include "constants.glsl"

vec3 evaluateBrdf(vec3 diffuse, vec4 specularExponent, vec3 n, vec3 wi, vec3 wo) {
    vec3 f = diffuse * kInvPi;
    if (any(greaterThan(specularExponent.rgb, vec3(0.0)))) {
        float exponent = specularExponent.w;
        vec3 mirror = reflect(-wi, n);
        float cosAlpha = max(dot(mirror, wo), 0.0);
        f += specularExponent.rgb * (exponent + 2.0) * kInvTwoPi * pow(cosAlpha, exponent);
    }
    return f;
}
