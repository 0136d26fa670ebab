#pragma once
// The refusals several methods share, in one line each naming the setting or field and the rule
// (empty: no refusal). The method's name is the one refusing.
#include <string>

#include "light_setup.h"

namespace ls {

// A point light's cube shadow map: every method that casts shadows samples it but analytic.
std::string refuseCubeShadow(const LightSetup& s, const std::string& method);
// Seed 002's noise is a density the model does not have; only seed 002's planes sample it.
std::string refuseNoise(const LightSetup& s, const std::string& method);
// Seed 004's simplified light model is another integrand; only the closed forms take it.
std::string refuseSimplified(const LightSetup& s, const std::string& method);
// Seed 003's low-end mode (no shadow-map look-ups): only cone-march has it.
std::string refuseSkippedShadows(const LightSetup& s, const std::string& method);
// The methods that depth-test planes against the engine's depth need it as an attachment.
std::string refuseNoDepthAttachment(const LightSetup& s, const std::string& what);
// A light color (cookie) on a light without a shadow map varies the light along each ray, which a
// closed form over the whole ray cannot carry. `how` says what the method integrates in closed
// form.
std::string refuseUnshadowedLightColor(const LightSetup& s, const std::string& method,
                                       const std::string& how);
// The first of the refusals given that is not empty.
std::string firstRefusal(std::initializer_list<std::string> refusals);

inline bool pointLike(const LightSetup& s) {
    return s.light.kind != LightType::Directional;
}
inline bool cubeShadowed(const LightSetup& s) {
    return s.shadowed && s.light.kind == LightType::Point;
}
inline bool skipsShadows(const LightSetup& s) {
    return !s.shadowSampling && s.shadowed;
}

// Scattering is isotropic: no Rayleigh part and an isotropic Mie lobe.
bool isotropicMedium(const LightSetup& s);
// The optical depth from the camera to the light along the largest extinction channel.
float opticalDepthToLight(const LightSetup& s);
// A number with two significant digits, for messages.
std::string twoDigits(float x);

}  // namespace ls
