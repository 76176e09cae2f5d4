// Image file I/O: bit-exact float round trips at awkward sizes, PFM's byte layout as the standard
// has it, PNG quantisation, and user-facing errors that name the file.
#include "core/input_error.h"
#include "image/image_io.h"
#include "image/pfm.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

namespace ispm {
namespace {

constexpr float kRandomRange = 1000.0f; // radiance-like magnitudes, both signs
// PNG stores round(v * 255): the read-back value is off by at most half a step.
constexpr float kPngTolerance = 0.5f / 255.0f + 1e-6f;

// A file name unique to the running test, so that tests run in parallel by ctest do not collide.
std::string getTempPath(const std::string& suffix) {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("ispm_") + info->test_suite_name() + "_" + info->name();
    std::replace(name.begin(), name.end(), '/', '_'); // parameterised tests have '/' in names
    return testing::TempDir() + name + suffix;
}

Image makeRandomImage(int width, int height, float minValue, float maxValue, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> dist(minValue, maxValue);
    Image image(width, height);
    for (glm::vec3& pixel : image.pixels) {
        pixel = glm::vec3(dist(rng), dist(rng), dist(rng));
    }
    return image;
}

void expectBitExact(const Image& actual, const Image& expected) {
    ASSERT_EQ(actual.width, expected.width);
    ASSERT_EQ(actual.height, expected.height);
    for (size_t i = 0; i < expected.getPixelCount(); ++i) {
        ASSERT_EQ(std::memcmp(&actual.pixels[i], &expected.pixels[i], sizeof(glm::vec3)), 0)
            << "pixel " << i << " differs";
    }
}

std::string readBytes(const std::string& path) {
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    std::string bytes(static_cast<size_t>(file.tellg()), '\0');
    file.seekg(0);
    file.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return bytes;
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file << bytes;
}

// Runs `action`, expects an InputError whose message names `path`.
template <typename Action> void expectInputErrorNaming(const std::string& path, Action&& action) {
    try {
        action();
        ADD_FAILURE() << "expected an InputError for " << path;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
}

std::string encodeFloat(float value, bool littleEndian) {
    uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    std::string bytes(4, '\0');
    for (int i = 0; i < 4; ++i) {
        const int shift = 8 * (littleEndian ? i : 3 - i);
        bytes[static_cast<size_t>(i)] = static_cast<char>((bits >> shift) & 0xffu);
    }
    return bytes;
}

class FloatRoundTripTest : public testing::TestWithParam<std::string> {};

TEST_P(FloatRoundTripTest, IsBitExactAtAwkwardSizes) {
    const struct { int width, height; } sizes[] = {{1, 1}, {7, 3}, {33, 17}};
    uint32_t seed = 1;
    for (const auto& size : sizes) {
        const Image image =
            makeRandomImage(size.width, size.height, -kRandomRange, kRandomRange, seed++);
        const std::string path = getTempPath(GetParam());
        writeImage(path, image);
        SCOPED_TRACE(testing::Message() << size.width << "x" << size.height);
        expectBitExact(readImage(path), image);
        std::filesystem::remove(path);
    }
}

INSTANTIATE_TEST_SUITE_P(LinearFormats, FloatRoundTripTest, testing::Values(".pfm", ".exr"),
                         [](const auto& paramInfo) { return paramInfo.param.substr(1); });

TEST(PfmTest, WritesStandardHeaderAndBottomRowFirstLittleEndian) {
    Image image(2, 3);
    image.at(0, 2) = glm::vec3(1.5f, -2.25f, 3.0e-7f); // bottom-left
    image.at(1, 2) = glm::vec3(4.0f, 5.0f, 6.0f);
    image.at(0, 0) = glm::vec3(7.0f, 8.0f, 9.0f); // top-left
    const std::string path = getTempPath(".pfm");
    writeImage(path, image);
    const std::string bytes = readBytes(path);

    const std::string header = "PF\n2 3\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 2 * 3 * 3 * sizeof(float));
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    const glm::vec3 firstRow[] = {image.at(0, 2), image.at(1, 2)};
    std::string expectedFirstRow;
    for (const glm::vec3& pixel : firstRow) {
        for (int c = 0; c < 3; ++c) {
            expectedFirstRow += encodeFloat(pixel[c], true);
        }
    }
    EXPECT_EQ(bytes.substr(header.size(), expectedFirstRow.size()), expectedFirstRow);
    std::filesystem::remove(path);
}

TEST(PfmTest, ReadsBigEndianGreyscaleBottomRowFirst) {
    const std::string bytes =
        "Pf\n1 2\n1.0\n" + encodeFloat(0.25f, false) + encodeFloat(4.0f, false);
    const Image image = decodePfm(bytes);
    ASSERT_EQ(image.width, 1);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.at(0, 1), glm::vec3(0.25f)); // first stored = bottom
    EXPECT_EQ(image.at(0, 0), glm::vec3(4.0f));
}

TEST(PfmTest, AppliesScaleMagnitude) {
    const std::string bytes = "PF 1 1 -2.0\n" + encodeFloat(1.0f, true) + encodeFloat(2.0f, true) +
                              encodeFloat(3.0f, true);
    EXPECT_EQ(decodePfm(bytes).at(0, 0), glm::vec3(2.0f, 4.0f, 6.0f));
}

TEST(PfmTest, RejectsBadHeaders) {
    EXPECT_THROW(decodePfm("PF\n0 1\n-1.0\n"), std::runtime_error);
    EXPECT_THROW(decodePfm("PF\n1 1\n0\n" + std::string(12, '\0')), std::runtime_error);
    EXPECT_THROW(decodePfm("PF\n1 x\n-1.0\n" + std::string(12, '\0')), std::runtime_error);
    EXPECT_THROW(decodePfm("PF\n1 1"), std::runtime_error);
}

TEST(PngTest, RoundTripsWithinHalfAStep) {
    const Image image = makeRandomImage(7, 5, 0.0f, 1.0f, 7);
    const std::string path = getTempPath(".png");
    writeImage(path, image);
    const Image read = readImage(path);
    ASSERT_EQ(read.width, image.width);
    ASSERT_EQ(read.height, image.height);
    for (size_t i = 0; i < image.getPixelCount(); ++i) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(read.pixels[i][c], image.pixels[i][c], kPngTolerance) << "pixel " << i;
        }
    }
    std::filesystem::remove(path);
}

