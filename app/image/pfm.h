// The Portable Float Map codec on byte buffers (no file access, so tests can check the exact
// bytes). Written as the format's standard has it: "PF", scale -1 (little-endian), rows bottom
// to top.
#pragma once

#include "image/image.h"

#include <string>
#include <string_view>

namespace ispm {

// "PF\n<w> <h>\n-1.0\n" followed by little-endian float RGB, bottom row first.
std::string encodePfm(const Image& image);

// Reads colour ("PF") and greyscale ("Pf") maps of either byte order, bottom row first, and
// multiplies by |scale| when it is not 1 (as pbrt-v4 does; the standard defines it as a scale).
// Throws std::runtime_error with the reason (no file name: the caller adds it).
Image decodePfm(std::string_view bytes);

// True when the bytes start like a PFM file.
bool isPfm(std::string_view bytes);

} // namespace ispm
