// The G-buffer keeps only the channels the scene's materials can fill (getSceneGBufferChannels):
// a channel left out reads zero, cleared once when it leaves, and the target's draws pass it by
// until it is back in the set.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"

#include "gl/gl.h"
#include "render/gbuffer.h"
#include "render/gpu_scene.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ispm::test {
namespace {

constexpr int kLightResolution = 64; // no lights: any valid size
constexpr int kSize = 4;

class GBufferChannelsTest : public GlTest {};

size_t getChannelIndex(std::string_view name) {
    const auto channels = getGBufferChannels();
    for (size_t i = 0; i < channels.size(); ++i)
        if (channels[i].name == name) return i;
    throw std::logic_error("no G-buffer channel " + std::string(name));
}

uint32_t getBit(std::string_view name) {
    return 1u << getChannelIndex(name);
}

Scene makeSquareOf(const Material& material) {
    const glm::mat4 identity(1.0f);
    Scene scene = makeGreySquares({&identity, 1});
    scene.materials[0] = material;
    return scene;
}

// Fills every texel of every layer of a channel (the G-buffer hands out const textures).
void fillChannel(const GBuffer& gbuffer, std::string_view name, float value) {
    const glm::vec4 texel(value);
    glClearTexImage(gbuffer.getChannel(name).getId(), 0, GL_RGBA, GL_FLOAT, &texel.x);
}

// Every texel of the channel equals `value`.
void expectChannel(const GBuffer& gbuffer, std::string_view name, float value) {
    for (const glm::vec4& texel : gbuffer.getChannel(name).readRgba())
        ASSERT_EQ(texel, glm::vec4(value)) << name;
}

TEST_F(GBufferChannelsTest, ALambertianSceneLeavesOutSpecularTransmissiveAndEmission) {
    Material grey;
    grey.diffuse = glm::vec3(0.5f);
    grey.phongExponent = 20.0f; // an exponent without a specular colour writes nothing but zero
    const GpuScene scene(makeSquareOf(grey), kLightResolution);
    const uint32_t mask = getSceneGBufferChannels(scene, true);
    for (const char* name : {"specular", "transmissive", "emission"})
        EXPECT_EQ(mask & getBit(name), 0u) << name;
    for (const char* name : {"position", "normal", "diffuse", "velocity"})
        EXPECT_NE(mask & getBit(name), 0u) << name;
}

TEST_F(GBufferChannelsTest, VelocityOnlyWhenMotionIsWanted) {
    Material grey;
    grey.diffuse = glm::vec3(0.5f);
    const GpuScene scene(makeSquareOf(grey), kLightResolution);
    EXPECT_EQ(getSceneGBufferChannels(scene, false) & getBit("velocity"), 0u);
    EXPECT_NE(getSceneGBufferChannels(scene, true) & getBit("velocity"), 0u);
    // Only velocity follows the wish.
    EXPECT_EQ(getSceneGBufferChannels(scene, false) | getBit("velocity"),
              getSceneGBufferChannels(scene, true));
}

TEST_F(GBufferChannelsTest, EachMaterialPartBringsItsChannelBack) {
    struct Case {
        const char* channel;
        void (*apply)(Material&);
    };
    const Case cases[] = {
        {"specular", [](Material& m) { m.specular = glm::vec3(0.0f, 0.0f, 0.1f); }},
        {"transmissive", [](Material& m) { m.transmissive = glm::vec3(0.9f); }},
        {"emission", [](Material& m) { m.emission = glm::vec3(0.0f, 2.0f, 0.0f); }},
    };
    for (const Case& c : cases) {
        Material m;
        m.diffuse = glm::vec3(0.5f);
        c.apply(m);
        const GpuScene scene(makeSquareOf(m), kLightResolution);
        const uint32_t mask = getSceneGBufferChannels(scene, true);
        for (const char* name : {"specular", "transmissive", "emission"}) {
            EXPECT_EQ((mask & getBit(name)) != 0, std::string_view(name) == c.channel)
                << c.channel << " material, channel " << name;
        }
    }
}

TEST_F(GBufferChannelsTest, AChannelLeftOutReadsZeroAndIsNotDrawn) {
    GBuffer gbuffer("channels test gbuffer", kSize, kSize, 1, false);
    const size_t count = getGBufferChannels().size();
    for (const GBufferChannel& c : getGBufferChannels())
        fillChannel(gbuffer, c.name, 1.0f);

    gbuffer.setChannelsInUse(~getBit("specular"));
    expectChannel(gbuffer, "specular", 0.0f); // cleared as it left
    expectChannel(gbuffer, "diffuse", 1.0f);  // the others untouched

    // A clear of every draw buffer of the target reaches the channels in use only.
    gbuffer.bindTarget(0);
    const float twos[4] = {2.0f, 2.0f, 2.0f, 2.0f};
    for (size_t i = 0; i < count; ++i)
        glClearBufferfv(GL_COLOR, static_cast<GLint>(i), twos);
    expectChannel(gbuffer, "specular", 0.0f);
    expectChannel(gbuffer, "diffuse", 2.0f);

    // clear() clears the channels in use and leaves the zero of the others.
    gbuffer.clear(0);
    expectChannel(gbuffer, "diffuse", 0.0f);

    // Back in the set, the channel is drawn again.
    gbuffer.setChannelsInUse(~0u);
    gbuffer.bindTarget(0);
    glClearBufferfv(GL_COLOR, static_cast<GLint>(getChannelIndex("specular")), twos);
    expectChannel(gbuffer, "specular", 2.0f);
}

TEST_F(GBufferChannelsTest, LightViewLayersLeaveTheChannelOutInEveryLayer) {
    constexpr int kLayers = 3;
    GBuffer gbuffer("channels test light gbuffer", kSize, kSize, kLayers, true);
    fillChannel(gbuffer, "transmissive", 1.0f);
    gbuffer.setChannelsInUse(~getBit("transmissive"));
    for (int layer = 0; layer < kLayers; ++layer) {
        for (const glm::vec4& texel : gbuffer.getChannel("transmissive").readRgba(layer))
            ASSERT_EQ(texel, glm::vec4(0.0f)) << "layer " << layer;
    }
}

} // namespace
} // namespace ispm::test
