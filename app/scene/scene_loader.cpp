// Scene files to the scene model: the top level, camera, lights and render settings (materials
// and objects have their own files). The format is documented in docs/scene-format.md.
#include "scene/scene_loader.h"

#include "core/input_error.h"
#include "core/strings.h"
#include "image/image_io.h"
#include "scene/gltf_import.h"
#include "scene/scene_parse.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace ispm {

namespace {

// A spot's light camera has a field of view of twice its outer angle: at 90 degrees the
// perspective projection degenerates, so the outer half-angle stops just short of it.
constexpr double kMaxSpotHalfAngleDeg = 89.9;
constexpr double kMaxLightPower = 1e12;
// The camera's up vector must make at least this sine with the view direction to define a roll.
constexpr float kMinUpSine = 1e-4f;
constexpr double kMaxFovYDeg = 180.0; // exclusive: a pinhole sees less than a half space
// Camera keys lie within this many seconds (11.6 days): later times lose float precision in the
// spline's interpolation parameter long before.
constexpr double kMaxAnimationTimeS = 1e6;

// The view direction from `position` to `target` must exist and make a roll with `up`.
void checkView(const JsonNode& node, const JsonNode& targetNode, const glm::vec3& position,
               const glm::vec3& target, const glm::vec3& up,
               const std::optional<JsonNode>& upNode) {
    const glm::vec3 forward = target - position;
    if (!(glm::length(forward) > 0.0f)) targetNode.fail("a target different from the position");
    if (!(glm::length(glm::cross(glm::normalize(forward), up)) > kMinUpSine)) {
        // The default up fails for a camera looking straight up or down: the file must say.
        const std::string what = "an up vector not parallel to the view direction";
        if (upNode) upNode->fail(what + strCat(" (at ", node.getPath(), ")"));
        throwInputError(node.getFile(), node.getPath() + "/up",
                        what + " (the default is [0, 1, 0])");
    }
}

// A camera path: keys in increasing time, each a position and target (and a field of view,
// else the camera's).
std::vector<CameraKey> parseCameraPath(const JsonNode& node, const Camera& camera,
                                       const std::optional<JsonNode>& upNode) {
    const std::vector<JsonNode> keyNodes = node.getElements("an array of camera keys");
    if (keyNodes.size() < 2) node.fail("at least two keys (one key is a still camera)");
    std::vector<CameraKey> keys;
    for (const JsonNode& k : keyNodes) {
        k.checkKeys({"time_s", "position", "target", "fov_y_deg"}, "a camera key");
        CameraKey key;
        const JsonNode time = k.get("time_s");
        key.timeS = time.readNumber(NumberRange::getClosed(0.0, kMaxAnimationTimeS));
        if (!keys.empty() && !(key.timeS > keys.back().timeS)) {
            time.failGot(strCat("a time after the previous key's (",
                                formatFloat(float(keys.back().timeS)), " s)"));
        }
        key.position = k.get("position").readVec3();
        const JsonNode target = k.get("target");
        key.target = target.readVec3();
        checkView(k, target, key.position, key.target, camera.up, upNode);
        key.fovYDeg = camera.fovYDeg;
        if (auto fov = k.find("fov_y_deg")) {
            key.fovYDeg = fov->readFloat(NumberRange::getOpen(0.0, kMaxFovYDeg));
        }
        keys.push_back(key);
    }
    return keys;
}

Camera parseCamera(const JsonNode& node) {
    node.checkKeys({"position", "target", "up", "fov_y_deg", "near", "far", "path"}, "the camera");
    Camera camera;
    const std::optional<JsonNode> up = node.find("up");
    if (up) camera.up = up->readDirection();
    if (auto fov = node.find("fov_y_deg")) {
        camera.fovYDeg = fov->readFloat(NumberRange::getOpen(0.0, kMaxFovYDeg));
    }
    const std::optional<JsonNode> path = node.find("path");
    if (path) {
        // The path says where the camera is: a position or target beside it would be ignored.
        for (const char* key : {"position", "target"}) {
            if (auto n = node.find(key))
                n->fail("no position or target beside a path (its keys give them)");
        }
        camera.path = parseCameraPath(*path, camera, up);
        const CameraPose start = evaluateCameraPath(camera.path, 0.0);
        camera.position = start.position;
        camera.target = start.target;
        camera.fovYDeg = start.fovYDeg;
    } else {
        camera.position = node.get("position").readVec3();
        const JsonNode target = node.get("target");
        camera.target = target.readVec3();
        checkView(node, target, camera.position, camera.target, camera.up, up);
    }
    if (auto nearNode = node.find("near")) {
        camera.nearM = nearNode->readFloat(NumberRange::getAbove(0.0));
    }
    if (auto farNode = node.find("far")) {
        camera.farM = farNode->readFloat(NumberRange::getAbove(0.0));
        if (camera.nearM > 0.0f && !(camera.farM > camera.nearM)) {
            farNode->failGot(strCat("far > near (", formatFloat(camera.nearM), ")"));
        }
    }
    return camera;
}

Light parseLight(const JsonNode& node) {
    node.requireObject("a light");
    const JsonNode typeNode = node.get("type");
    const std::string type = typeNode.readString();
    // Up to 1e12 W/sr or W/m^2 (the sun gives 1e3 W/m^2): 3e38 W/sr overflowed photon powers.
    const NumberRange nonNegative = NumberRange::getClosed(0.0, kMaxLightPower);
    Light light;
    if (type == "point") {
        node.checkKeys({"type", "position", "intensity", "photon_share", "animation"},
                       "a point light");
        light.type = LightType::Point;
        light.position = node.get("position").readVec3();
        light.intensity = node.get("intensity").readVec3(nonNegative);
    } else if (type == "spot") {
        node.checkKeys({"type", "position", "direction", "intensity", "inner_deg", "outer_deg",
                        "photon_share", "animation"},
                       "a spot light");
        light.type = LightType::Spot;
        light.position = node.get("position").readVec3();
        light.direction = node.get("direction").readDirection();
        light.intensity = node.get("intensity").readVec3(nonNegative);
        light.outerDeg =
            node.get("outer_deg").readFloat(NumberRange::getLeftOpen(0.0, kMaxSpotHalfAngleDeg));
        const JsonNode inner = node.get("inner_deg");
        light.innerDeg = inner.readFloat(NumberRange::getClosed(0.0, kMaxSpotHalfAngleDeg));
        if (light.innerDeg > light.outerDeg) {
            inner.failGot(strCat("inner_deg <= outer_deg (", formatFloat(light.outerDeg), ")"));
        }
    } else if (type == "sun") {
        node.checkKeys({"type", "direction", "irradiance", "photon_share", "animation"},
                       "a sun light");
        light.type = LightType::Sun;
        light.direction = node.get("direction").readDirection();
        light.irradiance = node.get("irradiance").readVec3(nonNegative);
    } else {
        typeNode.failGot("a light type: point, spot, sun or area");
    }
    if (auto share = node.find("photon_share")) light.photonShare = share->readFloat(nonNegative);
    if (auto animation = node.find("animation")) {
        const AnimationTarget target = light.type == LightType::Point  ? AnimationTarget::PointLight
                                       : light.type == LightType::Spot ? AnimationTarget::SpotLight
                                                                       : AnimationTarget::SunLight;
        light.animation = LightAnimation{light.position, light.direction,
                                         parseAnimation(*animation, target, light.position)};
    }
    return light;
}

void parseRender(const JsonNode& node, Settings& settings) {
    node.requireObject("render settings by name");
    for (const auto& [name, value] : node.getMembers()) {
        const std::string where = strCat(node.getFile(), ": ", value.getPath());
        const nlohmann::json& json = value.getJson();
        const SettingDesc* desc = findSetting(name);
        if (json.is_number() && desc && desc->type == SettingType::Enum) {
            // A number would be read as the index of a choice ("tonemap": 1 meant filmic).
            std::string choices;
            for (std::string_view c : desc->choices)
                choices += strCat(choices.empty() ? "" : ", ", c);
            value.failGot(strCat("one of ", choices, " (a name, not a number)"));
        } else if (json.is_number()) {
            settings.set(name, json.get<double>(), where);
        } else if (json.is_string()) {
            settings.setEnum(name, json.get<std::string>(), where);
        } else {
            value.failGot("a setting value (a number or a name)");
        }
    }
}

// An image environment: an equirectangular EXR or PFM image, 2:1, every texel finite and >= 0,
// found beside the scene file when its path is relative (as OBJ files are).
Environment parseImageEnvironment(const JsonNode& node, const std::string& baseDir) {
    node.checkKeys({"type", "image", "rotation_deg", "scale"}, "an image environment");
    const JsonNode imageNode = node.get("image");
    std::filesystem::path path(imageNode.readString());
    if (path.is_relative()) path = std::filesystem::path(baseDir) / path;
    const std::string file = path.string();
    const std::string ext = path.extension().string();
    const auto isExtension = [&](const char* e) {
        return ext.size() == 4 && std::equal(ext.begin(), ext.end(), e, [](char a, char b) {
                   return std::tolower(static_cast<unsigned char>(a)) == b;
               });
    };
    if (!isExtension(".exr") && !isExtension(".pfm")) {
        imageNode.fail(strCat("an EXR or PFM image (.exr, .pfm), got '", file, "'"));
    }
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        imageNode.fail(strCat("an existing EXR or PFM image, cannot open '", file, "'"));
    }
    Image image;
    try {
        image = readImage(file);
    } catch (const std::runtime_error& e) {
        imageNode.fail(strCat("a readable EXR or PFM image, '", file, "': ", e.what()));
    }
    if (image.height < 1 || image.width != 2 * image.height) {
        imageNode.fail(strCat("an equirectangular image twice as wide as it is high, '", file,
                              "' is ", image.width, " x ", image.height));
    }
    float scale = 1.0f;
    if (auto s = node.find("scale")) scale = s->readFloat(NumberRange::getClosed(0.0, 1e6));
    float rotationDeg = 0.0f;
    if (auto r = node.find("rotation_deg")) {
        rotationDeg = r->readFloat(NumberRange::getClosed(-360.0, 360.0));
    }
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 texel = image.at(x, y);
            for (int c = 0; c < 3; ++c) {
                if (std::isfinite(texel[c]) && texel[c] >= 0.0f &&
                    std::isfinite(texel[c] * scale)) {
                    continue;
                }
                imageNode.fail(strCat("an image of finite radiance >= 0 (x scale), '", file,
                                      "' has ", texel[c], " at texel (", x, ", ", y, ") channel ",
                                      c));
            }
        }
    }
    return makeImageEnvironment(image, scale, rotationDeg);
}

