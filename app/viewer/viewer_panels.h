// The viewer's read-out and editing panels besides the settings: timings with a rolling plot,
// photon counts and the GL renderer; per-light editing.
#pragma once

#include "render/frame.h"
#include "scene/scene.h"

#include <deque>
#include <string>
#include <vector>

namespace ispm {

// The last frames' pass times, for the table and the rolling plot.
class TimingHistory {
  public:
    void record(const std::vector<PassTiming>& timings);
    const std::vector<PassTiming>& getLast() const { return mLast; }
    // The Stats table's "frame" row: the last frame's passes added up.
    double getLastTotalMs() const;
    std::vector<float> getFrameTotals() const { return {mTotals.begin(), mTotals.end()}; }

  private:
    std::vector<PassTiming> mLast;
    std::deque<float> mTotals;
};

// accumulatedFrames: frames averaged into the indirect light shown (setting `accumulate`).
void drawStatsPanel(const TimingHistory& timings, const PhotonCounts& counts,
                    const std::string& renderer, const char* timingMethod, float luminanceMax,
                    uint32_t accumulatedFrames);

enum class LightEdit { None, Values, AddedOrRemoved };

// Position, direction, intensity/irradiance and cone of every light; add (a point light at
// `newLightPositionW`) and remove. Drag speeds follow the scene's size and each light's power.
// Says what changed: values re-upload, added/removed rebuild.
LightEdit drawLightsPanel(std::vector<Light>& lights, const glm::vec3& newLightPositionW,
                          float sceneSizeM);

} // namespace ispm
