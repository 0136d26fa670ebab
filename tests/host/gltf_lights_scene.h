#pragma once
// scenes/atrium_gltf_lights.json's lights written in SCENE.json instead: what its glTF's
// KHR_lights_punctual nodes must come to (tools/make_scenes/make_gltf_lights_scene.py places them).
// Intensities are the glTF's candela and lux over 683 lm/W times the colours; positions are the
// "Lamps" node's translation plus each lamp's; directions are the vectors the lamps' rotations
// turn -Z onto; the cold spot's inner cone, KHR's default 0, is the library's smallest, 0.1 degree.
#include <string>

namespace gltf_lights_test {

// The same atrium under the same camera and medium, its lights in SCENE.json; `atriumGltf` is the
// path of scenes/atrium.gltf (the same mesh, without lights).
inline std::string atriumLightsAsSceneJson(const std::string& atriumGltf) {
    return R"({
  "gltf": ")" +
           atriumGltf +
           R"(",
  "camera": {"position": [-6.0, 1.7, -4.0], "target": [0.0, 2.6, 6.0], "up": [0.0, 1.0, 0.0],
             "fovYDegrees": 65.0, "near": 0.1, "far": 500.0},
  "lights": [
    {"type": "directional", "direction": [-0.31, -0.4226, -0.8517], "intensity": [20, 18, 15],
     "shadowMapSize": 2048},
    {"type": "spot", "position": [-3, 6, 2], "direction": [0.3, -1, 0.2],
     "intensity": [400, 250, 120], "innerConeAngleDegrees": 15, "outerConeAngleDegrees": 20,
     "range": 30, "rangeFalloff": "window", "shadowMapSize": 1024},
    {"type": "spot", "position": [3, 6, 5], "direction": [-0.2, -1, -0.1],
     "intensity": [120, 250, 400], "innerConeAngleDegrees": 0.1, "outerConeAngleDegrees": 20,
     "shadowMapSize": 1024}
  ],
  "medium": {"betaR": [5.8e-05, 0.000135, 0.000331], "betaM": [0.025, 0.025, 0.025], "g": 0.7,
             "sigmaA": [0.0, 0.0, 0.0], "phase": "cornette-shanks", "maxDistance": 300.0},
  "sky": {"color": [0.35, 0.5, 0.8]},
  "ambient": [0.5, 0.55, 0.7],
  "exposure": 0.8
})";
}

}  // namespace gltf_lights_test
