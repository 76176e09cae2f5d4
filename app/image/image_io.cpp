// File-level image I/O: picks the codec (extension when writing, signature when reading), does
// the file access in one place, and wraps stb (PNG) and tinyexr (EXR); PFM lives in pfm.cpp.
// Codecs work on memory buffers so that every failure is reported the same way.
#include "image/image_io.h"

#include "core/file_write.h"
#include "core/input_error.h"
#include "core/strings.h"
#include "image/pfm.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <system_error>

namespace ispm {
namespace {

constexpr int kRgbChannels = 3;       // an Image holds RGB; alpha is neither read nor written
constexpr int kRgbaChannels = 4;      // tinyexr's LoadEXR always returns RGBA
constexpr float kMax8Bit = 255.0f;    // largest 8-bit PNG sample
constexpr float kMax16Bit = 65535.0f; // largest 16-bit PNG sample
constexpr std::string_view kPngSignature = "\x89PNG\r\n\x1a\n";
constexpr std::string_view kExrSignature = "\x76\x2f\x31\x01"; // OpenEXR magic number 20000630
// Images narrower and shorter than this are stored uncompressed, as tinyexr's own SaveEXR does:
// ZIP gains nothing on a few pixels.
constexpr int kExrMinCompressedSizePx = 16;

std::string getLowerExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

// False when the file cannot be opened or read; the caller reports it as an InputError.
bool readFileBytes(const std::string& path, std::string& bytes) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return false; // a directory opens too
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    const std::streamoff size = file ? static_cast<std::streamoff>(file.tellg()) : -1;
    if (size < 0) { // not opened, or not seekable (a directory)
        return false;
    }
    bytes.resize(static_cast<size_t>(size));
    file.seekg(0);
    file.read(bytes.data(), static_cast<std::streamsize>(size));
    return static_cast<bool>(file);
}

uint8_t quantise8Bit(float value) {
    // NaN fails the comparison and becomes black: converting NaN to an integer is undefined.
    const float clamped = value > 0.0f ? std::min(value, 1.0f) : 0.0f;
    return static_cast<uint8_t>(std::lround(clamped * kMax8Bit));
}

std::string encodePng(const Image& image) {
    std::vector<uint8_t> samples;
    samples.reserve(image.getPixelCount() * kRgbChannels);
    for (const glm::vec3& pixel : image.pixels) {
        samples.push_back(quantise8Bit(pixel.r));
        samples.push_back(quantise8Bit(pixel.g));
        samples.push_back(quantise8Bit(pixel.b));
    }
    std::string out;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<size_t>(size));
    };
    const int strideBytes = image.width * kRgbChannels;
    if (stbi_write_png_to_func(append, &out, image.width, image.height, kRgbChannels,
                               samples.data(), strideBytes) == 0) {
        throw std::runtime_error("stb_image_write failed to encode the PNG");
    }
    return out;
}

template <typename Sample>
Image convertSamples(const Sample* samples, int width, int height, float maxSample) {
    Image image(width, height);
    for (size_t i = 0; i < image.getPixelCount(); ++i) {
        const Sample* rgb = samples + i * kRgbChannels;
        image.pixels[i] = glm::vec3(rgb[0], rgb[1], rgb[2]) / maxSample;
    }
    return image;
}

Image decodePng(std::string_view bytes) {
    if (bytes.size() > static_cast<size_t>(INT_MAX)) {
        throw std::runtime_error("file too large for stb_image");
    }
    const auto* buffer = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = static_cast<int>(bytes.size());
    int width = 0;
    int height = 0;
    int channelsInFile = 0;
    if (stbi_is_16_bit_from_memory(buffer, length) != 0) {
        std::unique_ptr<stbi_us, void (*)(void*)> samples(
            stbi_load_16_from_memory(buffer, length, &width, &height, &channelsInFile,
                                     kRgbChannels),
            stbi_image_free);
        if (samples) {
            return convertSamples(samples.get(), width, height, kMax16Bit);
        }
    } else {
        std::unique_ptr<stbi_uc, void (*)(void*)> samples(
            stbi_load_from_memory(buffer, length, &width, &height, &channelsInFile, kRgbChannels),
            stbi_image_free);
        if (samples) {
            return convertSamples(samples.get(), width, height, kMax8Bit);
        }
    }
    throw std::runtime_error(strCat("stb_image: ", stbi_failure_reason()));
}

