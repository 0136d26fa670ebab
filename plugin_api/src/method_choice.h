#pragma once
// Which method a frame runs: the one asked for, checked against what the frame holds (a method
// that cannot honour the frame refuses it in one line), or for Method::Auto the cheapest that
// meets the frame's needs, with the reason.
#include <functional>
#include <string>

#include <lightscatter/lightscatter.h>
#include "frame_setup.h"
#include "shared/method_unit.h"

namespace lightscatter::detail {

// Seed 001's closed form ignores extinction; its image error grows like 1.33 tau with
// tau = max(betaT) |camera - light| (tests/float64 model: AnalyticExtinction). Auto uses it below
// this optical depth, where that error stays under 1%.
inline constexpr float kAnalyticMaxOpticalDepth = 0.007f;

// Screens with fewer pixels than slices x samples / 24 are cheaper to march per pixel than to
// sample epipolarly: the crossover measured with the balanced profile on the scene that pays last
// (the atrium at about 272x153, 25 samples per pixel; docs/methods.md gives the measurement).
inline constexpr uint32_t kEpipolarSamplesPerPixel = 24;

struct MethodChoice {
    Method method = Method::Epipolar;  // never Auto
    // The method's unit (the registry's; `method` is never Auto nor out of the enum).
    const ls::MethodUnit& unit() const;
    std::string reason;  // why, for Auto; empty otherwise
    std::string notice;  // an assumption of the method that the frame breaks
};

// Why the method cannot honour the light, in one line naming the field and the methods that can
// (what its caps rule out, then its own refusal); empty when it can.
std::string refusal(const ls::MethodUnit& unit, const ls::LightSetup& s);
// What its caps alone rule out.
std::string capsRefusal(const ls::MethodUnit& unit, const ls::LightSetup& s);

// The names of the methods whose caps pass `which`, in the registry's order, and with `orAuto`
// auto after them: "a, b or c".
std::string methodsWhere(const std::function<bool(const ls::MethodCaps&)>& which,
                         const char* last = "or", bool orAuto = false);

// Throws InvalidInput naming the method and the rule when it cannot honour the frame.
MethodChoice chooseMethod(Method requested, const ls::LightSetup& setup, bool lightReachesView);
// Each light's method: LightInput::method where it is not Auto, else the frame's `frameMethod`
// (Auto choosing for each light on its own). A refusal names lights[i] in a list. Converts the
// occluders into the setup of each light whose method reads them.
std::vector<MethodChoice> chooseLightMethods(Method frameMethod, ValidatedFrame& frame,
                                             const FrameDescription& description);

}  // namespace lightscatter::detail
