// A seeded mutation fuzzer for what users hand to ispm: scene files (the assets and
// tests/fuzz/mesh_scene.json), the OBJ and MTL files they name, and PFM and EXR images. Each case
// mutates one corpus file (bytes flipped, ranges cut or repeated, numbers swapped for extreme
// values, the file cut short) and loads it as the CLI does. The loader must either succeed with
// finite geometry or throw InputError with one line that names the file; anything else (another
// exception, a crash, a hang) fails. Deterministic: the same seeds every run. ISPM_FUZZ_CASES
// in the environment sets the cases per corpus file (default below) for longer runs.
#include "core/input_error.h"
#include "core/strings.h"
#include "image/image_io.h"
#include "scene/scene_loader.h"
#include "scene_test_util.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ispm::test {
namespace {

// Cases per corpus file in CI: about 2 s for all of them in a Release build.
constexpr int kDefaultCases = 400;

int getCaseCount() {
    const char* env = std::getenv("ISPM_FUZZ_CASES");
    const int n = env ? std::atoi(env) : 0;
    return n > 0 ? n : kDefaultCases;
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Values that have broken parsers: out of float range, below it, not numbers, past int.
constexpr std::array<const char*, 14> kExtremes = {
    "1e308",      "-1e308", "3.5e38", "1e-45", "1e-320", "nan",
    "inf",        "-inf",   "-0",     "0",     "-1",     "99999999999999999999",
    "4294967297", "1e9"};

class Mutator {
  public:
    explicit Mutator(uint32_t seed) : mRng(seed) {}

    std::string mutate(std::string text) {
        const int steps = pick(3) + 1;
        for (int i = 0; i < steps && !text.empty(); ++i)
            mutateOnce(text);
        return text;
    }

  private:
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(mRng); }
    size_t pickAt(const std::string& text) { return size_t(pick(int(text.size()))); }

    void mutateOnce(std::string& text) {
        switch (pick(7)) {
        case 0: // a byte flipped to any value
            text[pickAt(text)] = static_cast<char>(pick(256));
            break;
        case 1: { // a range cut out
            const size_t at = pickAt(text);
            text.erase(at, size_t(pick(16) + 1));
            break;
        }
        case 2: { // a range repeated
            const size_t at = pickAt(text);
            const std::string part = text.substr(at, size_t(pick(32) + 1));
            text.insert(at, part);
            break;
        }
        case 3: { // a number swapped for an extreme value
            std::vector<size_t> starts;
            for (size_t i = 0; i < text.size(); ++i) {
                const bool digit = text[i] >= '0' && text[i] <= '9';
                const bool after = i > 0 && ((text[i - 1] >= '0' && text[i - 1] <= '9') ||
                                             text[i - 1] == '.' || text[i - 1] == '-');
                if (digit && !after) starts.push_back(i);
            }
            if (starts.empty()) break;
            const size_t at = starts[size_t(pick(int(starts.size())))];
            size_t end = at;
            while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) ||
                                         text[end] == '.' || text[end] == 'e'))
                ++end;
            text.replace(at, end - at, kExtremes[size_t(pick(int(kExtremes.size())))]);
            break;
        }
        case 4: { // a structural character
            static constexpr std::string_view kChars = "{}[],:\"/\\ \n";
            text.insert(pickAt(text), 1, kChars[size_t(pick(int(kChars.size())))]);
            break;
        }
        case 5: // cut short
            text.resize(pickAt(text));
            break;
        default: { // nested deeper: the text wrapped in brackets many times
            const int depth = pick(200) + 1;
            text = std::string(size_t(depth), '[') + text + std::string(size_t(depth), ']');
            break;
        }
        }
    }

    std::mt19937 mRng;
};

// The outcome the CLI relies on: nothing, or one line naming `file`.
void expectCleanError(const InputError& e, const std::string& file, const std::string& what) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << what << ": " << message;
    EXPECT_TRUE(contains(message, file)) << what << ": " << message;
}