// tinyexr reports errors through a string it allocated; this takes ownership of it.
[[noreturn]] void throwExrError(const char* stage, const char* message) {
    std::string reason = strCat("tinyexr: ", stage, ": ", message ? message : "unknown error");
    if (message) {
        FreeEXRErrorMessage(message);
    }
    // tinyexr ends its messages with a newline and may hold several: one line for the user.
    while (!reason.empty() && std::isspace(static_cast<unsigned char>(reason.back())))
        reason.pop_back();
    std::replace(reason.begin(), reason.end(), '\n', ';');
    throw std::runtime_error(reason);
}

std::string encodeExr(const Image& image) {
    // EXR viewers expect channels in alphabetical order: B, G, R.
    constexpr std::array<const char*, kRgbChannels> kChannelNames = {"B", "G", "R"};
    constexpr std::array<int, kRgbChannels> kPlaneOfChannel = {2, 1, 0};
    std::array<std::vector<float>, kRgbChannels> planes;
    for (int c = 0; c < kRgbChannels; ++c) {
        planes[c].reserve(image.getPixelCount());
        for (const glm::vec3& pixel : image.pixels) {
            planes[c].push_back(pixel[kPlaneOfChannel[c]]);
        }
    }
    std::array<unsigned char*, kRgbChannels> planePointers{};
    std::array<EXRChannelInfo, kRgbChannels> channelInfos{};
    std::array<int, kRgbChannels> pixelTypes{};
    for (int c = 0; c < kRgbChannels; ++c) {
        planePointers[c] = reinterpret_cast<unsigned char*>(planes[c].data());
        std::snprintf(channelInfos[c].name, sizeof channelInfos[c].name, "%s", kChannelNames[c]);
        pixelTypes[c] = TINYEXR_PIXELTYPE_FLOAT; // full 32-bit floats, never half
    }

    EXRImage exrImage;
    InitEXRImage(&exrImage);
    exrImage.images = planePointers.data();
    exrImage.width = image.width;
    exrImage.height = image.height;
    exrImage.num_channels = kRgbChannels;

    EXRHeader header;
    InitEXRHeader(&header);
    header.num_channels = kRgbChannels;
    header.channels = channelInfos.data();
    header.pixel_types = pixelTypes.data();           // type of the data handed over
    header.requested_pixel_types = pixelTypes.data(); // type stored in the file
    const bool isSmall =
        image.width < kExrMinCompressedSizePx && image.height < kExrMinCompressedSizePx;
    header.compression_type = isSmall ? TINYEXR_COMPRESSIONTYPE_NONE : TINYEXR_COMPRESSIONTYPE_ZIP;

    unsigned char* memory = nullptr;
    const char* error = nullptr;
    const size_t size = SaveEXRImageToMemory(&exrImage, &header, &memory, &error);
    // The header and image point at our arrays: no FreeEXRHeader/FreeEXRImage.
    if (size == 0 || memory == nullptr) {
        throwExrError("encoding", error);
    }
    std::string out(reinterpret_cast<const char*>(memory), size);
    std::free(memory);
    return out;
}

