// FlyCamera: the scene camera's look-at form converted to yaw and pitch about its up axis.
#include "viewer/fly_camera.h"

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

constexpr float kSecondsToCrossScene = 4.0f;
constexpr float kRadiansPerPixel = 0.004f;  // a 400-pixel drag turns about 90 degrees
constexpr float kSpeedStepPerWheel = 1.25f; // multiplicative, so speeds span decades quickly
constexpr float kMaxPitchRad = 1.55f;       // just under 90 degrees: the basis stays defined
constexpr float kMinSpeedMps = 1e-4f;
constexpr float kMaxSpeedMps = 1e6f;

// Any unit vector perpendicular to `n`.
glm::vec3 computePerpendicular(const glm::vec3& n) {
    const glm::vec3 other = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(n, other));
}

} // namespace

FlyCamera::FlyCamera(const Camera& home, float sceneSizeM)
    : mHome(home), mHomeSpeedMps(std::max(sceneSizeM / kSecondsToCrossScene, kMinSpeedMps)),
      mSpeedMps(mHomeSpeedMps), mFocusM(1.0f) {
    Camera camera = home;
    reset(camera);
}

void FlyCamera::reset(Camera& camera) {
    camera = mHome;
    mSpeedMps = mHomeSpeedMps;
    mUp = glm::normalize(mHome.up);
    const glm::vec3 toTarget = mHome.target - mHome.position;
    mFocusM = std::max(glm::length(toTarget), 1e-3f);
    const glm::vec3 forward = toTarget / mFocusM;
    const glm::vec3 flat = forward - glm::dot(forward, mUp) * mUp;
    mAhead = glm::length(flat) > 1e-6f ? glm::normalize(flat) : computePerpendicular(mUp);
    mRight = glm::normalize(glm::cross(mAhead, mUp));
    mYawRad = 0.0f;
    mPitchRad = std::asin(std::clamp(glm::dot(forward, mUp), -1.0f, 1.0f));
}

glm::vec3 FlyCamera::computeForward() const {
    const glm::vec3 flat = std::cos(mYawRad) * mAhead + std::sin(mYawRad) * mRight;
    return std::cos(mPitchRad) * flat + std::sin(mPitchRad) * mUp;
}

void FlyCamera::update(const CameraInput& input, float seconds, Camera& camera) {
    if (input.wheel != 0.0f) {
        mSpeedMps = std::clamp(mSpeedMps * std::pow(kSpeedStepPerWheel, input.wheel), kMinSpeedMps,
                               kMaxSpeedMps);
    }
    // Drag right turns right; drag down looks down (window y grows downwards).
    mYawRad += input.dragPx.x * kRadiansPerPixel;
    mPitchRad =
        std::clamp(mPitchRad - input.dragPx.y * kRadiansPerPixel, -kMaxPitchRad, kMaxPitchRad);
    const glm::vec3 forward = computeForward();
    const glm::vec3 right = glm::normalize(glm::cross(forward, mUp));
    const glm::vec3 step = input.move.x * right + input.move.y * mUp + input.move.z * forward;
    camera.position += step * (mSpeedMps * seconds);
    camera.target = camera.position + forward * mFocusM;
    camera.up = mUp;
}

} // namespace ispm
