#pragma once
// The build of seed 002's planes shader the beam tree's sampling planes ask for (the builds:
// shaders/CMakeLists.txt).
#include "rendergraph/pipeline.h"

namespace ls {

rg::ShaderCode beamTreePlanesShader(bool shadowMap, bool cookie, bool cube, bool slab);

}  // namespace ls
