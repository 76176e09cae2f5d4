// The scene model: camera, lights, materials, meshes and their instances, plus the render
// settings the scene overrides. Plain data in metres and SI radiometric units; no GL
// (docs/design.md "Units and conventions").
#pragma once

#include "scene/animation.h"
#include "scene/environment.h"
#include "settings/settings.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace ispm {

struct Aabb {
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{-std::numeric_limits<float>::max()};
    void extend(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void extend(const Aabb& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool isEmpty() const { return lo.x > hi.x; }
    glm::vec3 getCenter() const { return 0.5f * (lo + hi); }
    glm::vec3 getExtent() const { return hi - lo; }
    // Corner i takes x from bit 0, y from bit 1, z from bit 2 of i (0: lo, 1: hi).
    glm::vec3 getCorner(int i) const {
        return {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    }
};

inline constexpr int kAabbCornerCount = 8;

// The box around every box of `boxes` (empty for none).
Aabb computeUnion(std::span<const Aabb> boxes);

// The box around `box`'s eight corners transformed by `m`: exact for translations and scales,
// conservative under rotation. An empty box stays empty.
Aabb transformBounds(const Aabb& box, const glm::mat4& m);

// Pinhole camera as gluLookAt + gluPerspective; the aspect ratio comes from the image size.
struct Camera {
    glm::vec3 position{0.0f, 0.0f, 0.0f};
    glm::vec3 target{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDeg = 45.0f; // full vertical field of view
    float nearM = 0.0f;    // 0: derived from the scene bounds
    float farM = 0.0f;     // 0: derived from the scene bounds
    // Keys of the camera's path (`path`), or none for a still camera: Scene::update moves
    // position, target and fovYDeg along it (evaluateCameraPath).
    std::vector<CameraKey> path;
};

inline constexpr uint32_t kNoTexture = 0xffffffffu;

// An 8-bit RGBA image whose RGB is sRGB-encoded (PNG and JPEG colour textures) or linear (a
// material's normal map: Material::normalTexture), row 0 at the top as image files store it
// (texture coordinate v = 0 is the top row, as in glTF; OBJ's v runs up and is flipped on import).
struct SceneTexture {
    std::string name;
    std::string sourcePath; // the file it was read from; empty when embedded (glTF buffers)
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba; // width * height * 4 bytes
};

// Reflectances in [0,1] per channel; defaults are all zero (ior 1.5), as in the scene format.
struct Material {
    std::string name;
    glm::vec3 diffuse{0.0f};
    glm::vec3 specular{0.0f};
    float phongExponent = 0.0f;
    glm::vec3 transmissive{0.0f};
    float ior = 1.5f;
    // Radiance W/(m^2 sr) leaving the side the triangles' winding faces (both sides with
    // emissionTwoSided): an emitting surface is a light (scene/emitters.h).
    glm::vec3 emission{0.0f};
    bool emissionTwoSided = false;
    // Share of the photon budget its emitting triangles take (< 0: derived from their power,
    // as a light's photon_share).
    float photonShare = -1.0f;
    // Index into Scene::textures whose colour multiplies `diffuse` (glTF base colour, MTL
    // map_Kd), or kNoTexture. Meshes with such materials carry texture coordinates.
    uint32_t diffuseTexture = kNoTexture;
    // Alpha test (glTF alphaMode MASK, leaves and fences): a point whose base colour texture's
    // alpha (1 without a texture) is below it is not there, for the camera, the lights and every
    // ray. 0: opaque; above 1: nothing of the material is there.
    float alphaCutoff = 0.0f;
    // glTF doubleSided, kept as the file said it. Every surface is drawn and traced two-sided
    // whatever it says: a one-sided surface lets light through one way and not the other
    // (docs/design.md "Alpha-tested and one-sided surfaces").
    bool doubleSided = true;
    // Index into Scene::textures of a tangent-space normal map (glTF normalTexture), or
    // kNoTexture: its linear RGB in [0, 1] is the shading normal (2 rgb - 1) in the frame of the
    // mesh's tangent, bitangent and normal (Mesh::tangents), x and y scaled by normalScale
    // (docs/design.md "Normal maps"). Meshes with such materials carry tangents.
    uint32_t normalTexture = kNoTexture;
    float normalScale = 1.0f;
};

enum class LightType : uint32_t { Point = 0, Spot = 1, Sun = 2 };

struct Light {
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};               // point, spot
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // spot axis; sun: the direction light travels (unit)
    glm::vec3 intensity{0.0f};              // point, spot: W/sr (spot: on the axis)
    glm::vec3 irradiance{0.0f};             // sun: W/m^2 on a surface facing it
    float innerDeg = 0.0f;                  // spot half-angles
    float outerDeg = 0.0f;
    float photonShare = -1.0f; // < 0: derived from the light's power
    // Set for lights that move; position and direction above are then its state at the last
    // Scene::update. Kept on the light so that adding or removing lights keeps the pairing.
    std::optional<LightAnimation> animation;
};

// "point", "spot" or "sun", as scene files spell them.
const char* getLightTypeName(LightType type);

// Spot falloff S(a): 1 inside inner, 0 outside outer, smoothstep in cos space between.
float computeSpotFalloff(float cosAngle, float innerDeg, float outerDeg);

// Triangles in object space, one material index per triangle (into Scene::materials).
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    // Texture coordinates per position (u right, v down from the image's top row), or empty for
    // a mesh without textures.
    std::vector<glm::vec2> texcoords;
    // Unit shading normals per position (OBJ vn, glTF NORMAL, or generated: smooth_angle_deg),
    // or empty for a flat-shaded mesh. A zero vector marks a position without one: a triangle
    // with such a corner is flat-shaded (its geometric normal), as is every triangle of a mesh
    // without normals.
    std::vector<glm::vec3> normals;
    // Per position: the unit tangent along +u and in w the handedness (+-1): the bitangent,
    // up the image (-v), is w cross(normal, tangent), as glTF's TANGENT; w = 0 where a position
    // has none. Empty for a mesh without normal-mapped materials.
    std::vector<glm::vec4> tangents;
    std::vector<glm::uvec3> triangles;
    std::vector<uint32_t> triangleMaterials;
    Aabb computeBounds() const;
};

// One placement of a mesh in the world.
struct Instance {
    uint32_t meshIndex = 0;
    glm::mat4 worldFromObject{1.0f};
};

struct Scene {
    std::string sourcePath; // the file it was loaded from, for messages
    Camera camera;
    // Further views the file names (`cameras`), chosen with selectCamera / --camera NAME.
    std::vector<std::pair<std::string, Camera>> namedCameras;
    glm::vec3 background{0.0f}; // what the camera sees where no surface is, without environment
    // Light from every direction no surface blocks; the camera sees it where no surface is.
    Environment environment;
    std::vector<Material> materials;
    std::vector<SceneTexture> textures; // Material::diffuseTexture indexes here
    std::vector<Mesh> meshes;
    std::vector<Instance> instances;
    std::vector<Light> lights;
    Settings settings; // overrides from the `render` block
    // Instances that move (Instance stays two fields: it is brace-initialised everywhere).
    std::vector<InstanceAnimation> instanceAnimations;

    bool isAnimated() const;
    // Sets every animated instance's transform and light's position/direction for time t
    // (seconds); the same t always gives the same scene. Callers that rendered the scene tell
    // the renderer (FrameRunner::updateScene). Defined in animation.cpp.
    void update(double timeS);
    Aabb computeWorldBounds() const; // computeUnion(computeInstanceBounds())
    // Each instance's world box (empty meshes left out): where the scene's parts lie.
    std::vector<Aabb> computeInstanceBounds() const;
    size_t countTriangles() const;
};

// Makes the named camera of the file's `cameras` the scene's camera; an empty name keeps
// `camera`. An unknown name throws InputError naming the file and /cameras.
void selectCamera(Scene& scene, const std::string& name);

// Camera matrices (OpenGL clip conventions, right-handed, -z forward in view space).
glm::mat4 computeViewFromWorld(const Camera& camera);
glm::mat4 computeClipFromView(const Camera& camera, float aspect, float nearM, float farM);
// Moves an image of `sizePx` by `shiftPx` pixels when applied after a clipFromWorld (sub-pixel
// jitter of the viewer and of the light cameras): 2 shift / size in normalised device coordinates.
glm::mat4 computeClipShift(glm::vec2 shiftPx, glm::vec2 sizePx);
// Whether two cameras see the same image (every field equal).
bool isSameCamera(const Camera& a, const Camera& b);

} // namespace ispm
