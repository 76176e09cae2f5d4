// Screenshots of the viewer window: the default framebuffer's back buffer (UI included) read
// back after the frame is drawn and before it is presented.
#pragma once

#include "image/image.h"

#include <string>

namespace ispm {

// Rows are flipped to Image order (row 0 at the top).
Image readWindowImage(int width, int height);
void writeScreenshot(const std::string& path, int width, int height);

} // namespace ispm
