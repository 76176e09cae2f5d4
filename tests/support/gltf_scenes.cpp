// The checker room as a glTF model built field by field and written by tinygltf.
#include "support/gltf_scenes.h"

#include <tiny_gltf.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace ispm::test {

namespace {

constexpr double kHalfSqrt2 = 0.70710678118654752;

// Appends `bytes` bytes to the buffer and a view over them; returns the view.
int appendBufferView(tinygltf::Model& model, const void* data, size_t bytes) {
    tinygltf::Buffer& buffer = model.buffers[0];
    const size_t offset = buffer.data.size();
    buffer.data.resize(offset + bytes);
    std::memcpy(buffer.data.data() + offset, data, bytes);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = bytes;
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size() - 1);
}

// Appends a float array to the buffer and a view + accessor over it; returns the accessor.
int addFloatAccessor(tinygltf::Model& model, const std::vector<float>& values, int type,
                     size_t count) {
    tinygltf::Accessor accessor;
    accessor.bufferView = appendBufferView(model, values.data(), values.size() * sizeof(float));
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.type = type;
    accessor.count = count;
    if (type == TINYGLTF_TYPE_VEC3) { // glTF requires min/max on positions
        accessor.minValues = {1e30, 1e30, 1e30};
        accessor.maxValues = {-1e30, -1e30, -1e30};
        for (size_t i = 0; i < count; ++i) {
            for (size_t c = 0; c < 3; ++c) {
                accessor.minValues[c] = std::min(accessor.minValues[c], double(values[3 * i + c]));
                accessor.maxValues[c] = std::max(accessor.maxValues[c], double(values[3 * i + c]));
            }
        }
    }
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size() - 1);
}

// Triangle indices as unsigned ints in a view of their own; the accessor's index.
int addIndexAccessor(tinygltf::Model& model, const std::vector<uint32_t>& indices) {
    tinygltf::Accessor accessor;
    accessor.bufferView =
        appendBufferView(model, indices.data(), indices.size() * sizeof(uint32_t));
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    accessor.type = TINYGLTF_TYPE_SCALAR;
    accessor.count = indices.size();
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size() - 1);
}

// A square at height y facing `up` (or down), with texture coordinates 0..1 over it.
int addSquareMesh(tinygltf::Model& model, float halfM, float y, bool facingUp, int material) {
    const float h = halfM;
    const std::vector<float> positions = {-h, y, -h, h, y, -h, h, y, h, -h, y, h};
    // u along +x, v along +z: square (i, j) of the checker lies at x = -h + (i + 0.5) ...
    const std::vector<float> uvs = {0, 0, 1, 0, 1, 1, 0, 1};
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = addFloatAccessor(model, positions, TINYGLTF_TYPE_VEC3, 4);
    prim.attributes["TEXCOORD_0"] = addFloatAccessor(model, uvs, TINYGLTF_TYPE_VEC2, 4);
    // Counter-clockwise seen from the side the square faces.
    const std::vector<uint16_t> indices = facingUp ? std::vector<uint16_t>{0, 2, 1, 0, 3, 2}
                                                   : std::vector<uint16_t>{0, 1, 2, 0, 2, 3};
    // Indices as unsigned shorts (little-endian) in their own view.
    tinygltf::Buffer& buffer = model.buffers[0];
    const size_t offset = buffer.data.size();
    buffer.data.resize(offset + indices.size() * sizeof(uint16_t));
    std::memcpy(buffer.data.data() + offset, indices.data(), indices.size() * sizeof(uint16_t));
    buffer.data.resize((buffer.data.size() + 3) / 4 * 4); // keep later float views aligned
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = indices.size() * sizeof(uint16_t);
    model.bufferViews.push_back(view);
    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model.bufferViews.size() - 1);
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    accessor.type = TINYGLTF_TYPE_SCALAR;
    accessor.count = indices.size();
    model.accessors.push_back(accessor);
    prim.indices = static_cast<int>(model.accessors.size() - 1);
    prim.material = material;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(prim);
    model.meshes.push_back(mesh);
    return static_cast<int>(model.meshes.size() - 1);
}

int addMaterial(tinygltf::Model& model, const std::string& name, int texture) {
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = 1.0;
    m.pbrMetallicRoughness.baseColorTexture.index = texture;
    m.doubleSided = true;
    model.materials.push_back(m);
    return static_cast<int>(model.materials.size() - 1);
}

// A node turned so its -z axis points down (-y) or up (+y).
tinygltf::Node makeVerticalNode(glm::vec3 position, bool up) {
    tinygltf::Node node;
    node.translation = {position.x, position.y, position.z};
    // +-90 degrees about x: -z -> -y (down) or +y (up).
    node.rotation = {up ? kHalfSqrt2 : -kHalfSqrt2, 0.0, 0.0, kHalfSqrt2};
    return node;
}

