// The Cornell box as published by the Cornell Program of Computer Graphics, in metres (the
// measured millimetres / 1000), without its area light. Walls are quads as measured (some are
// slightly non-planar); each quad is split (0,1,2), (0,2,3).
#include "scene/cornell_box.h"

#include "scene/mesh_builder.h"

#include <array>

namespace ispm {

namespace {

enum CornellColour : int { kWhite = 0, kRed = 1, kGreen = 2 };

struct CornellQuad {
    const char* part;
    CornellColour colour;
    float corners[4][3]; // metres
};

// Copied from the measurement data (floor, ceiling, walls, then the two blocks' top and sides):
// the product never reads the shared data folder.
// clang-format off
constexpr std::array<CornellQuad, 15> kQuads = {{
    {"floor", kWhite,
     {{0.5528f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f},
      {0.0f, 0.0f, 0.5592f}, {0.5496f, 0.0f, 0.5592f}}},
    {"ceiling", kWhite,
     {{0.556f, 0.5488f, 0.0f}, {0.556f, 0.5488f, 0.5592f},
      {0.0f, 0.5488f, 0.5592f}, {0.0f, 0.5488f, 0.0f}}},
    {"back_wall", kWhite,
     {{0.5496f, 0.0f, 0.5592f}, {0.0f, 0.0f, 0.5592f},
      {0.0f, 0.5488f, 0.5592f}, {0.556f, 0.5488f, 0.5592f}}},
    {"right_wall", kGreen,
     {{0.0f, 0.0f, 0.5592f}, {0.0f, 0.0f, 0.0f},
      {0.0f, 0.5488f, 0.0f}, {0.0f, 0.5488f, 0.5592f}}},
    {"left_wall", kRed,
     {{0.5528f, 0.0f, 0.0f}, {0.5496f, 0.0f, 0.5592f},
      {0.556f, 0.5488f, 0.5592f}, {0.556f, 0.5488f, 0.0f}}},
    {"short_block", kWhite,
     {{0.13f, 0.165f, 0.065f}, {0.082f, 0.165f, 0.225f},
      {0.24f, 0.165f, 0.272f}, {0.29f, 0.165f, 0.114f}}},
    {"short_block", kWhite,
     {{0.29f, 0.0f, 0.114f}, {0.29f, 0.165f, 0.114f},
      {0.24f, 0.165f, 0.272f}, {0.24f, 0.0f, 0.272f}}},
    {"short_block", kWhite,
     {{0.13f, 0.0f, 0.065f}, {0.13f, 0.165f, 0.065f},
      {0.29f, 0.165f, 0.114f}, {0.29f, 0.0f, 0.114f}}},
    {"short_block", kWhite,
     {{0.082f, 0.0f, 0.225f}, {0.082f, 0.165f, 0.225f},
      {0.13f, 0.165f, 0.065f}, {0.13f, 0.0f, 0.065f}}},
    {"short_block", kWhite,
     {{0.24f, 0.0f, 0.272f}, {0.24f, 0.165f, 0.272f},
      {0.082f, 0.165f, 0.225f}, {0.082f, 0.0f, 0.225f}}},
    {"tall_block", kWhite,
     {{0.423f, 0.33f, 0.247f}, {0.265f, 0.33f, 0.296f},
      {0.314f, 0.33f, 0.456f}, {0.472f, 0.33f, 0.406f}}},
    {"tall_block", kWhite,
     {{0.423f, 0.0f, 0.247f}, {0.423f, 0.33f, 0.247f},
      {0.472f, 0.33f, 0.406f}, {0.472f, 0.0f, 0.406f}}},
    {"tall_block", kWhite,
     {{0.472f, 0.0f, 0.406f}, {0.472f, 0.33f, 0.406f},
      {0.314f, 0.33f, 0.456f}, {0.314f, 0.0f, 0.456f}}},
    {"tall_block", kWhite,
     {{0.314f, 0.0f, 0.456f}, {0.314f, 0.33f, 0.456f},
      {0.265f, 0.33f, 0.296f}, {0.265f, 0.0f, 0.296f}}},
    {"tall_block", kWhite,
     {{0.265f, 0.0f, 0.296f}, {0.265f, 0.33f, 0.296f},
      {0.423f, 0.33f, 0.247f}, {0.423f, 0.0f, 0.247f}}},
}};
// clang-format on

// The usual RGB fits of the measured reflectance spectra.
Material makeMaterial(const char* name, const glm::vec3& diffuse) {
    Material material;
    material.name = name;
    material.diffuse = diffuse;
    return material;
}

} // namespace

void addCornellBox(Scene& scene, const glm::mat4& worldFromObject) {
    const std::array<uint32_t, 3> materials = {
        findOrAddMaterial(scene, makeMaterial("cornell_white", {0.725f, 0.71f, 0.68f})),
        findOrAddMaterial(scene, makeMaterial("cornell_red", {0.63f, 0.065f, 0.05f})),
        findOrAddMaterial(scene, makeMaterial("cornell_green", {0.14f, 0.45f, 0.091f})),
    };
    Mesh mesh;
    mesh.name = "cornell_box";
    for (const CornellQuad& quad : kQuads) {
        std::array<glm::vec3, 4> p;
        for (size_t i = 0; i < p.size(); ++i) {
            p[i] = {quad.corners[i][0], quad.corners[i][1], quad.corners[i][2]};
        }
        appendQuad(mesh, p[0], p[1], p[2], p[3], materials[static_cast<size_t>(quad.colour)]);
    }
    scene.meshes.push_back(std::move(mesh));
    scene.instances.push_back({static_cast<uint32_t>(scene.meshes.size() - 1), worldFromObject});
}

} // namespace ispm
