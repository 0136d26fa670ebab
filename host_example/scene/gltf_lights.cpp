// KHR_lights_punctual read from the glTF's JSON with nlohmann-json rather than through tinygltf:
// SCENE.json's lights are needed when the scene file is read (the benchmark checks every run's
// frame before anything is loaded), and tinygltf would read every buffer and image to get them.
// Everything is checked here, as the mesh loader checks what it reads, since the lights are read
// before it runs: node references, cycles, transforms, and each light's fields.
#include "scene/gltf_lights.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <numbers>

#include "scene/glb_bytes.h"
#include "scene/gltf_json.h"
#include "scene/input_file.h"
#include "scene/json_input.h"

namespace host {
namespace {

using nlohmann::json;
namespace limits = lightscatter::limits;

// The plugin's largest cone (lightscatter::Light): its methods clip a ray to the cone's lit nappe,
// which is convex only below 90 degrees.
constexpr double kMaxConeAngleDegrees = 89.0;

std::string quoted(const std::string& name) {
    return name.empty() ? "" : " '" + echoText(name) + "'";
}

class LightReader {
  public:
    LightReader(const std::string& path, double scale) : path_(path), scale_(scale) {}

    std::vector<GltfLight> read() {
        const std::shared_ptr<const json> parsed = document();
        const json& doc = *parsed;
        if (!doc.is_object()) fail("the top level must be a JSON object");
        const json* lights = at(doc, {"extensions", "KHR_lights_punctual", "lights"});
        if (!lights || !lights->is_array() || lights->empty())
            fail(
                "has no KHR_lights_punctual lights (extensions.KHR_lights_punctual.lights, a "
                "non-empty array)");
        lights_ = lights;
        const json* nodes = member(doc, "nodes");
        if (nodes && !nodes->is_array()) fail("nodes must be an array");
        nodes_ = nodes;
        walk(roots(doc));
        if (out_.empty())
            fail(
                "no node of its default scene places a KHR_lights_punctual light (a node's "
                "extensions.KHR_lights_punctual.light)");
        return out_;
    }

  private:
    [[noreturn]] void fail(const std::string& what) const { throw SceneError(path_ + ": " + what); }

    std::shared_ptr<const json> document() const {
        std::vector<unsigned char> bytes;
        try {
            bytes = readInputBytes(path_, "glTF file", glb::kFileCap);
        } catch (const InputFileError& e) {
            throw SceneError(e.what());
        }
        const char* begin = reinterpret_cast<const char*>(bytes.data());
        const char* end = begin + bytes.size();
        if (bytes.size() >= 4 && glb::readU32(bytes, 0) == glb::kMagic) {
            // A .glb: its JSON chunk, the first, after the 12-byte header.
            if (bytes.size() < 20) fail("truncated GLB header");
            if (glb::readU32(bytes, 16) != glb::kJsonChunk) fail("the first GLB chunk is not JSON");
            const uint64_t jsonEnd = 20ull + glb::readU32(bytes, 12);
            if (jsonEnd > bytes.size()) fail("the GLB JSON chunk runs past the end of the file");
            begin += 20;
            end = reinterpret_cast<const char*>(bytes.data()) + jsonEnd;
        }
        try {
            // Kept for the mesh loader's checks, which read the same text (gltf_json.h).
            return gltfJson(path_, begin, end, {.refuseDuplicateKeys = false}, true);
        } catch (const JsonInputError& e) {
            throw SceneError(e.what());
        }
    }