// A spot light shining down (or up) from `position`, in the scene.
void addSpotNode(tinygltf::Model& model, tinygltf::Scene& scene, glm::vec3 position, bool up,
                 float candela, float innerConeRad, float outerConeRad) {
    tinygltf::Light light;
    light.name = "spot";
    light.type = "spot";
    light.color = {1.0, 1.0, 1.0};
    light.intensity = candela;
    light.spot.innerConeAngle = innerConeRad;
    light.spot.outerConeAngle = outerConeRad;
    model.lights.push_back(light);
    tinygltf::Node lightNode = makeVerticalNode(position, up);
    lightNode.name = "spot";
    tinygltf::Value::Object lightRef;
    lightRef["light"] = tinygltf::Value(static_cast<int>(model.lights.size() - 1));
    lightNode.extensions["KHR_lights_punctual"] = tinygltf::Value(lightRef);
    model.nodes.push_back(lightNode);
    scene.nodes.push_back(static_cast<int>(model.nodes.size() - 1));
}

// A camera looking down (or up) from `position`, in the scene.
void addCameraNode(tinygltf::Model& model, tinygltf::Scene& scene, glm::vec3 position, bool up,
                   float yFovRad) {
    tinygltf::Camera camera;
    camera.name = "eye";
    camera.type = "perspective";
    camera.perspective.yfov = yFovRad;
    camera.perspective.znear = 0.01;
    camera.perspective.zfar = 100.0;
    camera.perspective.aspectRatio = 1.0;
    model.cameras.push_back(camera);
    tinygltf::Node cameraNode = makeVerticalNode(position, up);
    cameraNode.camera = static_cast<int>(model.cameras.size() - 1);
    // The image's up is the node's +y turned: -z looking down, +z looking up.
    model.nodes.push_back(cameraNode);
    scene.nodes.push_back(static_cast<int>(model.nodes.size() - 1));
}

void writeModel(tinygltf::Model& model, tinygltf::Scene scene, const std::string& path) {
    model.scenes.push_back(std::move(scene));
    model.defaultScene = 0;
    model.extensionsUsed.push_back("KHR_lights_punctual");
    tinygltf::TinyGLTF writer;
    const bool binary = path.size() > 4 && path.substr(path.size() - 4) == ".glb";
    if (!writer.WriteGltfSceneToFile(&model, path, true, true, !binary, binary)) {
        throw std::runtime_error("tinygltf could not write " + path);
    }
}

} // namespace

glm::vec3 getCheckerColor(const CheckerRoom& room, int i, int j) {
    const std::array<uint8_t, 3>& c = (i + j) % 2 == 0 ? room.colorA : room.colorB;
    glm::vec3 linear;
    for (int k = 0; k < 3; ++k) {
        const float s = float(c[static_cast<size_t>(k)]) / 255.0f;
        linear[k] = s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
    }
    return linear;
}

void writeCheckerRoomGltf(const std::string& path, const CheckerRoom& room) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.buffers.resize(1);

    tinygltf::Image image;
    image.name = "checker";
    image.width = room.checks * room.texelsPerCheck;
    image.height = image.width;
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.mimeType = "image/png";
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            // Row y of the image is v = y / height: square j along +z (v), i along +x (u).
            const int i = x / room.texelsPerCheck;
            const int j = y / room.texelsPerCheck;
            const std::array<uint8_t, 3>& c = (i + j) % 2 == 0 ? room.colorA : room.colorB;
            image.image.insert(image.image.end(), {c[0], c[1], c[2], 255});
        }
    }
    model.images.push_back(image);
    tinygltf::Texture texture;
    texture.source = 0;
    model.textures.push_back(texture);

    const int floorMaterial = addMaterial(model, "checker", 0);
    const int whiteMaterial = addMaterial(model, "white", -1);
    tinygltf::Scene scene;
    model.nodes.emplace_back();
    model.nodes.back().mesh = addSquareMesh(model, room.halfM, 0.0f, true, floorMaterial);
    model.nodes.back().name = "floor";
    scene.nodes.push_back(static_cast<int>(model.nodes.size() - 1));
    if (room.ceilingM > 0.0f) {
        model.nodes.emplace_back();
        model.nodes.back().mesh =
            addSquareMesh(model, room.halfM, room.ceilingM, false, whiteMaterial);
        model.nodes.back().name = "ceiling";
        scene.nodes.push_back(static_cast<int>(model.nodes.size() - 1));
    }

    addSpotNode(model, scene, glm::vec3(0.0f, room.lightHeightM, 0.0f), room.lightUp, room.candela,
                room.innerConeRad, room.outerConeRad);
    addCameraNode(model, scene, room.cameraPositionM, room.cameraUp, room.cameraYFovRad);
    writeModel(model, std::move(scene), path);
}

