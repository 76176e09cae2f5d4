// Image-test helpers.
#include "support/render_support.h"

#include "gl/gl.h"
#include "image/image_diff.h"
#include "image/image_io.h"
#include "render/readback.h"
#include "render/reference_pass.h"
#include "support/gl_fixture.h"
#include "support/test_settings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace ispm::test {

Image renderAov(const Scene& scene, const Settings& settings, Aov aov) {
    FrameRunner runner(scene, settings, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    return readTextureImage(runner.getAov(aov));
}

Image renderReference(const Scene& scene, const char* method, int sizePx, int spp, int bounces) {
    Settings settings = makeTestSettings({{"width", sizePx},
                                          {"height", sizePx},
                                          {"bounces", bounces},
                                          {"reference_method", method}});
    ReferencePass reference(scene, settings);
    for (int s = 0; s < spp; ++s)
        reference.addSample();
    return reference.readMean();
}

Image renderReferenceIndirect(const Scene& scene, const Settings& settings, int spp) {
    ReferencePass withBounces(scene, settings);
    Settings directOnly = withSettings(settings, {{"bounces", 0}});
    ReferencePass direct(scene, directOnly);
    for (int s = 0; s < spp; ++s) {
        withBounces.addSample();
        direct.addSample();
    }
    Image indirect = withBounces.readMean();
    const Image d = direct.readMean();
    for (size_t i = 0; i < d.pixels.size(); ++i)
        indirect.pixels[i] -= d.pixels[i];
    return indirect;
}

void expectMatchesGolden(const Image& actual, const std::string& name, const GoldenThresholds& t) {
    const std::filesystem::path golden =
        std::filesystem::path(ISPM_TEST_DATA_DIR) / "goldens" / (name + ".png");
    const char* update = std::getenv("ISPM_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        writeImage(golden.string(), actual);
        std::printf("updated golden %s\n", golden.string().c_str());
        return;
    }
    ASSERT_TRUE(std::filesystem::exists(golden))
        << golden << " is missing: run tools/update-goldens.sh";
    const Image expected = readImage(golden.string());
    ASSERT_EQ(expected.width, actual.width);
    ASSERT_EQ(expected.height, actual.height);
    // Compare what the golden holds: 8-bit values.
    Image quantised = actual;
    for (glm::vec3& p : quantised.pixels) {
        p = glm::round(glm::clamp(p, 0.0f, 1.0f) * 255.0f) / 255.0f;
    }
    const ImageDiff diff = computeImageDiff(quantised, expected, t.pixelTolerance);
    const bool ok =
        diff.meanAbsError <= t.maxMeanAbsError && diff.failingFraction <= t.maxFailingFraction;
    EXPECT_LE(diff.meanAbsError, t.maxMeanAbsError) << name;
    EXPECT_LE(diff.failingFraction, t.maxFailingFraction) << name;
    if (!ok) {
        const std::filesystem::path out =
            std::filesystem::path(ISPM_BINARY_DIR) / "golden-failures";
        std::filesystem::create_directories(out);
        writeImage((out / (name + ".actual.png")).string(), quantised);
        Image d = computeErrorImage(quantised, expected);
        for (glm::vec3& p : d.pixels)
            p = glm::min(p * 10.0f, glm::vec3(1.0f)); // 10x to see it
        writeImage((out / (name + ".diff.png")).string(), d);
        ADD_FAILURE() << "actual and diff images written to " << out;
    }
}

double computeMaxRelativeDifference(const Image& a, const Image& b) {
    double largest = 0.0;
    double sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            largest = std::max(largest, std::abs(double(a.pixels[i][c]) - double(b.pixels[i][c])));
            sum += double(b.pixels[i][c]);
        }
    }
    const double mean = sum / double(3 * b.pixels.size());
    EXPECT_GT(mean, 0.0) << "no light to compare";
    return mean > 0.0 ? largest / mean : 0.0;
}

} // namespace ispm::test