TEST(PngTest, ClampsOutOfRangeAndNan) {
    Image image(2, 1);
    image.at(0, 0) = glm::vec3(-1.0f, 2.0f, std::numeric_limits<float>::quiet_NaN());
    image.at(1, 0) = glm::vec3(std::numeric_limits<float>::infinity(), 0.0f, 1.0f);
    const std::string path = getTempPath(".png");
    writeImage(path, image);
    const Image read = readImage(path);
    EXPECT_EQ(read.at(0, 0), glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(read.at(1, 0), glm::vec3(1.0f, 0.0f, 1.0f));
    std::filesystem::remove(path);
}

TEST(ImageIoTest, ExtensionIsCaseInsensitive) {
    const Image image = makeRandomImage(3, 2, 0.0f, 1.0f, 3);
    const std::string path = getTempPath(".PfM");
    writeImage(path, image);
    expectBitExact(readImage(path), image);
    std::filesystem::remove(path);
}

TEST(ImageIoTest, UnknownExtensionNamesPathAndAcceptedOnes) {
    const std::string path = getTempPath(".jpg");
    try {
        writeImage(path, Image(1, 1));
        ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path), std::string::npos) << message;
        EXPECT_NE(message.find(".png"), std::string::npos) << message;
        EXPECT_NE(message.find(".pfm"), std::string::npos) << message;
        EXPECT_NE(message.find(".exr"), std::string::npos) << message;
    }
    EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(ImageIoTest, UnwritablePathIsARuntimeErrorNamingIt) {
    const std::string path = getTempPath("_no_such_dir/out.pfm");
    try {
        writeImage(path, Image(1, 1));
        ADD_FAILURE() << "expected a runtime_error";
    } catch (const InputError& e) {
        ADD_FAILURE() << "an I/O failure is not an input error: " << e.what();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
}

TEST(ImageIoTest, AFailedWriteKeepsWhatWasThere) {
    // The target is a folder with a file in it: the image cannot take its place, so the write
    // fails, and neither the folder nor its file nor a temporary file is left changed.
    const std::string folder = getTempPath("_target.pfm");
    std::filesystem::create_directories(folder);
    writeBytes(folder + "/kept.txt", "kept");
    EXPECT_THROW(writeImage(folder, Image(2, 2)), std::runtime_error);
    EXPECT_EQ(readBytes(folder + "/kept.txt"), "kept");
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(folder).parent_path())) {
        EXPECT_EQ(entry.path().string().find(folder + ".tmp"), std::string::npos)
            << entry.path() << " left behind";
    }
    std::filesystem::remove_all(folder);
    // A good write replaces an older image whole.
    const std::string path = getTempPath(".pfm");
    writeImage(path, makeRandomImage(8, 8, 0.0f, 1.0f, 1));
    const Image second = makeRandomImage(3, 5, 0.0f, 1.0f, 2);
    writeImage(path, second);
    EXPECT_EQ(readImage(path).pixels, second.pixels);
    std::filesystem::remove(path);
}

