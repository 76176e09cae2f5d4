// Animation of instances, lights and the camera (docs/scene-format.md, "Animation"): motions
// that are pure functions of time, applied in world space after an object's static transform (a
// camera follows a path of keys), so the same time always gives the same scene. No GL, no JSON:
// the loader fills these, Scene::update applies them.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace ispm {

// A rigid turn about the axis through `centreW`, once per period (a moon facing its planet).
struct Orbit {
    glm::vec3 centreW{0.0f};
    glm::vec3 axis{0.0f, 1.0f, 0.0f}; // unit; right-hand rule gives the sense of the turn
    double periodS = 1.0;             // > 0
};

// offset(t) = amplitude * sin(2 pi (t / period + phase)).
struct Oscillation {
    glm::vec3 amplitudeM{0.0f};
    double periodS = 1.0; // > 0
    double phase = 0.0;   // in periods, [0, 1]
};

// The motions compose as  M(t) = Translate(t) * Oscillate(t) * Orbit(t) * Rotate(t)  and a point
// of the object moves as  p(t) = M(t) * worldFromObject * p.  Every part is the identity at t = 0
// except an oscillation with a non-zero phase.
struct Animation {
    glm::vec3 translateMPerS{0.0f};
    // Angular velocity: the axis is the vector's direction, its length the rate in degrees/s.
    glm::vec3 rotateDegPerS{0.0f};
    glm::vec3 pivotW{0.0f}; // the rotation's centre
    std::optional<Orbit> orbit;
    std::optional<Oscillation> oscillation;
};

// M(t) above: a rigid motion of world space (rotation and translation only).
glm::mat4 computeAnimationTransform(const Animation& animation, double timeS);

// An animated instance: its transform at time t is M(t) * baseWorldFromObject.
struct InstanceAnimation {
    uint32_t instanceIndex = 0;
    glm::mat4 baseWorldFromObject{1.0f};
    Animation animation;
};

// An animated light: position M(t) * basePosition, direction rotated by M(t)'s rotation.
struct LightAnimation {
    glm::vec3 basePositionW{0.0f};
    glm::vec3 baseDirection{0.0f, -1.0f, 0.0f};
    Animation animation;
};

// A keyframe of a camera path: where the camera is and looks at `timeS`.
struct CameraKey {
    double timeS = 0.0;
    glm::vec3 position{0.0f};
    glm::vec3 target{0.0f};
    float fovYDeg = 45.0f; // full vertical field of view
};

// The camera at time t on a path of >= 2 keys with increasing times: position, target and field
// of view each follow a cubic Hermite spline through the keys (tangents from the neighbouring
// keys, Catmull-Rom on the keys' own times, one-sided at the ends), so speed and turn change
// smoothly; before the first key and after the last the camera rests there. Where the
// interpolated target would meet the position, the view direction of the nearer key is kept.
struct CameraPose {
    glm::vec3 position{0.0f};
    glm::vec3 target{0.0f};
    float fovYDeg = 45.0f;
};
CameraPose evaluateCameraPath(const std::vector<CameraKey>& keys, double timeS);

} // namespace ispm
