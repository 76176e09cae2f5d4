// Portable Float Map encoder and decoder. The header is text ("PF" or "Pf", width, height, scale,
// separated by whitespace, one whitespace byte before the data); the sign of the scale gives the
// byte order of the 32-bit floats that follow, rows from the bottom of the image to the top.
#include "image/pfm.h"

#include "core/strings.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace ispm {
namespace {

constexpr size_t kBytesPerFloat = 4;
constexpr size_t kRgbChannels = 3; // an Image holds RGB; "PF" stores all three
constexpr size_t kBitsPerByte = 8;
constexpr uint32_t kByteMask = 0xffu;
constexpr size_t kMagicLength = 2; // "PF" or "Pf"
// Dimensions beyond this are a corrupt header, not a render (GL textures stop far below it);
// the bound also keeps width * height * 12 bytes far from overflowing size_t.
constexpr int kMaxDimensionPx = 1 << 20;

bool isPfmSpace(char c) {
    return c == ' ' || c == '\n' || c == '\r' || c == '\t';
}

// Walks the text header token by token; `pos` ends on the byte after the last token read.
class HeaderReader {
  public:
    explicit HeaderReader(std::string_view bytes) : mBytes(bytes), mPos(kMagicLength) {}

    std::string_view readToken(const char* what) {
        while (mPos < mBytes.size() && isPfmSpace(mBytes[mPos])) {
            ++mPos;
        }
        const size_t start = mPos;
        while (mPos < mBytes.size() && !isPfmSpace(mBytes[mPos])) {
            ++mPos;
        }
        if (start == mPos) {
            throw std::runtime_error(strCat("header ends before the ", what));
        }
        return mBytes.substr(start, mPos - start);
    }

    template <typename T> T readNumber(const char* what) {
        const std::string_view token = readToken(what);
        T value{};
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (ec != std::errc() || end != token.data() + token.size()) {
            throw std::runtime_error(strCat("bad ", what, " '", token, "' in header"));
        }
        return value;
    }

    // The standard puts exactly one whitespace byte between the scale and the pixel data.
    size_t getDataOffset() const {
        if (mPos >= mBytes.size() || !isPfmSpace(mBytes[mPos])) {
            throw std::runtime_error("no whitespace byte after the scale");
        }
        return mPos + 1;
    }

  private:
    std::string_view mBytes;
    size_t mPos;
};

void appendLittleEndian(std::string& out, float value) {
    uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    for (size_t i = 0; i < kBytesPerFloat; ++i) {
        out.push_back(static_cast<char>((bits >> (i * kBitsPerByte)) & kByteMask));
    }
}

float readFloat(const char* bytes, bool littleEndian) {
    uint32_t bits = 0;
    for (size_t i = 0; i < kBytesPerFloat; ++i) {
        const uint32_t byte = static_cast<unsigned char>(bytes[i]);
        const size_t shift = littleEndian ? i : kBytesPerFloat - 1 - i;
        bits |= byte << (shift * kBitsPerByte);
    }
    float value = 0.0f;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

} // namespace

bool isPfm(std::string_view bytes) {
    return bytes.size() >= kMagicLength && bytes[0] == 'P' && (bytes[1] == 'F' || bytes[1] == 'f');
}

std::string encodePfm(const Image& image) {
    std::string out = strCat("PF\n", image.width, " ", image.height, "\n-1.0\n");
    out.reserve(out.size() + image.getPixelCount() * kRgbChannels * kBytesPerFloat);
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3& pixel = image.at(x, y);
            appendLittleEndian(out, pixel.r);
            appendLittleEndian(out, pixel.g);
            appendLittleEndian(out, pixel.b);
        }
    }
    return out;
}

Image decodePfm(std::string_view bytes) {
    if (!isPfm(bytes)) {
        throw std::runtime_error("no 'PF' or 'Pf' signature");
    }
    const size_t channels = bytes[1] == 'F' ? kRgbChannels : 1;
    HeaderReader header(bytes);
    const int width = header.readNumber<int>("width");
    const int height = header.readNumber<int>("height");
    const float scale = header.readNumber<float>("scale");
    const size_t dataOffset = header.getDataOffset();
    if (width <= 0 || height <= 0 || width > kMaxDimensionPx || height > kMaxDimensionPx) {
        throw std::runtime_error(strCat("bad size ", width, "x", height, " in header"));
    }
    if (!std::isfinite(scale) || scale == 0.0f) {
        throw std::runtime_error(strCat("bad scale ", scale, " in header"));
    }

    // Checked before the image is allocated: a header may claim far more than the file holds.
    const size_t dataSize = size_t(width) * size_t(height) * channels * kBytesPerFloat;
    if (bytes.size() - dataOffset < dataSize) {
        throw std::runtime_error(strCat("truncated: ", width, "x", height, " needs ", dataSize,
                                        " bytes of pixels, the file has ",
                                        bytes.size() - dataOffset));
    }
    Image image(width, height);

    const bool littleEndian = scale < 0.0f;
    const float magnitude = std::abs(scale);
    const char* data = bytes.data() + dataOffset;
    for (int y = height - 1; y >= 0; --y) {
        for (int x = 0; x < width; ++x) {
            glm::vec3& pixel = image.at(x, y);
            for (size_t c = 0; c < kRgbChannels; ++c) {
                // Greyscale maps repeat their one channel.
                const size_t channel = channels == 1 ? 0 : c;
                pixel[static_cast<glm::length_t>(c)] =
                    readFloat(data + channel * kBytesPerFloat, littleEndian);
            }
            data += channels * kBytesPerFloat;
            if (magnitude != 1.0f) {
                pixel *= magnitude;
            }
        }
    }
    return image;
}

} // namespace ispm