    static const json* member(const json& object, const char* key) {
        if (!object.is_object()) return nullptr;
        auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    static const json* at(const json& object, std::initializer_list<const char*> keys) {
        const json* v = &object;
        for (const char* key : keys)
            if (!(v = member(*v, key))) return nullptr;
        return v;
    }

    size_t index(const json& v, const std::string& name, size_t count, const char* what) const {
        if (!v.is_number_integer()) fail(name + " must be an integer");
        const bool negative = !v.is_number_unsigned() && v.get<int64_t>() < 0;
        if (negative || v.get<uint64_t>() >= count)
            fail(name + " = " + echo(v) + ": the file has " + std::to_string(count) + " " + what);
        return size_t(v.get<uint64_t>());
    }

    size_t nodeCount() const { return nodes_ ? nodes_->size() : 0; }

    // The default scene's root nodes; without scenes, every node that is nobody's child (as the
    // mesh loader takes them).
    std::vector<size_t> roots(const json& doc) const {
        std::vector<size_t> out;
        if (const json* scenes = member(doc, "scenes")) {
            if (!scenes->is_array()) fail("scenes must be an array");
            if (!scenes->empty()) {
                size_t which = 0;
                if (const json* s = member(doc, "scene"))
                    which = index(*s, "scene", scenes->size(), "scenes");
                const json& scene = (*scenes)[which];
                const std::string name = "scenes[" + std::to_string(which) + "].nodes";
                const json* nodes = member(scene, "nodes");
                if (!nodes) return out;
                if (!nodes->is_array()) fail(name + " must be an array");
                for (size_t i = 0; i < nodes->size(); ++i)
                    out.push_back(index((*nodes)[i], name + "[" + std::to_string(i) + "]",
                                        nodeCount(), "nodes"));
                return out;
            }
        }
        std::vector<bool> isChild(nodeCount(), false);
        for (size_t n = 0; n < nodeCount(); ++n)
            for (size_t c : children(n)) isChild[c] = true;
        for (size_t n = 0; n < nodeCount(); ++n)
            if (!isChild[n]) out.push_back(n);
        return out;
    }

    std::vector<size_t> children(size_t node) const {
        std::vector<size_t> out;
        const json* list = member((*nodes_)[node], "children");
        if (!list) return out;
        const std::string name = "nodes[" + std::to_string(node) + "].children";
        if (!list->is_array()) fail(name + " must be an array");
        for (size_t i = 0; i < list->size(); ++i)
            out.push_back(
                index((*list)[i], name + "[" + std::to_string(i) + "]", nodeCount(), "nodes"));
        return out;
    }

    // Depth first with an explicit stack, children in order: the mesh loader's walk, so the
    // lights come in the order a person reading the file meets them. A node reached twice (a
    // cycle, two parents) is refused, as the loader refuses it.
    void walk(const std::vector<size_t>& roots) {
        struct Pending {
            size_t node;
            glm::dmat4 parent;
        };
        std::vector<Pending> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it)
            stack.push_back({*it, glm::dmat4(1.0)});
        std::vector<bool> reached(nodeCount(), false);
        while (!stack.empty()) {
            const Pending pending = stack.back();
            stack.pop_back();
            if (reached[pending.node])
                fail("node " + std::to_string(pending.node) +
                     " is reached twice: the node hierarchy must be a tree");
            reached[pending.node] = true;
            const json& node = (*nodes_)[pending.node];
            if (!node.is_object())
                fail("nodes[" + std::to_string(pending.node) + "] must be an object");
            const glm::dmat4 world = pending.parent * localTransform(node, pending.node);
            if (const json* light = at(node, {"extensions", "KHR_lights_punctual", "light"}))
                place(*light, pending.node, world);
            const std::vector<size_t> list = children(pending.node);
            for (auto it = list.rbegin(); it != list.rend(); ++it) stack.push_back({*it, world});
        }
    }

    std::vector<double> numbers(const json& node, const char* key, size_t want,
                                const std::string& where) const {
        const json* v = member(node, key);
        if (!v) return {};
        const std::string name = where + "." + key;
        if (!v->is_array() || v->size() != want)
            fail(name + " must be an array of " + std::to_string(want) + " numbers");
        std::vector<double> out;
        for (const json& x : *v) {
            if (!x.is_number() || !std::isfinite(x.get<double>()))
                fail(name + " must be an array of " + std::to_string(want) + " finite numbers");
            out.push_back(x.get<double>());
        }
        return out;
    }

    // The mesh loader's nodeTransform (matrix, or T * R * S with the rotation normalised), in
    // double: a light's position and axis are all this reader keeps of it.
    glm::dmat4 localTransform(const json& node, size_t index) const {
        const std::string where = "nodes[" + std::to_string(index) + "]";
        const std::vector<double> matrix = numbers(node, "matrix", 16, where);
        if (!matrix.empty()) return glm::make_mat4(matrix.data());  // column-major, as glTF
        glm::dmat4 m(1.0);
        if (const auto t = numbers(node, "translation", 3, where); !t.empty())
            m = glm::translate(m, glm::make_vec3(t.data()));
        if (const auto r = numbers(node, "rotation", 4, where); !r.empty()) {
            const glm::dquat q(r[3], r[0], r[1], r[2]);  // glTF stores x, y, z, w
            if (glm::length(q) > 0.0) m *= glm::mat4_cast(glm::normalize(q));
        }
        if (const auto s = numbers(node, "scale", 3, where); !s.empty())
            m = glm::scale(m, glm::make_vec3(s.data()));
        return m;
    }

