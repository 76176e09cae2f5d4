// Objects of a scene file: transforms, inline meshes, boxes, OBJ files and the generators. Each
// object becomes one mesh in object space plus one instance that holds its transform.
#include "core/input_error.h"
#include "core/strings.h"
#include "scene/box_city.h"
#include "scene/cornell_box.h"
#include "scene/gltf_import.h"
#include "scene/mesh_builder.h"
#include "scene/mesh_normals.h"
#include "scene/obj_io.h"
#include "scene/scene_parse.h"

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cmath>
#include <filesystem>

namespace ispm {

namespace {

constexpr size_t kMatrixSize = 4;
constexpr double kMinScale = 1e-6; // `scale`, per axis
constexpr double kMaxScale = 1e6;
// An affine matrix's last row is (0 0 0 1) within this (tools print 1e-17 for zero).
constexpr float kAffineTolerance = 1e-6f;
// |det| of the 3x3 part below this fraction of its columns' length product: flat or singular.
constexpr float kMinRelativeDeterminant = 1e-9f;

// `smooth_angle_deg`: the crease angle up to which generateSmoothNormals joins faces; 0 (the
// default) keeps the mesh flat. Meshes whose file gives normals (OBJ vn, glTF NORMAL) keep those.
constexpr double kMaxSmoothAngleDeg = 180.0;

float parseSmoothAngle(const JsonNode& object) {
    const auto angle = object.find("smooth_angle_deg");
    return angle ? angle->readFloat(NumberRange::getClosed(0.0, kMaxSmoothAngleDeg)) : 0.0f;
}

void smoothMesh(Mesh& mesh, float angleDeg) {
    if (angleDeg > 0.0f && mesh.normals.empty()) generateSmoothNormals(mesh, angleDeg);
}

glm::mat4 parseMatrix(const JsonNode& node) {
    const char* what = "a row-major 4x4 matrix: 4 rows of 4 numbers, or 16 numbers";
    const std::vector<JsonNode> items = node.getElements(what);
    std::vector<JsonNode> numbers;
    if (items.size() == kMatrixSize) {
        for (const JsonNode& row : items) {
            const std::vector<JsonNode> cells = row.getElements("4 numbers (a matrix row)");
            if (cells.size() != kMatrixSize) row.failGot("4 numbers (a matrix row)");
            numbers.insert(numbers.end(), cells.begin(), cells.end());
        }
    } else if (items.size() == kMatrixSize * kMatrixSize) {
        numbers = items;
    } else {
        node.failGot(what);
    }
    glm::mat4 m(1.0f);
    for (size_t r = 0; r < kMatrixSize; ++r) {
        for (size_t c = 0; c < kMatrixSize; ++c) {
            // glm is column-major: m[column][row].
            m[static_cast<int>(c)][static_cast<int>(r)] =
                numbers[r * kMatrixSize + c].readFloat(NumberRange::getAny());
        }
    }
    const glm::vec4 lastRow{m[0][3], m[1][3], m[2][3], m[3][3]};
    if (glm::any(glm::greaterThan(glm::abs(lastRow - glm::vec4(0, 0, 0, 1)),
                                  glm::vec4(kAffineTolerance)))) {
        node.fail("an affine matrix (last row 0 0 0 1)");
    }
    const glm::mat3 linear(m);
    const float scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    if (!(std::fabs(glm::determinant(linear)) > kMinRelativeDeterminant * scale)) {
        node.fail("an invertible matrix (it flattens the object)");
    }
    return m;
}

// p' = T Rz Ry Rx S p: scale, then rotate about x, y, z (fixed axes; Blender's XYZ Euler), then
// translate.
glm::mat4 parseTransform(const JsonNode& object) {
    const bool hasTrs = object.has("translate") || object.has("rotate_deg") || object.has("scale");
    if (auto matrix = object.find("matrix")) {
        if (hasTrs) matrix->fail("either matrix or translate/rotate_deg/scale, not both");
        return parseMatrix(*matrix);
    }
    glm::mat4 m(1.0f);
    if (auto t = object.find("translate")) m = glm::translate(m, t->readVec3());
    if (auto r = object.find("rotate_deg")) {
        const glm::vec3 deg = r->readVec3();
        m = glm::rotate(m, glm::radians(deg.z), glm::vec3(0, 0, 1));
        m = glm::rotate(m, glm::radians(deg.y), glm::vec3(0, 1, 0));
        m = glm::rotate(m, glm::radians(deg.x), glm::vec3(1, 0, 0));
    }
    if (auto s = object.find("scale")) {
        // A millionth to a million: 1e-38 and 1e-45 (a denormal) broke the BVH and the planes.
        const NumberRange positive = NumberRange::getClosed(kMinScale, kMaxScale);
        const glm::vec3 scale =
            s->getJson().is_number() ? glm::vec3(s->readFloat(positive)) : s->readVec3(positive);
        m = glm::scale(m, scale);
    }
    return m;
}

std::array<glm::vec3, 4> readPolygon(const JsonNode& node, size_t count, const char* what) {
    const std::vector<JsonNode> points = node.getElements(what);
    if (points.size() != count) node.failGot(what);
    std::array<glm::vec3, 4> p{};
    for (size_t i = 0; i < count; ++i)
        p[i] = points[i].readVec3();
    return p;
}

void parseTriangles(const JsonNode& node, uint32_t material, Mesh& mesh) {
    const std::vector<JsonNode> triangles = node.getElements("an array of triangles");
    if (triangles.empty()) node.fail("at least one triangle");
    for (const JsonNode& triangle : triangles) {
        const auto p = readPolygon(triangle, 3, "3 points of 3 numbers");
        if (isDegenerateTriangle(p[0], p[1], p[2])) triangle.fail("a triangle with non-zero area");
        appendTriangle(mesh, p[0], p[1], p[2], material);
    }
}

void parseQuads(const JsonNode& node, uint32_t material, Mesh& mesh) {
    const std::vector<JsonNode> quads = node.getElements("an array of quads");
    if (quads.empty()) node.fail("at least one quad");
    for (const JsonNode& quad : quads) {
        const auto p = readPolygon(quad, 4, "4 points of 3 numbers");
        if (isDegenerateTriangle(p[0], p[1], p[2]) || isDegenerateTriangle(p[0], p[2], p[3])) {
            quad.fail("a quad whose triangles (0,1,2) and (0,2,3) both have non-zero area");
        }
        appendQuad(mesh, p[0], p[1], p[2], p[3], material);
    }
}

void parseObjFile(const JsonNode& object, const JsonNode& node, ParseContext& context, Mesh& mesh) {
    const std::string given = node.readString();
    std::filesystem::path path(given);
    if (path.is_relative()) path = std::filesystem::path(context.baseDir) / path;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        node.fail(strCat("an existing OBJ file, cannot open '", path.string(), "'"));
    }
    ObjModel model;
    try {
        model = importObj(path.string());
    } catch (const std::runtime_error& e) {
        node.fail(strCat("a valid OBJ file, '", path.string(), "': ", e.what()));
    }
    if (model.mesh.triangles.empty()) {
        node.fail(strCat("an OBJ file with at least one non-degenerate triangle, '", path.string(),
                         "' has none"));
    }
    const std::string warnings = model.warnings.empty() ? "" : " (" + model.warnings + ")";
    if (auto material = object.find("material")) {
        const uint32_t index = resolveMaterial(*material, context);
        for (uint32_t& m : model.mesh.triangleMaterials)
            m = index;
    } else {
        // The file's own materials, checked as strictly as the scene file's, named after it.
        std::vector<uint32_t> sceneIndex(model.materials.size(), kNoObjMaterial);
        std::vector<uint32_t> sceneTexture(model.textures.size(), kNoTexture);
        for (uint32_t& m : model.mesh.triangleMaterials) {
            if (m == kNoObjMaterial) {
                node.fail(strCat("an OBJ file whose faces all have MTL materials, or a 'material' "
                                 "on the object; '",
                                 path.string(), "' has faces without one", warnings));
            }
            if (sceneIndex[m] == kNoObjMaterial) {
                Material objMaterial = model.materials[m];
                const std::string problem = checkMaterialEnergy(objMaterial);
                if (!problem.empty()) {
                    node.fail(strCat(problem, " in MTL material '", objMaterial.name, "' of '",
                                     path.string(), "' (or a 'material' on the object)"));
                }
                objMaterial.name = given + ":" + objMaterial.name;
                if (objMaterial.diffuseTexture != kNoTexture) { // model's index -> the scene's
                    uint32_t& texture = sceneTexture.at(objMaterial.diffuseTexture);
                    if (texture == kNoTexture) {
                        texture = static_cast<uint32_t>(context.scene.textures.size());
                        context.scene.textures.push_back(
                            model.textures[objMaterial.diffuseTexture]);
                    }
                    objMaterial.diffuseTexture = texture;
                }
                sceneIndex[m] = findOrAddMaterial(context.scene, objMaterial);
            }
            m = sceneIndex[m];
        }
    }
    model.mesh.name = mesh.name;
    mesh = std::move(model.mesh);
}

void parseMesh(const JsonNode& object, ParseContext& context, Mesh& mesh) {
    const int sourceCount = static_cast<int>(object.has("triangles")) +
                            static_cast<int>(object.has("quads")) +
                            static_cast<int>(object.has("obj"));
    if (sourceCount != 1) {
        object.fail("a mesh with exactly one of 'triangles', 'quads' or 'obj'");
    }
    if (auto obj = object.find("obj")) {
        parseObjFile(object, *obj, context, mesh);
        return;
    }
    const uint32_t material = resolveMaterial(object.get("material"), context);
    if (auto triangles = object.find("triangles")) parseTriangles(*triangles, material, mesh);
    if (auto quads = object.find("quads")) parseQuads(*quads, material, mesh);
}

void parseBox(const JsonNode& object, ParseContext& context, Mesh& mesh) {
    const glm::vec3 lo = object.get("min").readVec3();
    const JsonNode maxNode = object.get("max");
    const glm::vec3 hi = maxNode.readVec3();
    if (!glm::all(glm::greaterThan(hi, lo))) maxNode.fail("max > min in every axis");
    appendBox(mesh, lo, hi, resolveMaterial(object.get("material"), context));
}

BoxCityParams parseBoxCityParams(const JsonNode& object, ParseContext& context) {
    BoxCityParams p;
    const NumberRange positive = NumberRange::getAbove(0.0);
    const NumberRange nonNegative = NumberRange::getAtLeast(0.0);
    if (auto v = object.find("blocks")) p.blocks = v->readIVec2(1, kMaxCityBlocksPerAxis);
    if (auto v = object.find("block_size")) p.blockSizeM = v->readVec2(positive);
    if (auto v = object.find("street_width")) p.streetWidthM = v->readFloat(nonNegative);
    if (auto v = object.find("alley_width")) p.alleyWidthM = v->readFloat(nonNegative);
    if (auto v = object.find("lots_per_block")) {
        p.lotsPerBlock = v->readIVec2(1, kMaxCityBlocksPerAxis);
    }
    if (auto v = object.find("building_height")) p.buildingHeightM = v->readFloatPair(positive);
    if (auto v = object.find("building_inset")) p.buildingInsetM = v->readFloatPair(nonNegative);
    if (auto v = object.find("attachments")) {
        p.attachments = v->readIntPair(0, kMaxAttachmentsPerBuilding);
    }
    if (auto v = object.find("attachment_size")) {
        p.attachmentSize = v->readFloatPair(NumberRange::getLeftOpen(0.0, 1.0));
    }
    if (auto v = object.find("seed")) p.seed = v->readUint64();
    if (auto v = object.find("material")) {
        p.buildingMaterial = static_cast<int32_t>(resolveMaterial(*v, context));
    }
    if (auto v = object.find("ground_material")) {
        p.groundMaterial = static_cast<int32_t>(resolveMaterial(*v, context));
    }
    // Constraints between keys (lots must fit their blocks, insets their lots ...).
    if (const auto error = checkBoxCityParams(p)) {
        throwInputError(object.getFile(), object.getPath() + "/" + error->key, error->expected);
    }
    return p;
}

} // namespace

