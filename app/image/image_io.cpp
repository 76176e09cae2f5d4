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

Image decodeExr(std::string_view bytes) {
    float* rgba = nullptr;
    int width = 0;
    int height = 0;
    const char* error = nullptr;
    const int result = LoadEXRFromMemory(&rgba, &width, &height,
                                         reinterpret_cast<const unsigned char*>(bytes.data()),
                                         bytes.size(), &error);
    if (result != TINYEXR_SUCCESS) {
        throwExrError("decoding", error);
    }
    std::unique_ptr<float, void (*)(void*)> owner(rgba, std::free);
    Image image(width, height);
    for (size_t i = 0; i < image.getPixelCount(); ++i) {
        const float* pixel = rgba + i * kRgbaChannels;
        image.pixels[i] = glm::vec3(pixel[0], pixel[1], pixel[2]);
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
