#pragma once
// The plugin's medium and light as the float64 model's (passes/reference), for tests that hold
// the GPU against it.
#include <vector>

#include <lightscatter/lightscatter.h>
#include "float64_model/light.h"
#include "float64_model/medium.h"
#include "test_frame.h"

namespace plugin_test {

ls::ref::Medium refMedium(const lightscatter::Medium& m);
ls::ref::Light refLight(const lightscatter::Light& l);

// The float64 model's unshadowed Lin of every pixel of a frame (RGBA, alpha 0): the reference for
// frames whose light nothing shadows.
std::vector<float> float64Unshadowed(const TestFrame& frame);

// The float64 model's unshadowed Lin with the frame's cookie (FrameSpec::cookie): the irradiance
// times the cookie's value where the light's shadowViewProjection puts the point, filtered as the
// GPU's linear clamp-to-edge sampler filters it, 1 outside the image or behind the light.
std::vector<float> float64WithCookie(const TestFrame& frame);

// The same for seed 004's simplified light model (ls::ref::simplifiedClosedForm) with a0, a1.
std::vector<float> float64Simplified(const TestFrame& frame, double a0, double a1);

}  // namespace plugin_test