TEST(ImageIoTest, FolderAndOversizedHeaderAreInputErrors) {
    const std::string folder = getTempPath("_folder");
    std::filesystem::create_directories(folder);
    expectInputErrorNaming(folder, [&] { readImage(folder); }); // was std::bad_alloc
    std::filesystem::remove_all(folder);
    // A header claiming 1048576 x 100 pixels over a few bytes: refused before any allocation.
    const std::string path = getTempPath(".pfm");
    writeBytes(path, "PF\n1048576 100\n-1.0\nabc");
    expectInputErrorNaming(path, [&] { readImage(path); });
    std::filesystem::remove(path);
}

TEST(ImageIoTest, MissingFileIsAnInputErrorNamingIt) {
    const std::string path = getTempPath("_missing.exr");
    expectInputErrorNaming(path, [&] { readImage(path); });
}

TEST(ImageIoTest, TruncatedPfmIsAnInputErrorNamingIt) {
    const std::string path = getTempPath(".pfm");
    writeImage(path, makeRandomImage(4, 4, 0.0f, 1.0f, 4));
    std::string bytes = readBytes(path);
    bytes.resize(bytes.size() - 5);
    writeBytes(path, bytes);
    expectInputErrorNaming(path, [&] { readImage(path); });
    std::filesystem::remove(path);
}

TEST(ImageIoTest, CorruptOrUnknownFilesAreInputErrors) {
    const std::string path = getTempPath(".exr");
    writeBytes(path, std::string("\x76\x2f\x31\x01", 4) + "garbage");
    expectInputErrorNaming(path, [&] { readImage(path); });
    // Truncated EXR: tinyexr's message ends with a newline; the error is still one line.
    writeImage(path, makeRandomImage(4, 4, 0.0f, 1.0f, 5));
    std::string exr = readBytes(path);
    exr.resize(exr.size() / 2);
    writeBytes(path, exr);
    try {
        readImage(path);
        ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
    writeBytes(path, "\x89PNG\r\n\x1a\ngarbage");
    expectInputErrorNaming(path, [&] { readImage(path); });
    writeBytes(path, "GIF89a");
    expectInputErrorNaming(path, [&] { readImage(path); });
    writeBytes(path, "");
    expectInputErrorNaming(path, [&] { readImage(path); });
    std::filesystem::remove(path);
}

} // namespace
} // namespace ispm
