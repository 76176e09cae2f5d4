// Animation transforms and Scene::update. Angles are reduced to one turn in double precision
// before they become float, so a periodic motion returns to its start exactly after each period
// and long play times keep their precision.
#include "scene/animation.h"

#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>

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

bool Scene::isAnimated() const {
    if (!instanceAnimations.empty()) return true;
    for (const Light& light : lights) {
        if (light.animation) return true;
    }
    return false;
}

void Scene::update(double timeS) {
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
