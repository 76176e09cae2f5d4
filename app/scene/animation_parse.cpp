// The `animation` key of objects and lights (docs/scene-format.md, "Animation"): checked as
// strictly as the rest of the file, and a motion that could not change anything (a sun moved
// along a line, a point light turned about itself) is an error rather than silently ignored.
#include "core/input_error.h"
#include "scene/scene_parse.h"

namespace ispm {

namespace {

// Shorter periods are no motion any frame rate can show; the bound also keeps t / period finite.
constexpr double kMinPeriodS = 1e-6;

// Kept in double as written: a period of 0.7 in float would drift a whole turn off in ~10^5 s.
double readPeriod(const JsonNode& node) {
    return node.readNumber(NumberRange::getAtLeast(kMinPeriodS));
}

Orbit parseOrbit(const JsonNode& node, bool hasCentre) {
    if (hasCentre) {
        node.checkKeys({"centre", "axis", "period_s"}, "an orbit");
    } else {
        node.checkKeys({"axis", "period_s"}, "a sun's orbit (its direction turns: no centre)");
    }
    Orbit orbit;
    if (hasCentre) orbit.centreW = node.get("centre").readVec3();
    if (auto axis = node.find("axis")) orbit.axis = axis->readDirection();
    orbit.periodS = readPeriod(node.get("period_s"));
    return orbit;
}

Oscillation parseOscillation(const JsonNode& node) {
    node.checkKeys({"amplitude", "period_s", "phase"}, "an oscillation");
    Oscillation osc;
    osc.amplitudeM = node.get("amplitude").readVec3();
    osc.periodS = readPeriod(node.get("period_s"));
    // In periods: a bound of 1 catches phases written in degrees or radians.
    if (auto phase = node.find("phase")) osc.phase = phase->readFloat(NumberRange::getClosed(0, 1));
    return osc;
}

} // namespace

Animation parseAnimation(const JsonNode& node, AnimationTarget target,
                         const glm::vec3& defaultPivotW) {
    const bool isSun = target == AnimationTarget::SunLight;
    if (isSun) {
        node.checkKeys({"rotate_deg_per_s", "orbit"},
                       "a sun's animation (only its direction moves)");
    } else {
        node.checkKeys({"translate_per_s", "rotate_deg_per_s", "pivot", "orbit", "oscillate"},
                       "an animation");
    }
    if (node.getJson().empty()) {
        node.fail(isSun ? "at least one motion: rotate_deg_per_s or orbit"
                        : "at least one motion: translate_per_s, rotate_deg_per_s, orbit or "
                          "oscillate");
    }
    Animation animation;
    if (auto v = node.find("translate_per_s")) animation.translateMPerS = v->readVec3();
    animation.pivotW = defaultPivotW;
    const std::optional<JsonNode> rotate = node.find("rotate_deg_per_s");
    if (rotate) animation.rotateDegPerS = rotate->readVec3();
    if (auto pivot = node.find("pivot")) {
        if (!rotate) pivot->fail("a pivot only beside rotate_deg_per_s");
        animation.pivotW = pivot->readVec3();
    } else if (rotate && target == AnimationTarget::PointLight) {
        throwInputError(node.getFile(), node.getPath() + "/pivot",
                        "a pivot with rotate_deg_per_s on a point light (turning about its own "
                        "position would not move it)");
    }
    if (auto orbit = node.find("orbit")) animation.orbit = parseOrbit(*orbit, !isSun);
    if (auto osc = node.find("oscillate")) animation.oscillation = parseOscillation(*osc);
    return animation;
}

} // namespace ispm
