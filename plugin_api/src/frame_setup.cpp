#include "frame_setup.h"

#include <algorithm>

#include <cmath>
#include <string>

#include "camera_checks.h"
#include "color_target.h"
#include "enum_checks.h"
#include "field_checks.h"
#include "image_checks.h"
#include "light_checks.h"
#include "medium_checks.h"
#include "rendergraph/format_info.h"

namespace lightscatter::detail {

ls::LightSetup setupFramePart(const FrameDescription& f, bool withImages) {
    ls::LightSetup s;
    checkProfile(f.profile, "profile");
    checkMethod(f.method, "method");
    s.settings = profileSettings(f.profile, f.custom);
    checkSettings(s.settings);
    // Checked, and converted, only for the methods that read them (beamOccluders): the others
    // ignore them, as the header says, and a scene of 100,000 parts must not stop them.
    s.occluders = f.occluders.size();
    if (!std::isfinite(f.timeSeconds))
        fail("timeSeconds = " + num(f.timeSeconds) + ": must be finite");
    s.timeSeconds = f.timeSeconds;
    if (!(f.preExposure >= 0.0f && f.preExposure <= limits::kMaxPreExposure))
        fail("preExposure = " + num(f.preExposure) + ": must be in [0, " +
             num(limits::kMaxPreExposure) + "] (lightscatter.h, limits::kMaxPreExposure)");
    s.preExposure = f.preExposure;

    // Camera.
    s.camera = setupCamera(f.camera);
    // What the depth buffer can resolve, before anything that a near plane too small for it
    // would break (the depth format is the engine's image's: unknown to the budget).
    if (withImages && rg::hasDepth(f.depth.format) && f.medium.maxDistance > 0.0f)
        checkDepthResolution(s.camera, f.medium.maxDistance, f.depth.format);
    checkViewProjection(s.camera);

    s.medium = setupMedium(f.medium);

    // Images.
    s.engineNoise = f.noise.has_value();
    s.depthAttachment =
        !withImages || (f.depth.usage & VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT) != 0;
    s.inscatterOut = f.inscatterOut.has_value();
    if (withImages) {
        checkImage(f.depth, "depth", VK_IMAGE_USAGE_SAMPLED_BIT);
        checkDepthFormat(f.depth.format, "depth");
        s.screen = f.depth.extent;
        oneLayer(&f.depth, "depth");
        checkColorTargets(f, s.screen);
        oneLayer(f.noise ? &*f.noise : nullptr, "noise");
        if (f.noise) checkImage(*f.noise, "noise", VK_IMAGE_USAGE_SAMPLED_BIT);
        if (f.volumeOut) {
            // Its extent is the froxel grid's, checked once the frame's method is known
            // (checkVolumeOut).
            oneLayer(&*f.volumeOut, "volumeOut");
            checkImage(*f.volumeOut, "volumeOut", VK_IMAGE_USAGE_STORAGE_BIT, false, true);
            if (f.volumeOut->format != VK_FORMAT_R16G16B16A16_SFLOAT)
                fail("volumeOut.format " + rg::formatName(f.volumeOut->format) +
                     ": must be R16G16B16A16_SFLOAT");
        }
    }
    return s;
}

namespace {

bool defaultLight(const Light& l) {
    const Light d;
    return l.type == d.type && l.position == d.position && l.direction == d.direction &&
           l.intensity == d.intensity && l.innerConeAngleDegrees == d.innerConeAngleDegrees &&
           l.outerConeAngleDegrees == d.outerConeAngleDegrees && l.range == d.range &&
           l.rangeFalloff == d.rangeFalloff && l.radius == d.radius &&
           l.shadowViewProjection == d.shadowViewProjection &&
           l.cubeFaceViewProjections == d.cubeFaceViewProjections &&
           l.shadowMapSize == d.shadowMapSize && l.shadowReversedZ == d.shadowReversedZ;
}

}  // namespace

std::vector<EdgeLight> edgeLights(const FrameDescription& frame) {
    std::vector<EdgeLight> lights;
    if (frame.lights.empty()) {
        lights.push_back(
            {LightInput{frame.light, frame.shadowMap, frame.lightColor}, LightPaths{}, 0, 0});
        return lights;
    }
    std::string both;
    if (!defaultLight(frame.light)) both = "light";
    if (frame.shadowMap) both += both.empty() ? "shadowMap" : ", shadowMap";
    if (frame.lightColor) both += both.empty() ? "lightColor" : ", lightColor";
    if (!both.empty())
        fail("lights holds " + std::to_string(frame.lights.size()) + " lights and " + both +
             " is given too: give the single light (light, shadowMap, lightColor) or the list "
             "(lights), "
             "never both");
    if (frame.lights.size() > kMaxLights)
        fail("lights holds " + std::to_string(frame.lights.size()) + " lights: at most " +
             std::to_string(kMaxLights) +
             " (kMaxLights; each light is a chain of passes and a table of its own)");
    lights.reserve(frame.lights.size());
    for (size_t i = 0; i < frame.lights.size(); ++i) {
        const std::string at = "lights[" + std::to_string(i) + "]";
        const LightInput& in = frame.lights[i];
        checkMethod(in.method, at + ".method");
        lights.push_back({in,
                          {at + ".light", at + ".shadowMap", at + ".lightColor",
                           in.settings ? at + ".settings" : "custom", at},
                          i,
                          in.id ? *in.id : i});
    }
    // In the order of their ids: the same lights in another order are the same frame.
    std::stable_sort(lights.begin(), lights.end(),
                     [](const EdgeLight& a, const EdgeLight& b) { return a.id < b.id; });
    for (size_t k = 1; k < lights.size(); ++k)
        if (lights[k].id == lights[k - 1].id) {
            const auto [first, second] = std::minmax(lights[k - 1].given, lights[k].given);
            fail("lights[" + std::to_string(second) + "].id = " + std::to_string(lights[k].id) +
                 " is lights[" + std::to_string(first) +
                 "]'s too (a light without an id has its position): each light's id must differ");
        }
    return lights;
}

InvalidInput aboutLight(const InvalidInput& e, const LightPaths& paths) {
    if (paths.about.empty()) return e;
    const std::string lead = "lightscatter: ";
    std::string m = e.what();
    if (m.rfind(lead, 0) == 0) m = m.substr(lead.size());
    return InvalidInput(lead + paths.about + ": " + m);
}

ValidatedFrame validateFrame(const FrameDescription& frame, bool withImages) {
    ValidatedFrame v;
    v.given = edgeLights(frame);
    // The frame's own part once; whatever fails there is not about a light.
    const ls::LightSetup framePart = setupFramePart(frame, withImages);
    v.lights.reserve(v.given.size());
    for (const EdgeLight& l : v.given) {
        ls::LightSetup s = framePart;
        s.lightPath = l.paths.light;
        s.settingsPath = l.paths.settings;
        try {
            setupLight(s, l.input, l.paths, withImages);
        } catch (const InvalidInput& e) {
            throw aboutLight(e, l.paths);
        }
        v.touchesView.push_back(ls::lightTouchesView(s.camera, s.light, s.medium));
        s.screenRect = ls::lightScreenRect(s.camera, s.light, s.medium, s.screen);
        v.lights.push_back(std::move(s));
    }
    return v;
}

}  // namespace lightscatter::detail
