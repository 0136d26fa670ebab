// SCENE.json: read with nlohmann-json and checked field by field, so that a typo or an out-of-range
// value stops the program with the field's JSON path instead of rendering something else.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>

#include <lightscatter/lightscatter.h>
#include "activity.h"
#include "scene/gltf_lights.h"
#include "scene/input_file.h"
#include "scene/json_input.h"
#include "scene/medium_json.h"
#include "scene/scene.h"

namespace host {
namespace {

using nlohmann::json;

constexpr uint64_t kSceneFileCap = 16 * kMiB;
constexpr uint64_t kCookieFileCap = 64 * kMiB;
constexpr int kMaxCookieSide = 4096;
// The plugin's ranges (lightscatter.h, lightscatter::limits), so that a scene the plugin would
// refuse is refused here, before any device exists, naming the scene's own field.
namespace limits = lightscatter::limits;
constexpr double kMaxCoordinate = limits::kMaxLength;

std::string joinNames(std::initializer_list<const char*> names) {
    std::string out;
    for (const char* name : names) out += (out.empty() ? "" : ", ") + std::string(name);
    return out;
}

// Reads the fields of one scene file; every failure names the file and the field's JSON path.
class SceneReader {
  public:
    explicit SceneReader(const std::string& path) : path_(path) {}

    // A "medium" object alone (a panel script's step), over `medium`.
    void readMediumOnly(const json& v, MediumDesc& medium) const {
        if (!v.is_object()) fail("medium must be an object");
        // Replaced as a whole where given: a script that sets the volumes sets all of them.
        if (v.contains("fogVolumes")) medium.fogVolumes.clear();
        if (v.contains("heightFog") && v["heightFog"].is_null()) {
            json rest = v;
            rest.erase("heightFog");
            medium.heightFog.reset();
            readMedium(rest, medium);
            return;
        }
        readMedium(v, medium);
    }

    SceneDesc read() {
        SceneDesc scene;
        scene.path = path_;
        const json root = parse();
        if (!root.is_object()) fail("the top level must be a JSON object");
        checkKeys(root, "",
                  {"gltf", "models", "camera", "light", "lights", "lightsFromGltf",
                   "gltfLightScale", "gltfLightShadows", "medium", "sky", "ambient", "exposure"});
        if (member(root, "light") && member(root, "lights"))
            fail(
                "\"light\" and \"lights\" are both given: a scene has one light (\"light\") or a "
                "list of "
                "them (\"lights\"), never both");
        if (const json* v = member(root, "gltf")) scene.models.push_back({modelPath(*v, "gltf")});
        if (const json* v = member(root, "models")) readModels(*v, scene.models);
        if (const json* v = member(root, "camera")) readCamera(*v, scene.camera);
        if (const json* v = member(root, "light")) readLight(*v, scene.light, "light");
        if (const json* v = member(root, "lights")) readLights(*v, scene);
        readGltfLightKeys(root, scene);
        if (const json* v = member(root, "medium")) readMedium(*v, scene.medium);
        if (const json* v = member(root, "sky")) {
            checkKeys(*v, "sky", {"color"});
            if (const json* color = member(*v, "color")) {
                scene.skyColor = nonNegativeVec3(*color, "sky.color");
            }
        }
        if (const json* v = member(root, "ambient")) scene.ambient = nonNegativeVec3(*v, "ambient");
        if (const json* v = member(root, "exposure")) scene.exposure = positive(*v, "exposure");
        checkDepthResolution(scene.camera, scene.medium);
        return scene;
    }

