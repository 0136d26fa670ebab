#pragma once
// The build of cone-march's shader its node asks for (the builds: shaders/CMakeLists.txt).
#include "rendergraph/pipeline.h"

namespace ls {

rg::ShaderCode coneMarchShader(bool shadowMap, bool lightColor, bool cube);

}  // namespace ls
