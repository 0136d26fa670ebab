#pragma once
// The build of the planes' shader the planes node asks for (the builds: shaders/CMakeLists.txt).
#include "rendergraph/pipeline.h"

namespace ls {

rg::ShaderCode planesShader(bool shadowMap, bool cookie, bool noise, bool cube);

}  // namespace ls
