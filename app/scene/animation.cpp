// Animation transforms and Scene::update. Angles are reduced to one turn in double precision
// before they become float, so a periodic motion returns to its start exactly after each period
// and long play times keep their precision.
#include "scene/animation.h"

#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace ispm {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kDegreesPerTurn = 360.0;

// The fraction of the current period, in [0, 1): whole periods are dropped exactly.
double computePeriodFraction(double timeS, double periodS) {
    const double turns = std::fmod(timeS / periodS, 1.0);
    return turns < 0.0 ? turns + 1.0 : turns;
}

glm::mat4 rotateAbout(const glm::vec3& centreW, const glm::vec3& axis, double angleRad) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), centreW);
    m = glm::rotate(m, static_cast<float>(angleRad), axis);
    return glm::translate(m, -centreW);
}

} // namespace

glm::mat4 computeAnimationTransform(const Animation& animation, double timeS) {
    glm::mat4 m(1.0f);
    const float rateDegPerS = glm::length(animation.rotateDegPerS);
    if (rateDegPerS > 0.0f) {
        const double deg = std::fmod(static_cast<double>(rateDegPerS) * timeS, kDegreesPerTurn);
        m = rotateAbout(animation.pivotW, animation.rotateDegPerS / rateDegPerS,
                        deg / kDegreesPerTurn * kTwoPi);
    }
    if (const auto& orbit = animation.orbit) {
        const double angleRad = computePeriodFraction(timeS, orbit->periodS) * kTwoPi;
        m = rotateAbout(orbit->centreW, orbit->axis, angleRad) * m;
    }
    glm::vec3 offsetM = animation.translateMPerS * static_cast<float>(timeS);
    if (const auto& osc = animation.oscillation) {
        const double turns = computePeriodFraction(timeS, osc->periodS) + osc->phase;
        offsetM += osc->amplitudeM * static_cast<float>(std::sin(turns * kTwoPi));
    }
    return glm::translate(glm::mat4(1.0f), offsetM) * m;
}

namespace {

// Hermite basis on s in [0, 1]: p(s) = h00 p0 + h10 m0 + h01 p1 + h11 m1 (tangents scaled by
// the segment's duration).
template <typename T>
T evaluateHermite(const T& p0, const T& m0, const T& p1, const T& m1, float s) {
    const float s2 = s * s;
    const float s3 = s2 * s;
    return (2.0f * s3 - 3.0f * s2 + 1.0f) * p0 + (s3 - 2.0f * s2 + s) * m0 +
           (-2.0f * s3 + 3.0f * s2) * p1 + (s3 - s2) * m1;
}

// The tangent (per second) at key i: the chord of its neighbours over their time, one-sided at
// the ends.
template <typename T>
T computeTangent(const std::vector<CameraKey>& keys, size_t i, T CameraKey::*field) {
    const size_t lo = i == 0 ? 0 : i - 1;
    const size_t hi = i + 1 == keys.size() ? i : i + 1;
    const auto dt = static_cast<float>(keys[hi].timeS - keys[lo].timeS);
    return (keys[hi].*field - keys[lo].*field) / dt;
}

// Shorter interpolated view directions (m) keep the nearer key's direction.
constexpr float kMinViewDistanceM = 1e-4f;

} // namespace

CameraPose evaluateCameraPath(const std::vector<CameraKey>& keys, double timeS) {
    const auto pose = [](const CameraKey& k) {
        return CameraPose{k.position, k.target, k.fovYDeg};
    };
    if (timeS <= keys.front().timeS) return pose(keys.front());
    if (timeS >= keys.back().timeS) return pose(keys.back());
    size_t i = 0;
    while (keys[i + 1].timeS <= timeS)
        ++i;
    const CameraKey& a = keys[i];
    const CameraKey& b = keys[i + 1];
    const double duration = b.timeS - a.timeS;
    const auto s = static_cast<float>((timeS - a.timeS) / duration);
    const auto d = static_cast<float>(duration);
    CameraPose p;
    p.position =
        evaluateHermite(a.position, d * computeTangent(keys, i, &CameraKey::position), b.position,
                        d * computeTangent(keys, i + 1, &CameraKey::position), s);
    p.target = evaluateHermite(a.target, d * computeTangent(keys, i, &CameraKey::target), b.target,
                               d * computeTangent(keys, i + 1, &CameraKey::target), s);
    p.fovYDeg = evaluateHermite(a.fovYDeg, d * computeTangent(keys, i, &CameraKey::fovYDeg),
                                b.fovYDeg, d * computeTangent(keys, i + 1, &CameraKey::fovYDeg), s);
    // The spline may overshoot a key's field of view slightly: keep it between the keys'.
    p.fovYDeg =
        std::clamp(p.fovYDeg, std::min(a.fovYDeg, b.fovYDeg), std::max(a.fovYDeg, b.fovYDeg));
    if (!(glm::length(p.target - p.position) > kMinViewDistanceM)) {
        const CameraKey& k = s < 0.5f ? a : b;
        p.target = p.position + (k.target - k.position);
    }
    return p;
}

bool Scene::isAnimated() const {
    if (!instanceAnimations.empty() || !camera.path.empty()) return true;
    for (const Light& light : lights) {
        if (light.animation) return true;
    }
    return false;
}

void Scene::update(double timeS) {
    if (!camera.path.empty()) {
        const CameraPose pose = evaluateCameraPath(camera.path, timeS);
        camera.position = pose.position;
        camera.target = pose.target;
        camera.fovYDeg = pose.fovYDeg;
    }
    for (const InstanceAnimation& a : instanceAnimations) {
        instances.at(a.instanceIndex).worldFromObject =
            computeAnimationTransform(a.animation, timeS) * a.baseWorldFromObject;
    }
    for (Light& light : lights) {
        if (!light.animation) continue;
        const glm::mat4 m = computeAnimationTransform(light.animation->animation, timeS);
        light.position = glm::vec3(m * glm::vec4(light.animation->basePositionW, 1.0f));
        // M is rigid: its linear part is a rotation, which keeps the direction unit length.
        light.direction = glm::normalize(glm::mat3(m) * light.animation->baseDirection);
    }
}

} // namespace ispm