// Loads every mutation of `name` (in `dir`, beside the files it refers to) as a scene.
void fuzzScene(const ScratchDir& dir, const std::string& sceneName, const std::string& fileName,
               const std::string& original, uint32_t seed) {
    Mutator mutator(seed);
    const int cases = getCaseCount();
    int loaded = 0;
    for (int i = 0; i < cases; ++i) {
        const std::string text = mutator.mutate(original);
        dir.write(fileName, text);
        const std::string what = strCat(fileName, " case ", i, " (seed ", seed, ")");
        try {
            const Scene scene = loadScene(dir.getPath(sceneName));
            for (const Mesh& mesh : scene.meshes) {
                for (const glm::vec3& p : mesh.positions) {
                    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
                        << what;
                }
            }
            ++loaded;
        } catch (const InputError& e) {
            // An error in a file the scene names carries that file's name inside the scene's.
            expectCleanError(e, sceneName, what);
        } catch (const std::exception& e) {
            ADD_FAILURE() << what << ": not an input error: " << e.what() << "\n" << text;
        }
    }
    std::printf("[ fuzz     ] %s mutated %d times: %d loaded, %d refused\n", fileName.c_str(),
                cases, loaded, cases - loaded);
}

TEST(FuzzInputs, MutatedAssetScenesLoadOrFailCleanly) {
    uint32_t seed = 1;
    for (const char* name :
         {"cornell.json", "courtyard.json", "dynamic.json", "moving_cube.json"}) {
        ScratchDir dir;
        fuzzScene(dir, name, name, readText(strCat(ISPM_ASSET_DIR, "/scenes/", name)), seed++);
    }
}

TEST(FuzzInputs, MutatedMeshScenesAndObjFilesLoadOrFailCleanly) {
    const std::string corpus = strCat(ISPM_TEST_DATA_DIR, "/fuzz/");
    const std::array<std::string, 3> names = {"mesh_scene.json", "model.obj", "model.mtl"};
    uint32_t seed = 100;
    for (const std::string& mutated : names) {
        ScratchDir dir;
        for (const std::string& name : names)
            dir.write(name, readText(corpus + name));
        fuzzScene(dir, "mesh_scene.json", mutated, readText(corpus + mutated), seed++);
    }
}

TEST(FuzzInputs, MutatedImagesReadOrFailCleanly) {
    // A small colour PFM and a 20 x 18 EXR (ZIP-compressed), written by ispm, and a greyscale
    // PFM by hand.
    ScratchDir dir;
    Image image(20, 18);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            image.at(x, y) = glm::vec3(float(x), float(y), 0.5f);
    writeImage(dir.getPath("colour.pfm"), image);
    writeImage(dir.getPath("colour.exr"), image);
    std::string grey = "Pf\n2 2\n-1.0\n";
    for (float v : {0.0f, 1.0f, 2.0f, 3.0f})
        grey.append(reinterpret_cast<const char*>(&v), sizeof v);
    uint32_t seed = 200;
    const std::array<std::pair<std::string, std::string>, 3> originals = {
        std::pair{readText(dir.getPath("colour.pfm")), std::string("m.pfm")},
        std::pair{grey, std::string("m.pfm")},
        std::pair{readText(dir.getPath("colour.exr")), std::string("m.exr")}};
    for (const auto& [original, name] : originals) {
        Mutator mutator(seed++);
        int read = 0;
        for (int i = 0; i < getCaseCount(); ++i) {
            const std::string path = dir.write(name, mutator.mutate(original));
            try {
                const Image decoded = readImage(path);
                EXPECT_FALSE(decoded.isEmpty());
                ++read;
            } catch (const InputError& e) {
                expectCleanError(e, name, strCat(name, " case ", i));
            } catch (const std::exception& e) {
                ADD_FAILURE() << name << " case " << i << ": not an input error: " << e.what();
            }
        }
        std::printf("[ fuzz     ] %s (seed %u) mutated %d times: %d read, %d refused\n",
                    name.c_str(), seed - 1, getCaseCount(), read, getCaseCount() - read);
    }
}

} // namespace
} // namespace ispm::test
