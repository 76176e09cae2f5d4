// The G-buffer: one table of channels (name, format, meaning) builds the attachments, the shader
// output locations (as #defines) and the viewer's debug-view menu. The viewer and every light
// camera render the same channels; light views are layers of 2D array textures.
#pragma once

#include "gl/objects.h"
#include "render/param_blocks.h"
#include "render/reloadable_program.h"

#include <shared/scene_data.h>

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ispm {

class GpuScene;

// What a G-buffer channel needs in the scene to hold anything but zero
// (getSceneGBufferChannels).
enum class ChannelSource {
    Always,
    SpecularLobes, // a material with a specular part (GpuScene::hasSpecularLobes)
    Transmissive,  // a material that transmits (GpuScene::hasTransmissive)
    Emission,      // a material that emits (GpuScene::hasEmission)
    Motion,        // read only by motion blur and the viewer's debug view (wantsMotion)
};

struct GBufferChannel {
    std::string_view name;
    std::string_view define; // GLSL output location macro
    gl::Format format;
    std::string_view meaning;
    // Written for the viewer only (light views have no such attachment, and their program
    // writes no such output). Such channels come last, so the others' indices match.
    bool viewerOnly = false;
    ChannelSource source = ChannelSource::Always;
};

std::span<const GBufferChannel> getGBufferChannels();
// "GBUFFER_POSITION 0", ... for the G-buffer program.
std::vector<std::string> getGBufferDefines();

class GBuffer {
  public:
    GBuffer() = default;
    GBuffer(std::string_view label, int width, int height, int layers, bool isArray);

    // The channels the scene can write anything but zero to (getSceneGBufferChannels; position
    // always): the others hold zero, cleared in every layer when they leave the set, and are
    // then neither cleared nor drawn, so readers find the zero the scene would have written.
    // All channels at first.
    void setChannelsInUse(uint32_t mask);
    void clear(int layer) const; // the channels in use, and depth
    // Framebuffer of one layer (the channels in use), with viewport.
    void bindTarget(int layer);
    // Position and depth cleared, the other channels left as they are: for layers whose readers
    // look at those only where position.w marks a surface (light views).
    void clearPositions(int layer) const;
    // A layer that only the shadow test reads (a shadow-only light view): position and depth
    // drawn, the other channels left as they are (a third of the cost on llvmpipe).
    void bindPositionTarget(int layer);
    void bindTextures(int firstUnit) const;
    const gl::Texture& getChannel(size_t index) const { return mChannels[index]; }
    const gl::Texture& getChannel(std::string_view name) const;
    int getWidth() const { return mWidth; }
    int getHeight() const { return mHeight; }
    int getLayers() const { return mLayers; }
    size_t getGpuBytes() const;

  private:
    std::vector<gl::Texture> mChannels;
    gl::Texture mDepth;
    std::vector<gl::Framebuffer> mTargets; // one per layer
    int mWidth = 0;
    int mHeight = 0;
    int mLayers = 0;
    uint32_t mChannelsInUse = ~0u; // bit i: mChannels[i]
};

// The G-buffer channels (bit i: channel i of getGBufferChannels()) the scene's materials can
// make nonzero, by each channel's source: specular only where a material has a specular part,
// transmissive where one transmits, emission where one emits, velocity when its readers want
// motion (wantsMotion: motion blur on, or the viewer showing the channel); the others always. A
// channel left out costs neither a clear nor a write at any pixel of any view: on llvmpipe the
// light views of a Lambertian scene take a quarter less without their specular and transmissive
// layers.
uint32_t getSceneGBufferChannels(const GpuScene& scene, bool wantsMotion);

// Appends the parameter blocks of one view: one per instance of the scene, seen through
// clipFromWorld. `eye` is the camera position (w = 1) or the direction toward an orthographic
// camera (w = 0): normals are turned to face it, since surfaces are two-sided. The velocity
// channel compares each point with where the instance's previous transform put it, seen through
// previousClipFromWorld, in pixels of a target of targetSizePx, less jitterMotionPx (the change
// of sub-pixel offset that both cameras hold).
void appendGBufferParams(std::vector<gpu::GBufferParams>& blocks, const GpuScene& scene,
                         const glm::mat4& clipFromWorld, const glm::vec4& eye,
                         const glm::mat4& previousClipFromWorld, glm::vec2 targetSizePx,
                         glm::vec2 jitterMotionPx = glm::vec2(0.0f));

// The order to draw the scene's instances in, seen from `eye` (as appendGBufferParams takes
// it): by the depth of their boxes' centres, nearest first, so the rasteriser's early depth test
// rejects what they hide instead of shading it first (llvmpipe shades on the CPU).
std::vector<uint32_t> computeDrawOrder(const GpuScene& scene, const glm::vec4& eye);

// Rasterises every instance of the scene into the bound G-buffer target, instance i with
// blocks[first + i] (appendGBufferParams), in `order` (computeDrawOrder).
void drawSceneGBuffer(const gl::Program& program, const GpuScene& scene,
                      const ParamBlocks<gpu::GBufferParams>& blocks, size_t first,
                      std::span<const uint32_t> order);

// The G-buffer program in variants: without textures (GBUFFER_TEXTURES 0: no texture
// coordinates fetched or interpolated, as fast as before textures existed) and with them, and
// with the alpha test (GBUFFER_ALPHA_TEST 1: its discard would cost opaque scenes their early
// depth test), each built when a scene that needs it is first drawn.
class GBufferPrograms {
  public:
    // lightViews: the light cameras' variant (GBUFFER_LIGHT_VIEWS 1), which writes no
    // viewer-only channel and interpolates nothing for them.
    explicit GBufferPrograms(bool lightViews);
    const gl::Program& get(bool textured, bool alphaTested);
    const gl::Program& get(const GpuScene& scene); // the variant the scene's materials need
    void reloadIfChanged(ShaderReloadReport& report);

  private:
    ProgramVariants mVariants; // by GBUFFER_TEXTURES and GBUFFER_ALPHA_TEST; the plain one built
                               // with the object
};

} // namespace ispm