// `environment`: a constant radiance, the sky tied to a sun (its own `sun_direction`, else the
// scene's first sun light's), or an equirectangular image.
Environment parseEnvironment(const JsonNode& node, const std::vector<Light>& lights,
                             const std::string& baseDir) {
    node.requireObject("an environment");
    const auto typeFound = node.find("type");
    if (!typeFound && node.find("image")) return parseImageEnvironment(node, baseDir);
    const JsonNode typeNode = node.get("type");
    const std::string type = typeNode.readString();
    if (type == "image") return parseImageEnvironment(node, baseDir);
    Environment environment;
    if (type == "constant") {
        node.checkKeys({"type", "radiance"}, "a constant environment");
        environment.type = EnvironmentType::Constant;
        environment.radiance =
            node.get("radiance").readVec3(NumberRange::getClosed(0.0, kMaxLightPower));
        return environment;
    }
    if (type != "sky") typeNode.failGot("an environment type: constant, sky or image");
    node.checkKeys({"type", "turbidity", "scale", "sun_direction"}, "a sky environment");
    environment.type = EnvironmentType::Sky;
    if (auto t = node.find("turbidity")) {
        environment.turbidity = t->readFloat(NumberRange::getClosed(1.7, 10.0));
    }
    if (auto scale = node.find("scale")) {
        environment.scale = scale->readFloat(NumberRange::getClosed(0.0, 1e6));
    }
    if (auto direction = node.find("sun_direction")) {
        environment.sunDirection = direction->readDirection();
        return environment;
    }
    for (const Light& light : lights) {
        if (light.type == LightType::Sun) {
            environment.sunDirection = light.direction;
            return environment;
        }
    }
    node.fail("a sun_direction, or a sun light in `lights` to tie the sky to");
}

} // namespace