    // The host's depth buffer is D32_SFLOAT: with standard depth it steps by 2^-24 near 1, and
    // the farthest distance it must tell apart (the far plane, or with an infinite one the sky)
    // may be at most 2^24 / lightscatter::limits::kDepthStepsPerDistance times the near plane,
    // as the plugin requires; reversed depth has no such limit.
    void checkDepthResolution(const CameraDesc& camera, const MediumDesc& medium) const {
        if (camera.reversedZ) return;
        const double ratio = 16777216.0 / limits::kDepthStepsPerDistance;
        const double farthest = camera.infiniteFar ? medium.maxDistance : camera.farPlane;
        if (farthest <= ratio * double(camera.nearPlane)) return;
        fail("camera.near = " + shortestText(camera.nearPlane) + ": with standard depth the " +
             (camera.infiniteFar ? "sky (medium.maxDistance, " : "far plane (camera.far, ") +
             shortestText(float(farthest)) + " m) may be at most " + shortestText(ratio) +
             " times the near plane, where a float32 depth step is 1/16 of the distance; make "
             "camera.near " +
             shortestText(float(farthest / ratio)) + " or more, or camera.reversedZ true");
    }

  private:
    [[noreturn]] void fail(const std::string& what) const { throw SceneError(path_ + ": " + what); }

    json parse() const {
        try {
            return readJsonFile(path_, "scene file", kSceneFileCap);
        } catch (const JsonInputError& e) {
            throw SceneError(e.what());
        }
    }