void writeLeafCardGltf(const std::string& path, const LeafCard& card) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.buffers.resize(1);

    tinygltf::Image image;
    image.name = "leaf";
    image.width = card.texelsPerSide;
    image.height = card.texelsPerSide;
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.mimeType = "image/png";
    constexpr uint8_t kLeafGreen[3] = {60, 160, 60}; // sRGB
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float u = (float(x) + 0.5f) / float(image.width) - 0.5f;
            const float v = (float(y) + 0.5f) / float(image.height) - 0.5f;
            const bool inside = u * u + v * v < card.discRadius * card.discRadius;
            image.image.insert(image.image.end(), {kLeafGreen[0], kLeafGreen[1], kLeafGreen[2],
                                                   uint8_t(inside ? 255 : 0)});
        }
    }
    model.images.push_back(image);
    tinygltf::Texture texture;
    texture.source = 0;
    model.textures.push_back(texture);

    const int floorMaterial = addMaterial(model, "floor", -1);
    const int leafMaterial = addMaterial(model, "leaf", 0);
    tinygltf::Material& leaf = model.materials[static_cast<size_t>(leafMaterial)];
    leaf.alphaMode = card.alphaMode;
    leaf.alphaCutoff = card.alphaCutoff;
    leaf.pbrMetallicRoughness.baseColorFactor[3] = card.factorAlpha;
    tinygltf::Scene scene;
    model.nodes.emplace_back();
    model.nodes.back().mesh = addSquareMesh(model, card.floorHalfM, 0.0f, true, floorMaterial);
    model.nodes.back().name = "floor";
    scene.nodes.push_back(0);
    model.nodes.emplace_back();
    model.nodes.back().mesh =
        addSquareMesh(model, card.cardHalfM, card.cardHeightM, true, leafMaterial);
    model.nodes.back().name = "leaf";
    scene.nodes.push_back(1);
    addSpotNode(model, scene, glm::vec3(0.0f, card.lightHeightM, 0.0f), false, card.candela,
                card.innerConeRad, card.outerConeRad);
    addCameraNode(model, scene, glm::vec3(0.0f, card.cameraHeightM, 0.0f), false,
                  card.cameraYFovRad);
    writeModel(model, std::move(scene), path);
}

int writeSphereGltf(const std::string& path, const TessellatedSphere& sphere) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.buffers.resize(1);
    std::vector<float> positions;
    std::vector<float> normals;
    for (int r = 0; r <= sphere.rings; ++r) {
        const float theta = glm::pi<float>() * float(r) / float(sphere.rings); // from +y
        // The poles exactly on the axis (sin(pi) in float is not 0): one point each.
        const bool pole = r == 0 || r == sphere.rings;
        const float sinTheta = pole ? 0.0f : std::sin(theta);
        for (int s = 0; s <= sphere.segments; ++s) {
            // The seam's two columns at exactly the same points, as exporters write them.
            const float phi =
                glm::two_pi<float>() * float(s % sphere.segments) / float(sphere.segments);
            const glm::vec3 n(sinTheta * std::cos(phi), std::cos(theta), -sinTheta * std::sin(phi));
            const glm::vec3 p = sphere.radiusM * n;
            positions.insert(positions.end(), {p.x, p.y, p.z});
            const bool bad = int(normals.size() / 3) == sphere.badNormalIndex;
            const glm::vec3 written = bad ? sphere.badNormal : n;
            normals.insert(normals.end(), {written.x, written.y, written.z});
        }
    }
    const int vertexCount = int(positions.size() / 3);
    std::vector<uint32_t> indices;
    const auto at = [&](int r, int s) { return uint32_t(r * (sphere.segments + 1) + s); };
    for (int r = 0; r < sphere.rings; ++r) {
        for (int s = 0; s < sphere.segments; ++s) {
            // phi turns counter-clockwise seen from +y, theta runs down: (r, s), (r + 1, s),
            // (r + 1, s + 1) is counter-clockwise seen from outside. The poles' zero-area
            // triangles are left out.
            if (r > 0) indices.insert(indices.end(), {at(r, s), at(r + 1, s), at(r, s + 1)});
            if (r + 1 < sphere.rings) {
                indices.insert(indices.end(), {at(r, s + 1), at(r + 1, s), at(r + 1, s + 1)});
            }
        }
    }
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] =
        addFloatAccessor(model, positions, TINYGLTF_TYPE_VEC3, size_t(vertexCount));
    if (sphere.withNormals) {
        const int accessor =
            addFloatAccessor(model, normals, TINYGLTF_TYPE_VEC3, size_t(vertexCount));
        // Bounds are optional here, and a bad normal's NaN would not survive the JSON.
        model.accessors[size_t(accessor)].minValues.clear();
        model.accessors[size_t(accessor)].maxValues.clear();
        prim.attributes["NORMAL"] = accessor;
    }
    prim.indices = addIndexAccessor(model, indices);
    prim.material = addMaterial(model, "sphere", -1);
    const double albedo = sphere.albedo;
    model.materials.back().pbrMetallicRoughness.baseColorFactor = {albedo, albedo, albedo, 1.0};
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = "sphere";
    mesh.primitives.push_back(prim);
    model.meshes.push_back(mesh);
    model.nodes.emplace_back();
    model.nodes.back().mesh = 0;
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&model, path, true, true, true, false)) {
        throw std::runtime_error("tinygltf could not write " + path);
    }
    return vertexCount;
}