void selectCamera(Scene& scene, const std::string& name) {
    if (name.empty()) return;
    std::string known;
    for (const auto& [cameraName, camera] : scene.namedCameras) {
        if (cameraName == name) {
            scene.camera = camera;
            return;
        }
        known += (known.empty() ? "" : ", ") + cameraName;
    }
    throwInputError(
        scene.sourcePath, "/cameras",
        strCat("a camera named '", name, "' (named: ", known.empty() ? "none" : known, ")"));
}

Scene parseScene(const nlohmann::json& doc, const std::string& file, const std::string& baseDir) {
    const JsonNode root(doc, "", file);
    root.checkKeys({"name", "description", "camera", "cameras", "background", "environment",
                    "materials", "objects", "lights", "render"},
                   "a scene");
    Scene scene;
    scene.sourcePath = file;
    ParseContext context{scene, baseDir, {}};
    // Only checked: names and descriptions are for people reading the file.
    if (auto name = root.find("name")) name->readString();
    if (auto description = root.find("description")) description->readString();

    if (auto materials = root.find("materials")) parseMaterials(*materials, context);
    scene.camera = parseCamera(root.get("camera"));
    if (auto cameras = root.find("cameras")) {
        cameras->requireObject("named cameras: name -> camera");
        for (const auto& [name, node] : cameras->getMembers()) {
            scene.namedCameras.emplace_back(name, parseCamera(node));
        }
    }
    if (auto background = root.find("background")) {
        scene.background = background->readVec3(NumberRange::getAtLeast(0.0));
    }
    const JsonNode objects = root.get("objects");
    const std::vector<JsonNode> objectNodes = objects.getElements("an array of objects");
    if (objectNodes.empty()) objects.fail("at least one object");
    for (size_t i = 0; i < objectNodes.size(); ++i)
        parseObject(objectNodes[i], i, context);
    if (auto lights = root.find("lights")) {
        const std::vector<JsonNode> lightNodes = lights->getElements("an array of lights");
        for (size_t i = 0; i < lightNodes.size(); ++i) {
            lightNodes[i].requireObject("a light");
            const auto type = lightNodes[i].find("type");
            if (type && type->getJson().is_string() && type->readString() == "area") {
                parseAreaLight(lightNodes[i], i, context);
            } else {
                scene.lights.push_back(parseLight(lightNodes[i]));
            }
        }
    }
    if (auto environment = root.find("environment")) {
        scene.environment = parseEnvironment(*environment, scene.lights, baseDir);
    }
    if (auto render = root.find("render")) parseRender(*render, scene.settings);
    // A loaded scene is its state at t = 0 (an oscillation's phase may already move it).
    if (scene.isAnimated()) scene.update(0.0);
    return scene;
}

Scene loadScene(const std::string& path) {
    if (isGltfPath(path)) return loadGltfScene(path);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        throwInputError(path, "", "a scene file, cannot open it");
    }
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throwInputError(path, "", "a readable scene file");
    const nlohmann::json doc = parseJsonText(text.str(), path);
    return parseScene(doc, path, std::filesystem::path(path).parent_path().string());
}

} // namespace ispm