    static const json* member(const json& object, const char* key) {
        auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    static std::string field(const std::string& parent, const char* key) {
        return parent.empty() ? key : parent + "." + key;
    }

    // Unknown keys are refused so that a misspelt field cannot silently keep its default.
    void checkKeys(const json& object, const std::string& where,
                   std::initializer_list<const char*> known) const {
        if (!object.is_object()) fail(where + " must be an object");
        for (const auto& item : object.items()) {
            bool found = false;
            for (const char* name : known) found = found || item.key() == name;
            if (!found) {
                fail((where.empty() ? "" : where + ": ") + "unknown key '" + echoText(item.key()) +
                     "' (known keys: " + joinNames(known) + ")");
            }
        }
    }

    // A number that is finite as a double and as the float it is stored in.
    double number(const json& v, const std::string& name) const {
        if (!v.is_number()) fail(name + " must be a number");
        const double d = v.get<double>();
        if (!std::isfinite(d) || std::fabs(d) > double(std::numeric_limits<float>::max())) {
            fail(name + " = " + shortestText(d) + ": must be a finite number");
        }
        return d;
    }

    // What a value becomes as the float it is stored in, for messages about values that are in
    // range as written but not once rounded (1e-50 becomes 0).
    static std::string rounding(double written, float stored) {
        return double(stored) == written
                   ? ""
                   : " (it is " + shortestText(stored) + " in single precision)";
    }

    float positive(const json& v, const std::string& name) const {
        const double x = number(v, name);
        const float f = float(x);
        if (!(f > 0.0f))
            fail(name + " = " + shortestText(x) + ": must be > 0" +
                 (x > 0.0 ? rounding(x, f) : ""));
        return f;
    }

    // In (lo, hi), or (lo, hi] when `closedHigh`.
    float inRange(const json& v, const std::string& name, double lo, double hi,
                  bool closedHigh) const {
        const double x = number(v, name);
        const float f = float(x);
        auto inside = [&](double d) { return d > lo && (d < hi || (closedHigh && d == hi)); };
        if (!inside(f)) {
            fail(name + " = " + shortestText(x) + ": must be in (" + shortestText(lo) + ", " +
                 shortestText(hi) + (closedHigh ? "]" : ")") + (inside(x) ? rounding(x, f) : ""));
        }
        return f;
    }

    // In [lo, hi], checked as the float the value is stored in.
    float inClosedRange(const json& v, const std::string& name, float lo, float hi) const {
        const double x = number(v, name);
        const float f = float(x);
        auto inside = [&](double d) { return d >= lo && d <= hi; };
        if (!inside(f)) {
            fail(name + " = " + shortestText(x) + ": must be in [" + shortestText(lo) + ", " +
                 shortestText(hi) + "]" + (inside(x) ? rounding(x, f) : ""));
        }
        return f;
    }

    glm::vec3 vec3InRange(const json& v, const std::string& name, float lo, float hi) const {
        const glm::vec3 out = vec3(v, name);
        for (int i = 0; i < 3; ++i) {
            if (!(out[i] >= lo && out[i] <= hi)) {
                fail(name + "[" + std::to_string(i) + "] = " + shortestText(out[i]) +
                     ": must be in [" + shortestText(lo) + ", " + shortestText(hi) + "]");
            }
        }
        return out;
    }

    glm::vec3 vec3(const json& v, const std::string& name) const {
        if (!v.is_array() || v.size() != 3) fail(name + " must be an array of 3 numbers");
        glm::vec3 out;
        for (int i = 0; i < 3; ++i) {
            if (!v[size_t(i)].is_number()) fail(name + " must be an array of 3 numbers");
            out[i] = float(number(v[size_t(i)], name + "[" + std::to_string(i) + "]"));
        }
        return out;
    }

    glm::vec3 nonNegativeVec3(const json& v, const std::string& name) const {
        const glm::vec3 out = vec3(v, name);
        for (int i = 0; i < 3; ++i) {
            if (out[i] < 0.0f) {
                fail(name + "[" + std::to_string(i) + "] = " + shortestText(out[i]) +
                     ": must be >= 0");
            }
        }
        return out;
    }

    glm::vec3 direction(const json& v, const std::string& name) const {
        // The length in double: a float's square overflows from about 1.8e19 on, which would
        // call [1e20, 0, 0] a zero vector.
        const glm::dvec3 out(vec3(v, name));
        const double length = glm::length(out);
        if (!(length > 0.0)) fail(name + " has zero length");
        return glm::vec3(out / length);
    }

    bool boolean(const json& v, const std::string& name) const {
        if (!v.is_boolean()) fail(name + " must be true or false");
        return v.get<bool>();
    }

    std::string string(const json& v, const std::string& name) const {
        if (!v.is_string()) fail(name + " must be a string");
        return v.get<std::string>();
    }

    template <class Enum>
    Enum oneOf(const json& v, const std::string& name,
               std::initializer_list<std::pair<const char*, Enum>> choices) const {
        const std::string text = string(v, name);
        std::string names;
        for (const auto& [word, value] : choices) {
            if (text == word) return value;
            names += (names.empty() ? "" : ", ") + std::string(word);
        }
        fail(name + " '" + echoText(text) + "' is not one of " + names);
    }

    // Relative paths are taken from the scene file's folder, so a scene can be run from anywhere.
    std::string modelPath(const json& v, const std::string& name) const {
        const std::string text = string(v, name);
        if (text.empty()) fail(name + " must not be empty");
        if (text.size() > kMaxPathChars || text.find('\0') != std::string::npos) {
            fail(name + " '" + echoText(text) + "' is not a path: " +
                 (text.size() > kMaxPathChars
                      ? "longer than the " + std::to_string(kMaxPathChars) + " bytes Linux opens"
                      : std::string("it holds a NUL character")));
        }
        std::filesystem::path file(text);
        if (file.is_relative()) file = std::filesystem::path(path_).parent_path() / file;
        std::error_code ec;
        file = std::filesystem::absolute(file, ec).lexically_normal();
        const std::string why = ec ? "cannot be resolved" : whyNotARegularFile(file.string());
        if (!why.empty())
            fail(name + " '" + echoText(text, kMaxPathChars) + "' " + why + " (looked for " +
                 echoText(file.string(), 2 * kMaxPathChars) + ")");
        return file.string();
    }

    void readModels(const json& models, std::vector<ModelInstance>& out) const {
        if (!models.is_array()) fail("models must be an array of objects");
        for (size_t i = 0; i < models.size(); ++i) {
            const std::string where = "models[" + std::to_string(i) + "]";
            const json& model = models[i];
            checkKeys(model, where, {"gltf", "translation", "rotationDegrees", "scale"});
            const json* gltf = member(model, "gltf");
            if (!gltf) fail(where + ".gltf is required");
            ModelInstance instance{modelPath(*gltf, where + ".gltf")};
            glm::vec3 translation(0.0f), degrees(0.0f), scale(1.0f);
            if (const json* v = member(model, "translation")) {
                translation = vec3(*v, where + ".translation");
            }
            if (const json* v = member(model, "rotationDegrees")) {
                degrees = vec3(*v, where + ".rotationDegrees");
            }
            if (const json* v = member(model, "scale")) scale = modelScale(*v, where + ".scale");
            // Euler angles applied X first, then Y, then Z: R = Rz * Ry * Rx.
            glm::mat4 m = glm::translate(glm::mat4(1.0f), translation);
            m = glm::rotate(m, glm::radians(degrees.z), glm::vec3(0, 0, 1));
            m = glm::rotate(m, glm::radians(degrees.y), glm::vec3(0, 1, 0));
            m = glm::rotate(m, glm::radians(degrees.x), glm::vec3(1, 0, 0));
            instance.transform = glm::scale(m, scale);
            out.push_back(instance);
        }
    }

    glm::vec3 modelScale(const json& v, const std::string& name) const {
        if (!v.is_number() && !v.is_array()) {
            fail(name + " must be a number or an array of 3 numbers");
        }
        const glm::vec3 scale = v.is_number() ? glm::vec3(float(number(v, name))) : vec3(v, name);
        for (int i = 0; i < 3; ++i) {
            if (scale[i] == 0.0f) fail(name + " = 0: must not be 0 (it flattens the model)");
        }
        return scale;
    }

    void readCamera(const json& v, CameraDesc& camera) const {
        checkKeys(
            v, "camera",
            {"position", "target", "up", "fovYDegrees", "near", "far", "reversedZ", "infiniteFar"});
        if (const json* x = member(v, "position")) camera.position = vec3(*x, "camera.position");
        if (const json* x = member(v, "target")) camera.target = vec3(*x, "camera.target");
        if (const json* x = member(v, "up")) camera.up = direction(*x, "camera.up");
        if (const json* x = member(v, "fovYDegrees")) {
            camera.fovYDegrees = inClosedRange(*x, "camera.fovYDegrees", limits::kMinFovDegrees,
                                               limits::kMaxFovDegrees);
        }
        if (const json* x = member(v, "near")) {
            camera.nearPlane =
                inClosedRange(*x, "camera.near", limits::kMinNearPlane, limits::kMaxLength);
        }
        if (const json* x = member(v, "far")) camera.farPlane = float(number(*x, "camera.far"));
        if (const json* x = member(v, "reversedZ")) {
            camera.reversedZ = boolean(*x, "camera.reversedZ");
        }
        if (const json* x = member(v, "infiniteFar")) {
            camera.infiniteFar = boolean(*x, "camera.infiniteFar");
        }
        if (!camera.infiniteFar && !(camera.farPlane > camera.nearPlane)) {
            fail("camera.far = " + shortestText(camera.farPlane) + ": must be > camera.near (" +
                 shortestText(camera.nearPlane) + ") unless camera.infiniteFar is true");
        }
        if (!camera.infiniteFar && !(camera.farPlane <= limits::kMaxLength)) {
            fail("camera.far = " + shortestText(camera.farPlane) + ": must be at most " +
                 shortestText(double(limits::kMaxLength)) + " unless camera.infiniteFar is true");
        }
        checkCameraPlacement(camera);
    }

    // In double precision, so that the message names the real problem rather than what float
    // overflow makes of it (a camera at 1e20 would otherwise have an "up parallel to the view").
    void checkCoordinates(const glm::vec3& point, const std::string& name) const {
        for (int i = 0; i < 3; ++i) {
            if (std::fabs(double(point[i])) > kMaxCoordinate) {
                fail(name + "[" + std::to_string(i) + "] = " + shortestText(point[i]) +
                     ": must be within +-" + shortestText(kMaxCoordinate) +
                     " (the renderer works in single precision)");
            }
        }
    }

    void checkCameraPlacement(const CameraDesc& camera) const {
        checkCoordinates(camera.position, "camera.position");
        checkCoordinates(camera.target, "camera.target");
        const glm::dvec3 view = glm::dvec3(camera.target) - glm::dvec3(camera.position);
        if (!(glm::length(view) > 0.0)) {
            fail("camera.target equals camera.position: the view direction has zero length");
        }
        const glm::dvec3 up(camera.up);
        const double sine = glm::length(glm::cross(glm::normalize(view), glm::normalize(up)));
        if (!(sine > 1e-6)) fail("camera.up is parallel to the view direction");
    }

    // "lights": an array of light objects, the first one the scene's `light`.
    void readLights(const json& v, SceneDesc& scene) const {
        if (!v.is_array() || v.empty()) fail("lights must be a non-empty array of light objects");
        if (v.size() > lightscatter::kMaxLights)
            fail("lights has " + std::to_string(v.size()) + " entries: at most " +
                 std::to_string(lightscatter::kMaxLights) + " (the plugin's kMaxLights)");
        scene.lightList = true;
        for (size_t i = 0; i < v.size(); ++i) {
            const std::string name = "lights[" + std::to_string(i) + "]";
            if (!v[i].is_object()) fail(name + " must be an object");
            LightDesc light;
            readLight(v[i], light, name);
            if (i == 0)
                scene.light = light;
            else
                scene.moreLights.push_back(light);
        }
    }

    // "lightsFromGltf": the lights of the "gltf" file's KHR_lights_punctual nodes instead of
    // "light" or "lights"; "gltfLightScale" and "gltfLightShadows" only with it.
    void readGltfLightKeys(const json& root, SceneDesc& scene) const {
        const json* from = member(root, "lightsFromGltf");
        const bool fromGltf = from && boolean(*from, "lightsFromGltf");
        if (!fromGltf) {
            for (const char* key : {"gltfLightScale", "gltfLightShadows"})
                if (member(root, key))
                    fail(std::string(key) +
                         " is read only with \"lightsFromGltf\": true (the scene's lights come "
                         "from SCENE.json)");
            return;
        }
        for (const char* key : {"light", "lights"})
            if (member(root, key))
                fail(std::string("\"lightsFromGltf\" and \"") + key +
                     "\" are both given: a scene's lights come from its glTF file or from "
                     "SCENE.json, never both");
        const json* gltf = member(root, "gltf");
        if (!gltf)
            fail(
                "lightsFromGltf needs \"gltf\", the file whose KHR_lights_punctual lights it "
                "reads");
        double scale = 1.0;
        if (const json* v = member(root, "gltfLightScale")) scale = positive(*v, "gltfLightScale");
        std::vector<GltfLight> lights;
        try {
            lights = readGltfLights(scene.models.front().path, scale);
        } catch (const SceneError& e) {
            fail(std::string("lightsFromGltf: ") + e.what());
        }
        if (const json* v = member(root, "gltfLightShadows"))
            readGltfShadows(*v, echoText(string(*gltf, "gltf"), kMaxPathChars), lights);
        scene.lightList = true;
        scene.light = lights.front().desc;
        for (size_t i = 1; i < lights.size(); ++i) scene.moreLights.push_back(lights[i].desc);
    }

    // Shadow-map sizes by a light's KHR name or its node's name; a name that matches no light
    // is refused (a misspelt one would silently leave the default), and so is a light that two
    // entries match.
    void readGltfShadows(const json& v, const std::string& gltf,
                         std::vector<GltfLight>& lights) const {
        if (!v.is_object())
            fail("gltfLightShadows must be an object of shadow-map sizes by light or node name");
        std::vector<std::string> matchedBy(lights.size());
        for (const auto& item : v.items()) {
            const std::string name = "gltfLightShadows." + echoText(item.key());
            const uint32_t size = shadowMapSize(item.value(), name);
            bool found = false;
            for (size_t i = 0; i < lights.size(); ++i) {
                GltfLight& light = lights[i];
                if (light.lightName != item.key() && light.nodeName != item.key()) continue;
                if (!matchedBy[i].empty())
                    fail(name + ": " + light.label() + " is also gltfLightShadows." +
                         echoText(matchedBy[i]) + ": give one size per light");
                matchedBy[i] = item.key();
                light.desc.shadowMapSize = size;
                found = true;
            }
            if (!found) {
                // A few, so that a file of many lights with long names stays a short line.
                constexpr size_t kListed = 8;
                std::string names;
                for (size_t i = 0; i < std::min(lights.size(), kListed); ++i)
                    names += (names.empty() ? "" : "; ") + lights[i].label();
                if (lights.size() > kListed)
                    names += "; and " + std::to_string(lights.size() - kListed) + " more";
                fail(name + ": no KHR_lights_punctual light or node of " + gltf + " is named '" +
                     echoText(item.key()) + "' (its lights: " + names + ")");
            }
        }
    }

    void readLight(const json& v, LightDesc& light, const std::string& name) const {
        checkKeys(v, name,
                  {"type", "position", "direction", "intensity", "innerConeAngleDegrees",
                   "outerConeAngleDegrees", "halfAngleDegrees", "range", "rangeFalloff", "radius",
                   "shadowMapSize", "cookie"});
        if (const json* x = member(v, "type")) {
            light.type = oneOf<lightscatter::LightType>(
                *x, name + ".type",
                {{"directional", lightscatter::LightType::Directional},
                 {"spot", lightscatter::LightType::Spot},
                 {"point", lightscatter::LightType::Point}});
        }
        // A point light's shadow map is a cube of six faces (six depth passes for the host, six
        // per-face passes for epipolar): it has one only when the scene asks (shadowMapSize > 0).
        if (light.type == lightscatter::LightType::Point) light.shadowMapSize = 0;
        if (const json* x = member(v, "position")) {
            light.position =
                vec3InRange(*x, name + ".position", -limits::kMaxLength, limits::kMaxLength);
        }
        if (const json* x = member(v, "direction")) {
            light.direction = direction(*x, name + ".direction");
        }
        if (const json* x = member(v, "intensity")) {
            light.intensity = vec3InRange(*x, name + ".intensity", 0.0f, limits::kMaxIntensity);
        }
        // A spot's cone: KHR_lights_punctual's inner and outer angles, or halfAngleDegrees alone,
        // the former key, a hard cone (inner = outer).
        auto angle = [&](const json& x, const std::string& key) {
            return inClosedRange(x, name + "." + key, limits::kMinConeAngleDegrees, 89.0f);
        };
        const json* half = member(v, "halfAngleDegrees");
        const json* outer = member(v, "outerConeAngleDegrees");
        const json* inner = member(v, "innerConeAngleDegrees");
        if (half && (outer || inner))
            fail(name +
                 ": halfAngleDegrees is a hard cone, inner = outer: give it or "
                 "innerConeAngleDegrees and outerConeAngleDegrees, not both");
        if (half)
            light.innerConeAngleDegrees = light.outerConeAngleDegrees =
                angle(*half, "halfAngleDegrees");
        if (outer) light.outerConeAngleDegrees = angle(*outer, "outerConeAngleDegrees");
        // Without its inner angle, a cone is hard.
        if (outer && !inner) light.innerConeAngleDegrees = light.outerConeAngleDegrees;
        if (inner) light.innerConeAngleDegrees = angle(*inner, "innerConeAngleDegrees");
        if (light.innerConeAngleDegrees > light.outerConeAngleDegrees)
            fail(name + ".innerConeAngleDegrees = " + echo(*inner) +
                 ": must be at most outerConeAngleDegrees (" +
                 (outer ? echo(*outer) : echo(json(light.outerConeAngleDegrees))) + ")");
        if (const json* x = member(v, "range")) light.range = positive(*x, name + ".range");
        if (const json* x = member(v, "rangeFalloff")) {
            light.rangeFalloff =
                oneOf<lightscatter::RangeFalloff>(*x, name + ".rangeFalloff",
                                                  {{"cut", lightscatter::RangeFalloff::Cut},
                                                   {"window", lightscatter::RangeFalloff::Window}});
        }
        if (const json* x = member(v, "radius")) {
            light.radius =
                inClosedRange(*x, name + ".radius", limits::kMinRadius, limits::kMaxLength);
        }
        if (const json* x = member(v, "shadowMapSize")) {
            light.shadowMapSize = shadowMapSize(*x, name + ".shadowMapSize");
        }
        if (const json* x = member(v, "cookie")) {
            // The plugin projects a light color with the light's one shadow matrix: a point light
            // has none, and the host fits a sun's to the view, which would slide its cookie with
            // the camera.
            if (light.type != lightscatter::LightType::Spot)
                fail(name + ".cookie needs a spot light (its cone's projection casts the image; " +
                     "a point light has no single projection, and the host fits a sun's shadow " +
                     "map to the view, which would slide a cookie with the camera)");
            light.cookie = cookie(*x, name + ".cookie");
        }
    }

    // A light's cookie: an image file, relative to the scene's folder, decoded now so that a
    // missing, unreadable or undecodable file is one error naming the field. At most
    // kMaxCookieSide a side: the marching methods cut each ray at every row and column of its
    // texels.
    std::shared_ptr<const Texture> cookie(const json& v, const std::string& name) const {
        const std::string file = modelPath(v, name);
        Texture texture;
        std::string why;
        try {
            why = decodeImageFile(readInputBytes(file, "cookie image", kCookieFileCap),
                                  kMaxCookieSide, texture);
        } catch (const InputFileError& e) {
            why = e.what();
        }
        if (!why.empty())
            fail(name + " '" + echoText(v.get<std::string>(), kMaxPathChars) +
                 "' is not an image the host reads: " + why);
        texture.name = file;
        return std::make_shared<const Texture>(std::move(texture));
    }

    uint32_t shadowMapSize(const json& v, const std::string& name) const {
        constexpr int64_t kMax = 16384;
        if (!v.is_number_integer()) fail(name + " must be an integer");
        const bool negative = v.is_number_unsigned() ? false : v.get<int64_t>() < 0;
        const uint64_t size = negative ? 0 : v.get<uint64_t>();
        if (negative || size > uint64_t(kMax)) {
            fail(name + " = " + echo(v) + ": must be in [0, " + std::to_string(kMax) + "]");
        }
        return uint32_t(size);
    }

    void readMedium(const json& v, MediumDesc& medium) const {
        checkKeys(v, "medium",
                  {"betaR", "betaM", "g", "sigmaA", "phase", "maxDistance", "density", "heightFog",
                   "fogVolumes"});
        const float c = limits::kMaxCoefficient;
        if (const json* x = member(v, "betaR"))
            medium.betaR = vec3InRange(*x, "medium.betaR", 0.0f, c);
        if (const json* x = member(v, "betaM"))
            medium.betaM = vec3InRange(*x, "medium.betaM", 0.0f, c);
        if (const json* x = member(v, "g")) medium.g = inRange(*x, "medium.g", -1.0, 1.0, false);
        if (const json* x = member(v, "sigmaA"))
            medium.sigmaA = vec3InRange(*x, "medium.sigmaA", 0.0f, c);
        if (const json* x = member(v, "phase")) {
            medium.phase = oneOf<lightscatter::MiePhase>(
                *x, "medium.phase",
                {{"cornette-shanks", lightscatter::MiePhase::CornetteShanks},
                 {"isotropic", lightscatter::MiePhase::Isotropic},
                 {"hazy", lightscatter::MiePhase::Hazy}});
        }
        if (const json* x = member(v, "maxDistance")) {
            medium.maxDistance = inRange(*x, "medium.maxDistance", 0.0, limits::kMaxLength, true);
        }
        if (const json* x = member(v, "density"))
            medium.density = inClosedRange(*x, "medium.density", 0.0f, limits::kMaxDensity);
        if (const json* x = member(v, "heightFog")) {
            checkKeys(*x, "medium.heightFog", {"baseHeight", "falloff"});
            lightscatter::HeightFog fog;
            if (const json* y = member(*x, "baseHeight"))
                fog.baseHeight = inClosedRange(*y, "medium.heightFog.baseHeight",
                                               -limits::kMaxLength, limits::kMaxLength);
            if (const json* y = member(*x, "falloff"))
                fog.falloff =
                    inClosedRange(*y, "medium.heightFog.falloff", 0.0f, limits::kMaxFogFalloff);
            medium.heightFog = fog;
        }
        if (const json* x = member(v, "fogVolumes")) {
            if (!x->is_array()) fail("medium.fogVolumes must be an array of fog volume objects");
            if (x->size() > limits::kMaxFogVolumes)
                fail("medium.fogVolumes holds " + std::to_string(x->size()) + " volumes: at most " +
                     std::to_string(limits::kMaxFogVolumes));
            for (size_t i = 0; i < x->size(); ++i)
                medium.fogVolumes.push_back(
                    readFogVolume((*x)[i], "medium.fogVolumes[" + std::to_string(i) + "]"));
        }
    }

    lightscatter::FogVolume readFogVolume(const json& v, const std::string& name) const {
        checkKeys(v, name, {"center", "halfExtents", "axes", "density", "fade"});
        lightscatter::FogVolume out;
        auto put = [](lightscatter::Vec3& to, const glm::vec3& from) {
            to = {from.x, from.y, from.z};
        };
        const json* center = member(v, "center");
        const json* half = member(v, "halfExtents");
        if (!center || !half) fail(name + " needs \"center\" and \"halfExtents\"");
        put(out.center,
            vec3InRange(*center, name + ".center", -limits::kMaxLength, limits::kMaxLength));
        put(out.halfExtents, vec3InRange(*half, name + ".halfExtents", 0.0f, limits::kMaxLength));
        if (const json* x = member(v, "axes")) {
            if (!x->is_array() || x->size() != 3)
                fail(name +
                     ".axes must be an array of 3 axes (the box's local x, y, z in world "
                     "space)");
            for (size_t j = 0; j < 3; ++j) {
                const std::string axis = name + ".axes[" + std::to_string(j) + "]";
                const glm::vec3 a = vec3((*x)[j], axis);
                if (std::fabs(glm::length(a) - 1.0f) > 1e-3f)
                    fail(axis + " has length " + shortestText(glm::length(a)) +
                         ": the axes must be unit vectors (within 1e-3)");
                for (size_t k = 0; k < j; ++k) {
                    const float d =
                        glm::dot(a, glm::vec3(out.axes[k][0], out.axes[k][1], out.axes[k][2]));
                    if (std::fabs(d) > 1e-3f)
                        fail(axis + " and " + name + ".axes[" + std::to_string(k) +
                             "] have dot product " + shortestText(d) +
                             ": the axes must be orthogonal (within 1e-3)");
                }
                put(out.axes[j], a);
            }
        }
        if (const json* x = member(v, "density"))
            out.density = inClosedRange(*x, name + ".density", 0.0f, limits::kMaxDensity);
        if (const json* x = member(v, "fade"))
            out.fade = inClosedRange(*x, name + ".fade", 0.0f, limits::kMaxLength);
        return out;
    }

    std::string path_;
};

}  // namespace

MediumDesc readMediumJson(const nlohmann::json& v, const std::string& source, MediumDesc start) {
    SceneReader(source).readMediumOnly(v, start);
    return start;
}

SceneDesc loadSceneFile(const std::string& path) {
    Activity reading("reading " + path);
    return SceneReader(path).read();
}

MeshData loadSceneMeshes(const SceneDesc& scene) {
    MeshData mesh;
    for (const ModelInstance& model : scene.models) {
        Activity loading("loading " + model.path);
        appendGltf(mesh, model.path, model.transform);
    }
    return mesh;
}

}  // namespace host
