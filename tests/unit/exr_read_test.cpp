// EXR files ispm does not write itself, read through readImage: tiled (one level, 8 x 8 tiles,
// edge tiles cut by the image's edge), half-float channels, and a single grey channel. Written
// here with tinyexr's own encoder.
#include "core/input_error.h"
#include "image/image_io.h"

#include <gtest/gtest.h>
#include <tinyexr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace ispm {
namespace {

constexpr int kWidth = 20;
constexpr int kHeight = 18;
constexpr int kTile = 8;

// A value no neighbour shares: channel c of pixel (x, y).
float makeValue(int c, int x, int y) {
    return float(c) * 1000.0f + float(y) * 32.0f + float(x) + 0.25f;
}

std::string getPath(const char* name) {
    return (std::filesystem::temp_directory_path() /
            (std::string("ispm_exr_read_") + name + "_" + std::to_string(::getpid()) + ".exr"))
        .string();
}

void writeBytes(const std::string& path, const unsigned char* data, size_t size) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
}

// Encodes `channels` (names, alphabetical) of pixel type `type`, tiled or in scanlines.
std::string writeExr(const char* name, const std::vector<const char*>& channels, int type,
                     bool tiled) {
    const int n = int(channels.size());
    std::vector<EXRChannelInfo> infos(size_t(n), EXRChannelInfo{});
    std::vector<int> types(size_t(n), type);
    for (int c = 0; c < n; ++c)
        std::snprintf(infos[size_t(c)].name, sizeof infos[size_t(c)].name, "%s",
                      channels[size_t(c)]);
    EXRHeader header;
    InitEXRHeader(&header);
    header.num_channels = n;
    header.channels = infos.data();
    header.pixel_types = types.data();
    header.requested_pixel_types = types.data();
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
    // Values as float bits, or as half bits when `type` is half (whole numbers below 2048 then,
    // exact in half).
    const auto encode = [type](float v, std::vector<unsigned char>& out) {
        if (type == TINYEXR_PIXELTYPE_FLOAT) {
            const auto* b = reinterpret_cast<const unsigned char*>(&v);
            out.insert(out.end(), b, b + sizeof v);
        } else {
            // Half: v is a whole number below 2048 here, exact in 11 bits of mantissa.
            int e = 0;
            const float m = std::frexp(v, &e); // v = m 2^e, m in [0.5, 1)
            uint16_t bits = 0;
            if (v != 0.0f) {
                const int exponent = e - 1 + 15;
                const auto mantissa = uint16_t(std::lround((m * 2.0f - 1.0f) * 1024.0f));
                bits = uint16_t((exponent << 10) | mantissa);
            }
            out.push_back(uint8_t(bits & 0xff));
            out.push_back(uint8_t(bits >> 8));
        }
    };
    const auto value = [&](int c, int x, int y) {
        return type == TINYEXR_PIXELTYPE_FLOAT ? makeValue(c, x, y) : float(c * 300 + y * 16 + x);
    };
    EXRImage image;
    InitEXRImage(&image);
    image.width = kWidth;
    image.height = kHeight;
    image.num_channels = n;
    std::vector<std::vector<unsigned char>> planes;
    std::vector<unsigned char*> planePointers;
    std::vector<EXRTile> tiles;
    std::vector<std::vector<unsigned char*>> tilePointers;
    if (tiled) {
        header.tiled = 1;
        header.data_window.max_x = kWidth - 1; // the tile count follows the data window
        header.data_window.max_y = kHeight - 1;
        header.tile_size_x = kTile;
        header.tile_size_y = kTile;
        header.tile_level_mode = TINYEXR_TILE_ONE_LEVEL;
        header.tile_rounding_mode = TINYEXR_TILE_ROUND_DOWN;
        const int tilesX = (kWidth + kTile - 1) / kTile;
        const int tilesY = (kHeight + kTile - 1) / kTile;
        tiles.resize(size_t(tilesX * tilesY));
        planes.resize(tiles.size() * size_t(n));
        tilePointers.resize(tiles.size());
        for (int t = 0; t < tilesX * tilesY; ++t) {
            EXRTile& tile = tiles[size_t(t)];
            tile.offset_x = t % tilesX;
            tile.offset_y = t / tilesX;
            tile.level_x = 0;
            tile.level_y = 0;
            tile.width = std::min(kTile, kWidth - tile.offset_x * kTile);
            tile.height = std::min(kTile, kHeight - tile.offset_y * kTile);
            for (int c = 0; c < n; ++c) {
                std::vector<unsigned char>& plane = planes[size_t(t * n + c)];
                for (int j = 0; j < kTile; ++j)
                    for (int i = 0; i < kTile; ++i)
                        encode(value(c, tile.offset_x * kTile + i, tile.offset_y * kTile + j),
                               plane);
                tilePointers[size_t(t)].push_back(plane.data());
            }
            tile.images = tilePointers[size_t(t)].data();
        }
        image.tiles = tiles.data();
        image.num_tiles = int(tiles.size());
    } else {
        planes.resize(size_t(n));
        for (int c = 0; c < n; ++c) {
            for (int y = 0; y < kHeight; ++y)
                for (int x = 0; x < kWidth; ++x)
                    encode(value(c, x, y), planes[size_t(c)]);
            planePointers.push_back(planes[size_t(c)].data());
        }
        image.images = planePointers.data();
    }
    unsigned char* memory = nullptr;
    const char* error = nullptr;
    const size_t size = SaveEXRImageToMemory(&image, &header, &memory, &error);
    EXPECT_GT(size, 0u) << (error ? error : "");
    if (error) FreeEXRErrorMessage(error);
    const std::string path = getPath(name);
    writeBytes(path, memory, size);
    std::free(memory);
    return path;
}

TEST(ExrReadTest, TiledFileReadsEveryPixel) {
    // Channels B, G, R: file channel 0 is blue.
    const std::string path = writeExr("tiled", {"B", "G", "R"}, TINYEXR_PIXELTYPE_FLOAT, true);
    const Image image = readImage(path);
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec3 expected(makeValue(2, x, y), makeValue(1, x, y), makeValue(0, x, y));
            ASSERT_EQ(image.at(x, y), expected) << x << ", " << y;
        }
    }
    std::filesystem::remove(path);
}

TEST(ExrReadTest, HalfAndGreyChannelsRead) {
    const std::string half = writeExr("half", {"B", "G", "R"}, TINYEXR_PIXELTYPE_HALF, false);
    Image image = readImage(half);
    ASSERT_EQ(image.width, kWidth);
    EXPECT_EQ(image.at(3, 5), glm::vec3(600 + 5 * 16 + 3, 300 + 5 * 16 + 3, 5 * 16 + 3));
    const std::string grey = writeExr("grey", {"Y"}, TINYEXR_PIXELTYPE_FLOAT, false);
    image = readImage(grey);
    EXPECT_EQ(image.at(7, 2), glm::vec3(makeValue(0, 7, 2)));
    const std::string two = writeExr("two", {"U", "V"}, TINYEXR_PIXELTYPE_FLOAT, false);
    try {
        readImage(two);
        ADD_FAILURE() << "two unnamed channels should not read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("expected R, G and B channels"), std::string::npos)
            << e.what();
    }
    for (const std::string& p : {half, grey, two})
        std::filesystem::remove(p);
}

} // namespace
} // namespace ispm
