#pragma once
// Vulkan-convention projections for tests: the host example's own
// (host_example/engine/camera_math.h), so tests and the engine build cameras the same way.
#include "camera_math.h"

namespace testing_support {

using host::vulkanOrtho;
using host::vulkanPerspective;

}  // namespace testing_support
