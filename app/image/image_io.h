// Reading and writing images: PFM and EXR carry linear float radiance, PNG carries display-encoded
// 8-bit values that were tone mapped before writing. Writers choose the format by extension,
// readers by the file's signature.
#pragma once

#include "image/image.h"

#include <string>

namespace ispm {

enum class ImageFormat { Png, Pfm, Exr };

// The format named by the path's extension (.png, .pfm, .exr, any case). Throws InputError naming
// the path and the accepted extensions for anything else.
ImageFormat getImageFormatFromPath(const std::string& path);

// True for formats that store linear float values (PFM, EXR); PNG expects tone-mapped input.
bool isLinearImageFormat(ImageFormat format);

// Writes by extension: PFM (little-endian, rows bottom to top), EXR (32-bit float RGB, ZIP),
// PNG (values clamped to [0,1] and rounded to 8 bits, no gamma applied here).
// Throws InputError for an unknown extension, std::runtime_error naming the path on I/O failure.
void writeImage(const std::string& path, const Image& image);

// Reads PNG (8 or 16 bit, to [0,1] as stored: no linearisation), PFM (colour or greyscale, either
// byte order) and EXR (RGB or single channel; alpha is dropped). Greyscale fills all three
// channels. Throws InputError "path: expected a PNG/PFM/EXR image (reason)" for a missing,
// unreadable, unrecognised or corrupt file.
// PNG rows are read top first: stb's global vertical-flip flag must stay off (its default).
Image readImage(const std::string& path);

} // namespace ispm
