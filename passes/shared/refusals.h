#pragma once
// What several methods ask of a light, and the refusal the methods that depth-test their planes
// share (empty: no refusal). The refusals a method's caps imply (light types, cube maps, cookies,
// Settings' extras) are the plugin's, which names the methods that honour them.
#include <string>

#include "light_setup.h"

namespace ls {

// The methods that depth-test planes against the engine's depth need it as an attachment.
std::string refuseNoDepthAttachment(const LightSetup& s, const std::string& what);

inline bool pointLike(const LightSetup& s) {
    return s.light.kind != LightType::Directional;
}
inline bool cubeShadowed(const LightSetup& s) {
    return s.shadowed && s.light.kind == LightType::Point;
}
inline bool skipsShadows(const LightSetup& s) {
    return !s.settings.shadowSampling && s.shadowed;
}

// Scattering is isotropic: no Rayleigh part and an isotropic Mie lobe.
bool isotropicMedium(const LightSetup& s);
// The optical depth from the camera to the light along the largest extinction channel.
float opticalDepthToLight(const LightSetup& s);
// A number with two significant digits, for messages.
std::string twoDigits(float x);

}  // namespace ls
