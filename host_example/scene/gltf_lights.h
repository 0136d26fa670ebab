#pragma once
// KHR_lights_punctual: the lights a glTF file's nodes place, as the host's LightDescs, for a
// SCENE.json with "lightsFromGltf" (docs/host_example.md). Only the file's JSON is read (a .glb's
// JSON chunk): the lights must be known when SCENE.json is read, before any mesh is loaded.
#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace host {

// The luminous efficacy of 555 nm light, 683 lm/W: KHR_lights_punctual's photometric intensities
// (candela for point and spot lights, lux for directional ones) divided by it are the radiometric
// ones of docs/model.md (W/sr, W/m^2), as if every watt were emitted at 555 nm.
inline constexpr double kLumensPerWatt = 683.0;

struct GltfLight {
    LightDesc desc;         // shadowMapSize: SCENE.json's default for the light's type
    size_t lightIndex = 0;  // in the file's extensions.KHR_lights_punctual.lights
    size_t nodeIndex = 0;   // the node that places it
    std::string lightName;  // as the file gives them, "" when it gives none
    std::string nodeName;
    std::string label() const;  // "light 1 'Warm' (node 3 'Lamp')", for messages
};

// The lights the nodes of the file's default scene place, in the order the mesh loader walks the
// nodes (depth first, children in order). Position: the node's world origin; direction: its world
// -Z axis, normalised; intensity: KHR's intensity / kLumensPerWatt * `scale` * color. KHR's
// range becomes a windowed range (without one, unbounded). Throws SceneError "PATH: ..." naming the
// light and node and the rule broken: a file without KHR_lights_punctual lights, a node naming a
// light that does not exist, a spot's outer cone beyond 89 degrees.
std::vector<GltfLight> readGltfLights(const std::string& path, double scale);

}  // namespace host