void parseObject(const JsonNode& object, size_t index, ParseContext& context) {
    object.requireObject("an object");
    const JsonNode typeNode = object.get("type");
    const std::string type = typeNode.readString();
    Scene& scene = context.scene;
    const size_t firstInstance = scene.instances.size();
    Mesh mesh;
    mesh.name = object.has("name") ? object.get("name").readString() : strCat("object_", index);

    if (type == "mesh") {
        object.checkKeys({"type", "name", "matrix", "translate", "rotate_deg", "scale", "material",
                          "triangles", "quads", "obj", "smooth_angle_deg", "animation"},
                         "a mesh object");
        const glm::mat4 worldFromObject = parseTransform(object);
        parseMesh(object, context, mesh);
        smoothMesh(mesh, parseSmoothAngle(object));
        scene.meshes.push_back(std::move(mesh));
        scene.instances.push_back(
            {static_cast<uint32_t>(scene.meshes.size() - 1), worldFromObject});
    } else if (type == "box") {
        object.checkKeys({"type", "name", "matrix", "translate", "rotate_deg", "scale", "material",
                          "min", "max", "animation"},
                         "a box object");
        const glm::mat4 worldFromObject = parseTransform(object);
        parseBox(object, context, mesh);
        scene.meshes.push_back(std::move(mesh));
        scene.instances.push_back(
            {static_cast<uint32_t>(scene.meshes.size() - 1), worldFromObject});
    } else if (type == "cornell_box") {
        object.checkKeys(
            {"type", "name", "matrix", "translate", "rotate_deg", "scale", "animation"},
            "a cornell_box object");
        addCornellBox(scene, parseTransform(object));
        if (object.has("name")) scene.meshes.back().name = mesh.name;
    } else if (type == "box_city") {
        object.checkKeys({"type", "name", "matrix", "translate", "rotate_deg", "scale", "blocks",
                          "block_size", "street_width", "alley_width", "lots_per_block",
                          "building_height", "building_inset", "attachments", "attachment_size",
                          "seed", "material", "ground_material", "animation"},
                         "a box_city object");
        const glm::mat4 worldFromObject = parseTransform(object);
        addBoxCity(scene, parseBoxCityParams(object, context), worldFromObject);
        if (object.has("name")) scene.meshes.back().name = mesh.name;
    } else if (type == "gltf") {
        object.checkKeys({"type", "name", "matrix", "translate", "rotate_deg", "scale", "path",
                          "smooth_angle_deg", "animation"},
                         "a gltf object");
        const float smoothAngleDeg = parseSmoothAngle(object);
        const size_t firstMesh = scene.meshes.size();
        const glm::mat4 worldFromObject = parseTransform(object);
        const JsonNode pathNode = object.get("path");
        std::filesystem::path path(pathNode.readString());
        if (path.is_relative()) path = std::filesystem::path(context.baseDir) / path;
        std::error_code ec;
        if (!isGltfPath(path.string()) || !std::filesystem::is_regular_file(path, ec)) {
            pathNode.fail(
                strCat("an existing .gltf or .glb file, cannot open '", path.string(), "'"));
        }
        // The file's cameras join the scene's named cameras (--camera NAME).
        for (auto& camera : importGltf(path.string(), worldFromObject, scene))
            scene.namedCameras.push_back(std::move(camera));
        for (size_t m = firstMesh; m < scene.meshes.size(); ++m)
            smoothMesh(scene.meshes[m], smoothAngleDeg);
    } else {
        typeNode.failGot("an object type: mesh, box, cornell_box, box_city or gltf");
    }
    if (auto animation = object.find("animation")) {
        // Every instance the object made moves as one; without a pivot it turns about its origin.
        const glm::vec3 originW(scene.instances.at(firstInstance).worldFromObject[3]);
        const Animation parsed = parseAnimation(*animation, AnimationTarget::Object, originW);
        for (size_t i = firstInstance; i < scene.instances.size(); ++i) {
            scene.instanceAnimations.push_back(
                {static_cast<uint32_t>(i), scene.instances[i].worldFromObject, parsed});
        }
    }
}

} // namespace ispm
