#pragma once
// The plugin's medium and light as the float64 model's (passes/reference), for tests that hold
// the GPU against it.
#include "lightscatter.h"
#include "float64_model/light.h"
#include "float64_model/medium.h"

namespace plugin_test {

ls::ref::Medium refMedium(const lightscatter::Medium& m);
ls::ref::Light refLight(const lightscatter::Light& l);

}  // namespace plugin_test