// tinyexr's LoadEXRFromMemory leaks the parsed header when the image data are corrupt; this is
// the same decoding with every allocation freed on every path: version, header (half channels
// read as float), image, then R, G and B (or one grey channel) from scanlines or tiles.
Image decodeExr(std::string_view bytes) {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    EXRVersion version;
    if (ParseEXRVersionFromMemory(&version, data, bytes.size()) != TINYEXR_SUCCESS) {
        throw std::runtime_error("tinyexr: decoding: not an OpenEXR version 2 file");
    }
    EXRHeader header;
    InitEXRHeader(&header);
    const auto freeHeader = [](EXRHeader* h) { FreeEXRHeader(h); };
    const std::unique_ptr<EXRHeader, decltype(freeHeader)> headerOwner(&header, freeHeader);
    const char* error = nullptr;
    if (ParseEXRHeaderFromMemory(&header, &version, data, bytes.size(), &error) !=
        TINYEXR_SUCCESS) {
        throwExrError("decoding", error);
    }
    for (int c = 0; c < header.num_channels; ++c) {
        if (header.pixel_types[c] == TINYEXR_PIXELTYPE_UINT) {
            throw std::runtime_error("tinyexr: decoding: expected half or float channels, got "
                                     "an integer channel");
        }
        header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
    }
    EXRImage exr;
    InitEXRImage(&exr);
    // On failure tinyexr frees what it loaded of the image itself (freeing it again would free
    // twice); on success the image is ours.
    if (LoadEXRImageFromMemory(&exr, &header, data, bytes.size(), &error) != TINYEXR_SUCCESS) {
        throwExrError("decoding", error);
    }
    const auto freeImage = [](EXRImage* i) { FreeEXRImage(i); };
    const std::unique_ptr<EXRImage, decltype(freeImage)> imageOwner(&exr, freeImage);
    // The channel each of R, G, B comes from: by name, or the only channel for all three.
    std::array<int, kRgbChannels> source = {-1, -1, -1};
    for (int c = 0; c < header.num_channels; ++c) {
        const std::string_view name = header.channels[c].name;
        if (name == "R") source[0] = c;
        if (name == "G") source[1] = c;
        if (name == "B") source[2] = c;
    }
    if (header.num_channels == 1) source = {0, 0, 0};
    if (std::find(source.begin(), source.end(), -1) != source.end()) {
        throw std::runtime_error("tinyexr: decoding: expected R, G and B channels or one channel");
    }
    Image image(exr.width, exr.height);
    const auto put = [&](int x, int y, float* const* planes, size_t at) {
        if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
        image.at(x, y) =
            glm::vec3(planes[source[0]][at], planes[source[1]][at], planes[source[2]][at]);
    };
    if (header.tiled) {
        for (int t = 0; t < exr.num_tiles; ++t) {
            const EXRTile& tile = exr.tiles[t];
            auto* const* planes = reinterpret_cast<float* const*>(tile.images);
            for (int j = 0; j < tile.height; ++j) {
                for (int i = 0; i < tile.width; ++i) {
                    put(tile.offset_x * header.tile_size_x + i,
                        tile.offset_y * header.tile_size_y + j, planes,
                        size_t(j) * size_t(header.tile_size_x) + size_t(i));
                }
            }
        }
    } else {
        auto* const* planes = reinterpret_cast<float* const*>(exr.images);
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x)
                put(x, y, planes, size_t(y) * size_t(image.width) + size_t(x));
        }
    }
    return image;
}

} // namespace

ImageFormat getImageFormatFromPath(const std::string& path) {
    const std::string extension = getLowerExtension(path);
    if (extension == ".png") {
        return ImageFormat::Png;
    }
    if (extension == ".pfm") {
        return ImageFormat::Pfm;
    }
    if (extension == ".exr") {
        return ImageFormat::Exr;
    }
    throw InputError(strCat(path, ": expected an image file name ending in .png, .pfm or .exr"));
}

bool isLinearImageFormat(ImageFormat format) {
    return format != ImageFormat::Png;
}

void writeImage(const std::string& path, const Image& image) {
    const ImageFormat format = getImageFormatFromPath(path);
    if (image.isEmpty()) {
        throw std::runtime_error(
            strCat(path, ": cannot write an empty (", image.width, "x", image.height, ") image"));
    }
    std::string bytes;
    try {
        switch (format) {
        case ImageFormat::Png:
            bytes = encodePng(image);
            break;
        case ImageFormat::Pfm:
            bytes = encodePfm(image);
            break;
        case ImageFormat::Exr:
            bytes = encodeExr(image);
            break;
        }
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(strCat(path, ": ", e.what()));
    }
    try {
        writeFileWhole(path, bytes);
    } catch (const std::runtime_error&) {
        throw std::runtime_error(strCat(path, ": cannot write the image file"));
    }
}

Image readImage(const std::string& path) {
    const auto fail = [&path](std::string_view reason) {
        return InputError(strCat(path, ": expected a PNG/PFM/EXR image (", reason, ")"));
    };
    std::string bytes;
    if (!readFileBytes(path, bytes)) {
        std::error_code ignored; // exists() without it throws on, say, a permission error
        const bool exists = std::filesystem::exists(path, ignored);
        const bool folder = std::filesystem::is_directory(path, ignored);
        throw fail(folder   ? "a folder, not a file"
                   : exists ? "cannot read the file"
                            : "no such file");
    }
    try {
        if (bytes.starts_with(kPngSignature)) {
            return decodePng(bytes);
        }
        if (bytes.starts_with(kExrSignature)) {
            return decodeExr(bytes);
        }
        if (isPfm(bytes)) {
            return decodePfm(bytes);
        }
    } catch (const std::runtime_error& e) {
        throw fail(e.what());
    }
    throw fail(bytes.empty() ? "the file is empty" : "unrecognised file signature");
}

} // namespace ispm
