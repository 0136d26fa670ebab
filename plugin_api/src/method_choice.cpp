#include "method_choice.h"

#include <algorithm>
#include <cstdio>

#include "method_units.h"
#include "occluder_input.h"
#include "registry/method_registry.h"
#include "shared/refusals.h"

namespace lightscatter::detail {
namespace {

[[noreturn]] void refuse(const std::string& what) {
    throw InvalidInput("lightscatter: " + what);
}

MethodChoice pick(Method method, std::string reason) {
    MethodChoice c;
    c.method = method;
    c.reason = std::move(reason);
    return c;
}

// Auto's default: epipolar sampling (an unshadowed light is its closed form per pixel).
MethodChoice sampled(std::string reason) {
    return pick(Method::Epipolar, std::move(reason));
}

// Seed 001's closed form, where it is exact enough.
MethodChoice closedForm(std::string reason) {
    return pick(Method::Analytic, std::move(reason));
}

const char* kindName(ls::LightType t) {
    return t == ls::LightType::Directional ? "directional"
           : t == ls::LightType::Spot      ? "spot"
                                           : "point";
}

bool takesKind(const ls::MethodCaps& c, ls::LightType t) {
    return t == ls::LightType::Directional ? c.directional
           : t == ls::LightType::Spot      ? c.spot
                                           : c.point;
}

// What makes the medium non-uniform, as the engine set it.
std::string nonUniformParts(const ls::LightSetup& s) {
    std::string parts = s.medium.heightFog ? "medium.heightFog" : "";
    if (!s.medium.volumes.empty())
        parts += std::string(parts.empty() ? "" : " and ") + "medium.fogVolumes (" +
                 std::to_string(s.medium.volumes.size()) + ")";
    return parts;
}

}  // namespace

// What the method's caps rule out for this light, in one line naming the field, and the methods
// that take it instead; empty when they rule out nothing.
std::string capsRefusal(const ls::MethodUnit& unit, const ls::LightSetup& s) {
    const ls::MethodCaps c = unit.caps();
    const std::string method = "method " + std::string(unit.name());
    const std::string& set = s.settingsPath;
    const ls::LightType kind = s.light.kind;
    if (!takesKind(c, kind)) {
        std::string kinds;
        for (ls::LightType t :
             {ls::LightType::Directional, ls::LightType::Spot, ls::LightType::Point})
            if (takesKind(c, t)) kinds += std::string(kinds.empty() ? "" : " and ") + kindName(t);
        return method + " takes " + kinds + " lights only; this frame's light is " +
               kindName(kind) + " (use auto, " +
               methodsWhere([&](const ls::MethodCaps& o) { return takesKind(o, kind); }) + ")";
    }
    if (ls::cubeShadowed(s) && !c.cubeShadow)
        return method + " cannot sample a point light's cube shadow map (" + s.lightPath +
               ".shadowMapSize > 0 with a point light): use " +
               methodsWhere([](const ls::MethodCaps& o) { return o.cubeShadow; }, "or", true);
    if (s.shadowed && !c.shadowMap)
        return method + " cannot cast shadows; this frame has a shadow map (use auto, " +
               methodsWhere([](const ls::MethodCaps& o) { return o.shadowMap; }) + ")";
    if (s.lightColor && s.shadowed && !c.lightColor)
        return method + " cannot vary the light's color along the ray: " + s.lightPath +
               "Color needs " +
               methodsWhere([](const ls::MethodCaps& o) { return o.lightColor; }, "or", true);
    if (s.lightColor && !s.shadowed && !c.unshadowedLightColor)
        return method + " cannot vary the light's color along the ray: " + s.lightPath +
               "Color without a shadow map needs " +
               methodsWhere([](const ls::MethodCaps& o) { return o.unshadowedLightColor; }, "or",
                            true);
    if (ls::skipsShadows(s) && !c.skipsShadowSampling) {
        const std::string honour =
            methodsWhere([](const ls::MethodCaps& o) { return o.skipsShadowSampling; }, "and");
        return set + ".shadowSampling = false (seed 003's low-end mode) is honoured by " + honour +
               " only; " + method + " samples the shadow map (use " +
               methodsWhere([](const ls::MethodCaps& o) { return o.skipsShadowSampling; }) +
               " or auto)";
    }
    if (ls::noisy(s) && !c.noise)
        return set + ".noiseAmplitude > 0 (seed 002's scrolling noise) is honoured by " +
               methodsWhere([](const ls::MethodCaps& o) { return o.noise; }, "and") + " only; " +
               method + " integrates the model's homogeneous medium (use " +
               methodsWhere([](const ls::MethodCaps& o) { return o.noise; }) +
               " or auto, or amplitude 0)";
    if (s.medium.nonUniform() && !c.media)
        return method + " integrates a homogeneous medium only; this frame's has " +
               nonUniformParts(s) + " (use auto, " +
               methodsWhere([](const ls::MethodCaps& o) { return o.media; }) + ")";
    if (s.medium.nonUniform() && (ls::simplifiedModel(s) || ls::noisy(s)))
        return set +
               (ls::noisy(s) ? ".noiseAmplitude > 0 (seed 002's scrolling noise)"
                             : ".lightModel = simplified (seed 004's light model)") +
               " replaces docs/model.md's medium, and this frame's has " + nonUniformParts(s) +
               ": use one or the other";
    if (ls::simplifiedModel(s) && !c.simplifiedModel)
        return set + ".lightModel = simplified (seed 004's light model) is honoured by " +
               methodsWhere([](const ls::MethodCaps& o) { return o.simplifiedModel; }, "and") +
               " only; " + method + " integrates docs/model.md's full model (use " +
               methodsWhere([](const ls::MethodCaps& o) { return o.simplifiedModel; }) +
               " or auto, or lightModel full)";
    return {};
}

namespace {

// Epipolar sampling for a shadowed light, unless the screen is too small for it to pay. A light
// that covers little of the screen is sampled too: its lines keep to its screen rectangle, and
// their count to its share (passes/epipolar/screen_share.h), which costs less than marching the
// rectangle's pixels at every share measured (docs/methods.md).
MethodChoice epipolarOrBruteForce(const ls::LightSetup& s, const std::string& light) {
    const uint64_t pixels = uint64_t{s.screen.width} * s.screen.height;
    const uint64_t samples =
        uint64_t{s.settings.epipolar.slices} * s.settings.epipolar.samplesPerSlice;
    if (pixels * kEpipolarSamplesPerPixel >= samples) return sampled(light + ": epipolar sampling");
    return pick(Method::BruteForce,
                light + " on a screen of " + std::to_string(pixels) + " pixels, fewer than " +
                    std::to_string(samples / kEpipolarSamplesPerPixel) + " (epipolar samples / " +
                    std::to_string(kEpipolarSamplesPerPixel) + "): per-pixel marching is cheaper");
}

// A setting beyond docs/model.md the light's frame asks for, and the methods that honour it.
struct Extra {
    std::string what;  // the field, as the engine set it
    bool (*honours)(const ls::MethodCaps&);
};

std::vector<Extra> extrasAsked(const ls::LightSetup& s) {
    const std::string& set = s.settingsPath;  // "custom", or the light's own settings
    std::vector<Extra> asked;
    if (ls::simplifiedModel(s))
        asked.push_back({set + ".lightModel = simplified (seed 004's light model)",
                         [](const ls::MethodCaps& c) { return c.simplifiedModel; }});
    if (ls::noisy(s))
        asked.push_back({set + ".noiseAmplitude > 0 (seed 002's scrolling noise)",
                         [](const ls::MethodCaps& c) { return c.noise; }});
    if (ls::skipsShadows(s))
        asked.push_back({set + ".shadowSampling = false (seed 003's low-end mode)",
                         [](const ls::MethodCaps& c) { return c.skipsShadowSampling; }});
    return asked;
}

// The first method that honours every extra the frame asks for and takes the light.
MethodChoice honouring(const ls::LightSetup& s, const std::vector<Extra>& asked) {
    std::string what;
    for (const Extra& e : asked) what += (what.empty() ? "" : " and ") + e.what;
    const auto all = [&](const ls::MethodCaps& c) {
        for (const Extra& e : asked)
            if (!e.honours(c)) return false;
        return true;
    };
    if (methodsWhere(all).empty()) {
        std::string each;
        for (const Extra& e : asked)
            each += (each.empty() ? "" : "; ") + e.what + ": " + methodsWhere(e.honours);
        refuse(what + ": no method honours both (" + each + ")");
    }
    std::string last;
    const auto& units = ls::methodRegistry();
    for (size_t i = 0; i < units.size(); ++i) {
        if (!all(units[i]->caps())) continue;
        std::string r = refusal(*units[i], s);
        if (r.empty())
            return pick(static_cast<Method>(i), what + ": " + units[i]->name() +
                                                    ", the first method that honours it and "
                                                    "takes this light");
        last = std::move(r);
    }
    refuse(what + ": no method that honours it takes this light (" + last + ")");
}

// Auto: the cheapest method that meets the frame's needs, and why.
MethodChoice autoChoice(const ls::LightSetup& s, bool lightReachesView) {
    const bool pointLike = ls::pointLike(s);
    if (!lightReachesView)
        return sampled("the light reaches no view ray (or nothing scatters): extinction only");
    if (const std::vector<Extra> asked = extrasAsked(s); !asked.empty()) return honouring(s, asked);
    if (ls::cubeShadowed(s))
        return epipolarOrBruteForce(
            s, "shadowed point light (a cube shadow map, marched face by face)");
    // A light color without a shadow map varies the light along each ray: no closed form carries
    // it, so the light is marched per pixel through the color (epipolar's unshadowed form).
    if (!s.shadowed && s.lightColor)
        return sampled(
            "unshadowed light with a light color: marched per pixel through the color (the closed "
            "forms cannot vary it along a ray)");
    if (!s.shadowed && pointLike && s.medium.nonUniform())
        return sampled(
            "unshadowed point light in a non-uniform medium: integrated per pixel in pieces over "
            "the point-light table (no closed form holds: docs/methods.md, \"Non-uniform media\")");
    if (!s.shadowed && pointLike) {
        const float tau = ls::opticalDepthToLight(s);
        if (ls::isotropicMedium(s) && tau < kAnalyticMaxOpticalDepth)
            return closedForm(
                "unshadowed point light in an isotropic, thin medium (optical depth " +
                ls::twoDigits(tau) + " to the light): seed 001's closed form, within 1%");
        return sampled(std::string("unshadowed point light: the point-light table per pixel (") +
                       (ls::isotropicMedium(s)
                            ? "the optical depth to the light, " + ls::twoDigits(tau) +
                                  ", puts seed 001's closed form over 1%"
                            : "seed 001's closed form assumes isotropic scattering") +
                       ")");
    }
    if (!s.shadowed) return sampled("unshadowed directional light: closed form per pixel");
    return epipolarOrBruteForce(s, "shadowed light");
}

}  // namespace

std::string refusal(const ls::MethodUnit& unit, const ls::LightSetup& s) {
    const std::string r = capsRefusal(unit, s);
    return r.empty() ? unit.refusal(s) : r;
}

const ls::MethodUnit& MethodChoice::unit() const {
    return *methodUnit(method);
}

MethodChoice chooseMethod(Method requested, const ls::LightSetup& s, bool lightReachesView) {
    MethodChoice c;
    if (requested == Method::Auto) {
        c = autoChoice(s, lightReachesView);
        // Auto picks a method that honours the frame; its notice still says what it assumes.
        if (c.unit().caps().readsOccluders) c.notice = c.unit().notice(s);
        return c;
    }
    const ls::MethodUnit* unit = methodUnit(requested);
    if (!unit) refuse("method is not a Method value");
    if (const std::string r = refusal(*unit, s); !r.empty()) refuse(r);
    c.method = requested;
    c.notice = unit->notice(s);
    return c;
}

std::vector<MethodChoice> chooseLightMethods(Method frameMethod, ValidatedFrame& v,
                                             const FrameDescription& frame) {
    const size_t n = v.lights.size();
    std::vector<MethodChoice> choices(n);
    bool occluders = false;
    // A light's own method overrides the frame's; its Auto follows the frame's.
    auto requested = [&](size_t i) {
        const Method own = v.given[i].input.method;
        return own != Method::Auto ? own : frameMethod;
    };
    for (size_t i = 0; i < n; ++i) {
        try {
            choices[i] = chooseMethod(requested(i), v.lights[i], v.touchesView[i]);
        } catch (const InvalidInput& e) {
            throw aboutLight(e, v.given[i].paths);
        }
    }
    // A one-per-frame method (froxels) takes every light into one chain: once one light resolves
    // to it, the lights that follow the frame's method go with it, and one that names another
    // method is refused.
    for (size_t i = 0; i < n; ++i) {
        if (!choices[i].unit().caps().onePerFrame) continue;
        const Method wide = choices[i].method;
        for (size_t j = 0; j < n; ++j) {
            if (choices[j].method == wide) continue;
            const std::string at = "lights[" + std::to_string(v.given[j].given) + "]";
            if (v.given[j].input.method != Method::Auto)
                refuse(at + ".method = " + methodName(v.given[j].input.method) + ": " +
                       methodName(wide) + " (lights[" + std::to_string(v.given[i].given) +
                       "]'s) takes every light of the frame into one grid and mixes with no "
                       "other method; leave " +
                       at + ".method auto, or choose no " + methodName(wide));
            try {
                choices[j] = chooseMethod(wide, v.lights[j], v.touchesView[j]);
                choices[j].reason = methodName(wide) +
                                    std::string(" takes every light of the frame (lights[") +
                                    std::to_string(v.given[i].given) + "] resolved to it)";
            } catch (const InvalidInput& e) {
                throw aboutLight(e, v.given[j].paths);
            }
        }
        break;
    }
    for (size_t i = 0; i < n; ++i)
        occluders = occluders || (v.touchesView[i] && choices[i].unit().caps().readsOccluders);
    // Checked, and converted, only when a light's method reads them: the others ignore them, as
    // the header says, and a scene of 100,000 parts must not stop them.
    if (occluders) {
        const std::vector<ls::beam::Occluder> converted = beamOccluders(frame.occluders);
        for (size_t i = 0; i < n; ++i)
            if (v.touchesView[i] && choices[i].unit().caps().readsOccluders)
                v.lights[i].beamOccluders = converted;
    }
    return choices;
}

std::string methodsWhere(const std::function<bool(const ls::MethodCaps&)>& which, const char* last,
                         bool orAuto) {
    std::vector<std::string> names;
    for (const ls::MethodUnit* m : ls::methodRegistry())
        if (which(m->caps())) names.emplace_back(m->name());
    if (orAuto) names.emplace_back("auto");
    std::string s;
    for (size_t i = 0; i < names.size(); ++i)
        s += (i == 0                  ? ""
              : i + 1 == names.size() ? std::string(" ") + last + " "
                                      : ", ") +
             names[i];
    return s;
}

}  // namespace lightscatter::detail
