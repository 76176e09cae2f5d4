// A fly camera over the scene's pinhole camera: yaw about the scene camera's up axis, pitch toward
// it, moves along the view axes. Pure maths (no GL, no window), so scripted input and tests drive
// it exactly as the keyboard and mouse do.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

namespace ispm {

// What the user asked of the camera during one frame.
struct CameraInput {
    glm::vec3 move{0.0f};   // right, up, forward in [-1, 1] (D/A, E/Q, W/S)
    glm::vec2 dragPx{0.0f}; // mouse drag with the left button, window pixels (y down)
    float wheel = 0.0f;     // scroll steps: speed up (> 0) or down
};

class FlyCamera {
  public:
    // `sceneSizeM` sets the initial speed: crossing the scene takes a few seconds.
    FlyCamera(const Camera& home, float sceneSizeM);

    // Moves by speed x seconds along the input and turns by the drag; writes into `camera`.
    void update(const CameraInput& input, float seconds, Camera& camera);
    void reset(Camera& camera);

    float getSpeed() const { return mSpeedMps; }
    void setSpeed(float metresPerSecond) { mSpeedMps = metresPerSecond; }
    float getYawRad() const { return mYawRad; }
    float getPitchRad() const { return mPitchRad; }

  private:
    glm::vec3 computeForward() const;

    Camera mHome;
    float mHomeSpeedMps;
    float mSpeedMps;
    float mFocusM; // distance from position to target, kept so `target` stays a sensible point
    glm::vec3 mUp;
    glm::vec3 mAhead; // horizontal forward at yaw 0
    glm::vec3 mRight; // horizontal right at yaw 0
    float mYawRad = 0.0f;
    float mPitchRad = 0.0f;
};

} // namespace ispm
