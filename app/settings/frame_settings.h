// FrameSettings: the settings table resolved for a frame, once per change. Every value a pass
// reads is a typed field here, derived values filled in (splat neighbours, filter iterations,
// the splat buffer's size); passes never look settings up by name. Enum fields hold the
// constants of shaders/shared/ that the shaders compare against, and the table's choices are
// checked against those constants at compile time (frame_settings.cpp).
#pragma once

#include "settings/setting_choices.h"
#include "settings/settings.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>

namespace ispm {

struct FrameSettings {
    int width = 0;  // px
    int height = 0; // px
    // Tone mapping.
    uint32_t toneMap = 0; // gpu::kTonemap*
    float exposureStops = 0.0f;
    float gamma = 2.2f;
    std::optional<float> luminanceMax; // W/(m^2 sr); derived on the GPU when not set
    float eyeAdaptationS = 0.0f;       // time constant of the derived white point; 0 = at once
    // Lights and shadows.
    int shadowMapSize = 0; // px
    float shadowBiasTexels = 0.0f;
    uint32_t shadows = 0; // gpu::kShadowsMap, kShadowsRay
    int edgeSamples = 0;  // rays per pixel where the direct light changes inside it; 0: off
    int areaSamples = 8;  // emitter samples per pixel for direct light (each a shadow ray)
    // Photons.
    uint32_t seed = 0;
    int photons = 0;
    float frameMsTarget = 0.0f; // 0: the budget as set
    int bounces = 0;
    uint32_t firstBounce = 0; // gpu::kFirstBounceRoulette, kFirstBounceWeighted
    // Levels of mirror and refraction rays traced from viewer pixels (SpecularPass); 0: off.
    int specularDepth = 0;
    bool bouncesSet = false;      // the reference path tracer has its own default
    uint32_t referenceMethod = 0; // gpu::kReferencePath, kReferenceLight
    float importance = 0.0f;      // aimed share; 0 when importanceSamples is 0
    int importanceSamples = 0;
    int importanceFrames = 1;  // frames the maps average (ImportancePass)
    uint32_t rngGenerator = 0; // gpu::kRngPcg, kRngLcg, kRngSobol
    uint32_t rngMode = 0;      // gpu::kRngFixed, kRngPerFrame, kRngObjectSpace
    // Splats.
    uint32_t radiusMode = 0; // gpu::kRadius*
    int splatNeighbours = 0; // derived: 0.45 sqrt(photons), 16 to 256
    float splatMerge = 0.0f; // merge cell side / radius (radius_mode density); 0: off
    // As set (metres, before radius_scale); the passes derive the rest from the scene.
    std::optional<float> radiusMinM;
    std::optional<float> radiusMaxM;
    std::optional<float> distMinM;
    std::optional<float> distMaxM;
    float radiusScale = 1.0f;
    float squash = 0.0f;
    int splatPasses = 1;
    uint32_t splatShape = 0;   // gpu::kSplatShape*
    uint32_t splatMode = 0;    // gpu::kSplatMode*
    bool splatClip = false;    // discs cut at the surfaces their plane meets (clip lines)
    bool surfaceEnds = false;  // without clip lines: power over the disc's share on a surface
    bool widenStrong = false;  // travel modes (never density): strong photons widened
    int splatDivisor = 1;      // image pixels per splat-buffer pixel along an axis (1, 2, 4)
    glm::ivec2 splatSize{0};   // the splat buffer: the image divided, rounded up
    int denoiseIterations = 0; // derived from the splat buffer's size
    int accumulate = 0;        // history length in frames (0: off)
    // Post-processing (PostPass); each 0 = off.
    float motionBlurShutter = 0.0f; // fraction of a frame
    float dofApertureM = 0.0f;      // lens diameter
    std::optional<float> dofFocusM; // derived on the GPU (the image centre's depth)
    float bloomIntensity = 0.0f;    // share of the light above the threshold spread
    float bloomThreshold = 0.0f;    // luminance, W/(m^2 sr)
    float bloomRadiusPx = 0.0f;     // 3 sigma

    bool hasMotionBlur() const { return motionBlurShutter > 0.0f; }
    bool hasDepthBlur() const { return dofApertureM > 0.0f; }
    bool hasBloom() const { return bloomIntensity > 0.0f; }
    bool hasPost() const { return hasMotionBlur() || hasDepthBlur() || hasBloom(); }

    bool hasIndirect() const { return bounces > 0 && photons > 0; }
};

FrameSettings resolveFrameSettings(const Settings& settings);
// frame_ms_target's adapted budget (FrameBudget) over the settings' photons: `photons` and the
// values derived from them (splat neighbours, the derived shadow_map_size), the rest as resolved.
void applyPhotonBudget(FrameSettings& frame, const Settings& settings, int photons);

// The derivations, also for the viewer's "auto" labels.
int computeSplatNeighbours(const Settings& settings);
// With `photons` in place of the setting's (applyPhotonBudget).
int computeSplatNeighbours(const Settings& settings, double photons);
int computeSplatDivisor(const Settings& settings, int width, int height);
glm::ivec2 computeSplatSize(const Settings& settings, int width, int height);
int computeDenoiseIterations(const Settings& settings, int width, int height);
int computeShadowMapSize(const Settings& settings);
int computeShadowMapSize(const Settings& settings, double photons);
bool computeSplatClip(const Settings& settings);
// surface_ends as it applies: never with clip lines (they renormalise per pixel instead).
bool computeSurfaceEnds(const Settings& settings);

} // namespace ispm
