// The image environment's sampling tables and their CPU sampler (docs/design.md "Environment"):
// the same piecewise-constant distribution lib/environment.glsl samples from the texture.
#include "scene/environment.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

// The index of the first entry of the increasing `cdf` above u (the last where rounding leaves
// u at or above them all), and where u falls inside that entry's step, in [0, 1).
struct CdfPick {
    int index = 0;
    float offset = 0.0f;
};
CdfPick pickFromCdf(const float* cdf, int count, float u) {
    const int index = std::min(int(std::upper_bound(cdf, cdf + count, u) - cdf), count - 1);
    const float low = index > 0 ? cdf[index - 1] : 0.0f;
    const float step = cdf[index] - low;
    const float offset = step > 0.0f ? std::clamp((u - low) / step, 0.0f, 0.99999994f) : 0.5f;
    return {index, offset};
}

size_t getTexelIndex(const EnvironmentImage& image, int x, int y) {
    return size_t(y) * size_t(image.width) + size_t(x);
}

} // namespace

EnvironmentImage buildEnvironmentImage(const Image& source, float scale) {
    EnvironmentImage image;
    image.width = source.width;
    image.height = source.height;
    image.radiance = source.pixels;
    image.conditionalCdf.resize(source.pixels.size());
    image.marginalCdf.resize(size_t(source.height));
    const auto w = uint32_t(source.width);
    const auto h = uint32_t(source.height);
    const glm::vec3 rec709(0.2126f, 0.7152f, 0.0722f);
    const double texelPhi = glm::two_pi<double>() / double(w);
    double total = 0.0;
    for (uint32_t y = 0; y < h; ++y) {
        double row = 0.0;
        // The exact solid angle of a texel of this row, for the luminance's integral.
        const double solidAngle = texelPhi * (std::cos(glm::pi<double>() * y / h) -
                                              std::cos(glm::pi<double>() * (y + 1) / h));
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = getTexelIndex(image, int(x), int(y));
            image.radiance[i] *= scale;
            row += double(gpu::computeEnvironmentTexelWeight(image.radiance[i], y, h));
            image.conditionalCdf[i] = float(row);
            image.luminanceIntegral += double(glm::dot(image.radiance[i], rec709)) * solidAngle;
        }
        for (uint32_t x = 0; x < w; ++x) {
            float& c = image.conditionalCdf[getTexelIndex(image, int(x), int(y))];
            // A black row is never picked; an even CDF keeps it well formed.
            c = row > 0.0 ? float(double(c) / row) : float(x + 1) / float(w);
        }
        image.conditionalCdf[getTexelIndex(image, int(w) - 1, int(y))] = 1.0f;
        total += row;
        image.marginalCdf[y] = float(total);
    }
    for (uint32_t y = 0; y < h; ++y) {
        image.marginalCdf[y] =
            total > 0.0 ? float(double(image.marginalCdf[y]) / total) : float(y + 1) / float(h);
    }
    if (h > 0) image.marginalCdf[h - 1] = 1.0f;
    image.normaliser = total > 0.0 ? double(w) * double(h) / total : 0.0;
    return image;
}

std::vector<glm::vec4> packEnvironmentTexels(const EnvironmentImage& image) {
    std::vector<glm::vec4> texels(size_t(image.width) * size_t(image.height + 1), glm::vec4(0.0f));
    for (size_t i = 0; i < image.radiance.size(); ++i)
        texels[i] = glm::vec4(image.radiance[i], image.conditionalCdf[i]);
    const size_t last = size_t(image.width) * size_t(image.height);
    for (size_t y = 0; y < image.marginalCdf.size(); ++y)
        texels[last + y].x = image.marginalCdf[y];
    return texels;
}

Environment makeImageEnvironment(const Image& image, float scale, float rotationDeg) {
    Environment environment;
    environment.type = EnvironmentType::Image;
    environment.scale = scale;
    environment.rotationDeg = rotationDeg;
    environment.image =
        std::make_shared<const EnvironmentImage>(buildEnvironmentImage(image, scale));
    return environment;
}

EnvironmentSample sampleEnvironmentImage(const Environment& environment, glm::vec2 u) {
    const EnvironmentImage& image = *environment.image;
    const gpu::GpuEnvironment g = makeGpuEnvironment(environment);
    EnvironmentSample s;
    if (!(image.normaliser > 0.0)) return s;
    const CdfPick row = pickFromCdf(image.marginalCdf.data(), image.height, u.x);
    const float* conditional = image.conditionalCdf.data() + getTexelIndex(image, 0, row.index);
    const CdfPick column = pickFromCdf(conditional, image.width, u.y);
    const glm::vec2 uv((float(column.index) + column.offset) / float(image.width),
                       (float(row.index) + row.offset) / float(image.height));
    s.toward = gpu::computeEnvironmentDirection(uv, glm::vec2(g.image));
    s.radiance = image.radiance[getTexelIndex(image, column.index, row.index)];
    const float weight =
        gpu::computeEnvironmentTexelWeight(s.radiance, uint32_t(row.index), uint32_t(image.height));
    s.pdf = gpu::computeEnvironmentSolidAnglePdf(weight, g.image.z,
                                                 std::sin(uv.y * gpu::kEnvironmentPi));
    return s;
}

float computeEnvironmentImagePdf(const Environment& environment, const glm::vec3& toward) {
    const EnvironmentImage& image = *environment.image;
    const gpu::GpuEnvironment g = makeGpuEnvironment(environment);
    const glm::vec2 uv = gpu::computeEnvironmentUv(toward, glm::vec2(g.image));
    const int x = std::min(int(uv.x * float(image.width)), image.width - 1);
    const int y = std::min(int(uv.y * float(image.height)), image.height - 1);
    const float weight = gpu::computeEnvironmentTexelWeight(
        image.radiance[getTexelIndex(image, x, y)], uint32_t(y), uint32_t(image.height));
    // From x and z: 1 - y^2 loses the digits near the poles, where the pdf is largest.
    const float sinTheta = std::sqrt(toward.x * toward.x + toward.z * toward.z);
    return gpu::computeEnvironmentSolidAnglePdf(weight, g.image.z, sinTheta);
}

} // namespace ispm
