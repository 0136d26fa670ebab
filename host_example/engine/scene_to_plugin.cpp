#include "scene_to_plugin.h"

#include <cctype>
#include <cstring>
#include <utility>

namespace host {
namespace {

lightscatter::Vec3 v3(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

// Whether a field name may begin at text[i]: not inside another name, a path or an index.
bool startsWord(const std::string& text, size_t i) {
    if (i == 0) return true;
    const char c = text[i - 1];
    return !(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '[');
}

void replaceAll(std::string& text, const std::string& from, const std::string& to) {
    for (size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size())
        text.replace(at, from.size(), to);
}

}  // namespace

lightscatter::Mat4 toPluginMatrix(const glm::mat4& m) {
    lightscatter::Mat4 out;
    std::memcpy(out.data(), &m[0][0], sizeof(float) * 16);
    return out;
}

lightscatter::Camera toPluginCamera(const CameraDesc& c, const glm::mat4& view,
                                    const glm::mat4& projection) {
    lightscatter::Camera out;
    out.view = toPluginMatrix(view);
    out.projection = toPluginMatrix(projection);
    out.nearPlane = c.nearPlane;
    out.farPlane = c.farPlane;
    out.reversedZ = c.reversedZ;
    out.infiniteFar = c.infiniteFar;
    return out;
}

lightscatter::Light toPluginLight(const LightDesc& l, const glm::mat4& shadowViewProj,
                                  bool shadowed) {
    lightscatter::Light out;
    out.type = l.type;
    out.position = v3(l.position);
    out.direction = v3(l.direction);
    out.intensity = v3(l.intensity);
    out.innerConeAngleDegrees = l.innerConeAngleDegrees;
    out.outerConeAngleDegrees = l.outerConeAngleDegrees;
    out.range = l.range;
    out.rangeFalloff = l.rangeFalloff;
    out.radius = l.radius;
    if (shadowed) {
        out.shadowViewProjection = toPluginMatrix(shadowViewProj);
        out.shadowMapSize = l.shadowMapSize;
    }
    return out;
}

std::string pluginRefusalInSceneTerms(const std::string& message, const std::string& scenePath) {
    std::string m = message;
    while (m.rfind("lightscatter: ", 0) == 0) m.erase(0, 14);
    if (const size_t colon = m.find("]: ");
        m.rfind("lights[", 0) == 0 && colon != std::string::npos) {
        // A light of the scene's "lights": the plugin's "lights[i]: lights[i].light.x" is what the
        // single light's "light.x" would be, named "lights[i].x" as the scene names it.
        const std::string light = m.substr(0, colon + 1);
        std::string single = m.substr(colon + 3);
        replaceAll(single, light + ".light.", "light.");
        std::string out = pluginRefusalInSceneTerms(single, scenePath);
        std::string named;
        for (size_t i = 0; i < out.size();) {
            if (startsWord(out, i) && out.compare(i, 6, "light.") == 0) {
                named += light + ".";
                i += 6;
            } else {
                named += out[i++];
            }
        }
        replaceAll(named, " the light ", " " + light + " ");
        // A refusal naming no field of the light (its method's) still says which light it is.
        const std::string lead = scenePath + ": the plugin refused the frame: ";
        if (named.find(light) == std::string::npos && named.rfind(lead, 0) == 0)
            named.insert(lead.size(), light + ": ");
        return named;
    }
    // Longest first: a phrase, then the fields whose SCENE.json names differ. The matrices are
    // made by the host from several scene fields, so those are named instead.
    static const std::pair<const char*, const char*> kTerms[] = {
        {"camera.projection * camera.view",
         "the camera made from camera.position, camera.target, camera.up, camera.fovYDegrees, "
         "camera.near and camera.far"},
        {"camera.view", "the view made from camera.position, camera.target and camera.up"},
        {"camera.projection",
         "the projection made from camera.fovYDegrees, camera.near and camera.far"},
        {"light.cubeFaceViewProjections",
         "the cube shadow map's faces made from light.position and the scene's bounds"},
        {"light.shadowViewProjection",
         "the shadow map's projection made from the light and the scene's bounds"},
        {"light.shadowMapSize / shadowMap", "light.shadowMapSize"},
        {"camera.nearPlane", "camera.near"},
        {"camera.farPlane", "camera.far"},
        {"nearPlane", "camera.near"},
        {"unless infiniteFar", "unless camera.infiniteFar is true"},
    };
    const bool aboutTheScene =
        m.rfind("camera.", 0) == 0 || m.rfind("light.", 0) == 0 || m.rfind("medium.", 0) == 0;
    if (!aboutTheScene) return scenePath + ": the plugin refused the frame: " + m;
    std::string out;
    for (size_t i = 0; i < m.size();) {
        bool replaced = false;
        for (const auto& [plugin, scene] : kTerms) {
            const size_t n = std::strlen(plugin);
            const bool wordEnd =
                i + n >= m.size() ||
                !(std::isalnum(static_cast<unsigned char>(m[i + n])) || m[i + n] == '_');
            if (startsWord(m, i) && wordEnd && m.compare(i, n, plugin) == 0) {
                out += scene;
                i += n;
                replaced = true;
                break;
            }
        }
        if (!replaced) out += m[i++];
    }
    return scenePath + ": " + out + " (refused by the plugin)";
}

lightscatter::Medium toPluginMedium(const MediumDesc& m) {
    lightscatter::Medium out;
    out.betaR = v3(m.betaR);
    out.betaM = v3(m.betaM);
    out.g = m.g;
    out.sigmaA = v3(m.sigmaA);
    out.phase = m.phase;
    out.maxDistance = m.maxDistance;
    out.density = m.density;
    out.heightFog = m.heightFog;
    out.fogVolumes = m.fogVolumes;
    return out;
}

}  // namespace host