    void place(const json& reference, size_t node, const glm::dmat4& world) {
        const std::string where = "nodes[" + std::to_string(node) + "]";
        GltfLight light;
        light.nodeIndex = node;
        light.lightIndex = index(reference, where + ".extensions.KHR_lights_punctual.light",
                                 lights_->size(), "KHR_lights_punctual lights");
        if (const json* name = member((*nodes_)[node], "name"); name && name->is_string())
            light.nodeName = name->get<std::string>();
        const json& source = (*lights_)[light.lightIndex];
        if (const json* name = member(source, "name"); name && name->is_string())
            light.lightName = name->get<std::string>();
        if (out_.size() == lightscatter::kMaxLights)
            fail("its nodes place more than " + std::to_string(lightscatter::kMaxLights) +
                 " lights (the plugin's kMaxLights)");
        Converter(*this, light).convert(source, world);
        out_.push_back(light);
    }

    // One light's fields, each failure naming the light and node.
    class Converter {
      public:
        Converter(const LightReader& reader, GltfLight& light) : reader_(reader), light_(light) {}

        void convert(const json& source, const glm::dmat4& world) {
            if (!source.is_object()) fail("must be an object");
            LightDesc& d = light_.desc;
            const json* type = member(source, "type");
            if (!type) fail("type is required (directional, point or spot)");
            const std::string kind = type->is_string() ? type->get<std::string>() : "";
            if (kind == "directional")
                d.type = lightscatter::LightType::Directional;
            else if (kind == "point")
                d.type = lightscatter::LightType::Point;
            else if (kind == "spot")
                d.type = lightscatter::LightType::Spot;
            else
                fail("type " + echo(*type) + " is not one of directional, point, spot");
            // SCENE.json's defaults: a point light's shadow map is a cube, drawn only when asked.
            d.shadowMapSize = d.type == lightscatter::LightType::Point ? 0 : 2048;
            placeIt(world);
            intensity(source);
            if (d.type == lightscatter::LightType::Directional) return;  // KHR: no range, no cone
            if (const json* range = member(source, "range")) {
                const double r = number(*range, "range");
                if (!(float(r) > 0.0f)) fail("range = " + echo(*range) + ": must be > 0");
                d.range = float(r);
                d.rangeFalloff = lightscatter::RangeFalloff::Window;  // KHR's window, exactly
            }
            if (d.type == lightscatter::LightType::Spot) cone(member(source, "spot"));
        }

      private:
        [[noreturn]] void fail(const std::string& what) const {
            reader_.fail("KHR_lights_punctual " + light_.label() + ": " + what);
        }

        double number(const json& v, const std::string& name) const {
            if (!v.is_number() || !std::isfinite(v.get<double>()))
                fail(name + " must be a finite number");
            return v.get<double>();
        }

        void placeIt(const glm::dmat4& world) {
            LightDesc& d = light_.desc;
            const glm::dvec3 position(world[3]);
            for (int i = 0; i < 3; ++i)
                if (!(std::fabs(position[i]) <= double(limits::kMaxLength)))
                    fail("its node's world position [" + shortestText(position.x) + ", " +
                         shortestText(position.y) + ", " + shortestText(position.z) +
                         "] must be within +-" + shortestText(limits::kMaxLength) + " m");
            d.position = glm::vec3(position);
            const glm::dvec3 axis = -glm::dvec3(world[2]);
            // Divided by its largest component first: the length of an axis scaled by 1e200
            // overflows a double, though its direction is plain.
            const double largest =
                std::max({std::fabs(axis.x), std::fabs(axis.y), std::fabs(axis.z)});
            if (!std::isfinite(largest))
                fail(
                    "its node's world -Z axis is not finite (the scales of its node and its "
                    "parents multiply past a double's range): it has no direction");
            if (!(largest > 0.0))
                fail(
                    "its node's world -Z axis has zero length (a scale of 0): it has no direction");
            d.direction = glm::vec3(glm::normalize(axis / largest));
        }

