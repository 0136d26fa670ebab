#pragma once
// The build of the planes' shader the slices node asks for (the builds: shaders/CMakeLists.txt).
#include "rendergraph/pipeline.h"

namespace ls {

rg::ShaderCode slicePlanesShader(bool shadowMap, bool cookie, bool noise);

}  // namespace ls
