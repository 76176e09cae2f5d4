// The viewer's windows over the scene region: the frame-rate overlay (F2) in its top-left corner
// and the keys' help (F1) in the middle of the window. Inside an ImGui frame.
#pragma once

#include "viewer/frame_pacer.h"

namespace ispm {

// The UI's rate (it keeps its own, FramePacer) and the rendered frames' (drawn in slices), over
// the image of the region [0, regionWidth) x [0, regionHeight); nothing before both are known.
void drawFrameRateOverlay(const FramePacer& pacer, int regionWidth, int regionHeight);
// What the keys and the mouse do, centred in the window; its close button clears `isOpen`.
void drawHelpWindow(bool& isOpen, int windowWidth, int windowHeight);

} // namespace ispm