        void intensity(const json& source) {
            glm::dvec3 color(1.0);
            if (const json* c = member(source, "color")) {
                if (!c->is_array() || c->size() != 3) fail("color must be an array of 3 numbers");
                for (int i = 0; i < 3; ++i) {
                    color[i] = number((*c)[size_t(i)], "color[" + std::to_string(i) + "]");
                    if (color[i] < 0.0)
                        fail("color[" + std::to_string(i) + "] = " + shortestText(color[i]) +
                             ": must be >= 0");
                }
            }
            double value = 1.0;
            if (const json* v = member(source, "intensity")) {
                value = number(*v, "intensity");
                if (value < 0.0) fail("intensity = " + shortestText(value) + ": must be >= 0");
            }
            const bool directional = light_.desc.type == lightscatter::LightType::Directional;
            const glm::dvec3 radiometric = value / kLumensPerWatt * reader_.scale_ * color;
            for (int i = 0; i < 3; ++i)
                if (!(radiometric[i] <= double(limits::kMaxIntensity)))
                    fail("intensity " + shortestText(value) + (directional ? " lx" : " cd") +
                         " x color[" + std::to_string(i) + "] x gltfLightScale " +
                         shortestText(reader_.scale_) +
                         " / 683 lm/W = " + shortestText(radiometric[i]) +
                         (directional ? " W/m^2" : " W/sr") + ": must be at most " +
                         shortestText(limits::kMaxIntensity) + " (the plugin's limit)");
            light_.desc.intensity = glm::vec3(radiometric);
        }

        // KHR's angles in radians, inner 0 and outer pi/4 by default. Inner 0 (a cone that fades
        // from its axis) is the library's smallest angle; an outer angle beyond 89 degrees is
        // refused rather than narrowed, which would light less than the file says.
        void cone(const json* spot) {
            double inner = 0.0, outer = std::numbers::pi / 4.0;
            if (spot && !spot->is_object()) fail("spot must be an object");
            if (spot) {
                if (const json* v = member(*spot, "innerConeAngle"))
                    inner = number(*v, "spot.innerConeAngle");
                if (const json* v = member(*spot, "outerConeAngle"))
                    outer = number(*v, "spot.outerConeAngle");
            }
            const double toDegrees = 180.0 / std::numbers::pi;
            auto degrees = [&](double radians) {
                return shortestText(radians * toDegrees) + " degrees";
            };
            if (!(outer * toDegrees <= kMaxConeAngleDegrees))
                fail("spot.outerConeAngle = " + shortestText(outer) + " (" + degrees(outer) +
                     "): must be at most 89 degrees (" +
                     shortestText(kMaxConeAngleDegrees / toDegrees) +
                     "), the library's limit: at 90 a spot's cone is no longer convex");
            if (!(float(outer * toDegrees) >= limits::kMinConeAngleDegrees))
                fail("spot.outerConeAngle = " + shortestText(outer) + " (" + degrees(outer) +
                     "): must be at least " + shortestText(limits::kMinConeAngleDegrees) +
                     " degrees, the library's smallest cone");
            if (!(inner >= 0.0 && inner <= outer))
                fail("spot.innerConeAngle = " + shortestText(inner) + ": must be in [0, " +
                     "outerConeAngle = " + shortestText(outer) + "]");
            light_.desc.outerConeAngleDegrees = float(outer * toDegrees);
            light_.desc.innerConeAngleDegrees =
                std::max(float(inner * toDegrees), limits::kMinConeAngleDegrees);
        }

        const LightReader& reader_;
        GltfLight& light_;
    };

    std::string path_;
    double scale_;
    const json* lights_ = nullptr;
    const json* nodes_ = nullptr;
    std::vector<GltfLight> out_;
};

}  // namespace

std::string GltfLight::label() const {
    return "light " + std::to_string(lightIndex) + quoted(lightName) + " (node " +
           std::to_string(nodeIndex) + quoted(nodeName) + ")";
}

std::vector<GltfLight> readGltfLights(const std::string& path, double scale) {
    return LightReader(path, scale).read();
}

}  // namespace host