glm::vec4 getPlaneTangent(PlaneUv uv) {
    switch (uv) {
    case PlaneUv::Standard:
        return {1.0f, 0.0f, 0.0f, 1.0f};
    case PlaneUv::FlippedV:
        return {1.0f, 0.0f, 0.0f, -1.0f};
    case PlaneUv::Rotated:
        return {0.0f, 0.0f, 1.0f, 1.0f};
    }
    return {};
}

void writeNormalMappedPlaneGltf(const std::string& path, const NormalMappedPlane& plane) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.buffers.resize(1);
    tinygltf::Image image;
    image.name = "normal_map";
    image.width = plane.texelsPerSide;
    image.height = plane.texelsPerSide;
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.mimeType = "image/png";
    for (int i = 0; i < image.width * image.height; ++i)
        image.image.insert(image.image.end(),
                           {plane.texel[0], plane.texel[1], plane.texel[2], 255});
    model.images.push_back(image);
    tinygltf::Texture texture;
    texture.source = 0;
    model.textures.push_back(texture);
    const int material = addMaterial(model, "bumpy", -1);
    model.materials.back().normalTexture.index = 0;

    const float h = plane.halfM;
    const std::vector<float> positions = {-h, 0, -h, h, 0, -h, h, 0, h, -h, 0, h};
    // Corner (x, z) in {-h, h}^2 to (u, v) as the layouts above say.
    std::vector<float> uvs;
    for (size_t c = 0; c < 4; ++c) {
        const float x = positions[3 * c] > 0.0f ? 1.0f : 0.0f;
        const float z = positions[3 * c + 2] > 0.0f ? 1.0f : 0.0f;
        switch (plane.uv) {
        case PlaneUv::Standard:
            uvs.insert(uvs.end(), {x, z});
            break;
        case PlaneUv::FlippedV:
            uvs.insert(uvs.end(), {x, 1.0f - z});
            break;
        case PlaneUv::Rotated:
            uvs.insert(uvs.end(), {z, 1.0f - x});
            break;
        }
    }
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = addFloatAccessor(model, positions, TINYGLTF_TYPE_VEC3, 4);
    prim.attributes["TEXCOORD_0"] = addFloatAccessor(model, uvs, TINYGLTF_TYPE_VEC2, 4);
    if (plane.writeNormals) {
        const std::vector<float> normals = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
        prim.attributes["NORMAL"] = addFloatAccessor(model, normals, TINYGLTF_TYPE_VEC3, 4);
    }
    if (plane.writeTangents) {
        const glm::vec4 t = getPlaneTangent(plane.uv);
        std::vector<float> tangents;
        for (int c = 0; c < 4; ++c)
            tangents.insert(tangents.end(), {t.x, t.y, t.z, t.w});
        prim.attributes["TANGENT"] = addFloatAccessor(model, tangents, TINYGLTF_TYPE_VEC4, 4);
    }
    // Counter-clockwise seen from +y, as unsigned ints in their own view.
    const std::vector<uint32_t> indices = {0, 2, 1, 0, 3, 2};
    prim.indices = addIndexAccessor(model, indices);
    prim.material = material;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = "plane";
    mesh.primitives.push_back(prim);
    model.meshes.push_back(mesh);
    model.nodes.emplace_back();
    model.nodes.back().mesh = 0;
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&model, path, true, true, true, false)) {
        throw std::runtime_error("tinygltf could not write " + path);
    }
}

} // namespace ispm::test
