// The viewer's animation clock and its panel: play/pause, a time scrubber and the playback speed.
// The clock only says when the scene's time changed; the viewer then runs Scene::update and
// FrameRunner::updateScene, so a paused scene costs nothing per frame.
#pragma once

namespace ispm {

struct AnimationClock {
    double timeS = 0.0;        // scene time shown
    double appliedTimeS = 0.0; // the time the scene was last updated to (a loaded scene: 0)
    float speed = 1.0f;        // scene seconds per wall-clock second
    bool isPlaying = true;
};

// Advances a playing clock by `wallSeconds` x speed; true when the scene must be updated to
// clock.timeS (played, scrubbed or reset since the last call).
bool advanceAnimationClock(AnimationClock& clock, double wallSeconds);

// The panel's widgets (inside the caller's ImGui window).
void drawAnimationPanel(AnimationClock& clock);

} // namespace ispm
