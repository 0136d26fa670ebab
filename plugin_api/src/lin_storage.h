#pragma once
// The power of two a frame's Lin is stored with between a method's passes and the composite
// (FrameConstants::linStorage, shaders/shared/frame.glsl's storedLin and loadedLin).
#include "frame_setup.h"
#include "shared/method_unit.h"

namespace lightscatter::detail {

// Every method leaves Lin in a screen texture (float16 for most: at most 65504) that the composite
// reads. This bounds the frame's Lin from above, per channel, with the phase functions' peaks
// pR <= 3 / (8 pi) and pM <= pMax(g) (under the shaders' floor of 1e-6 on Cornette-Shanks'
// denominator), betaS = betaR + betaM and betaT the extinction:
//   directional    E (betaR pR + betaM pM) / betaT  (the transmittance integrates to 1 / betaT)
//   point, spot    I (betaR pR + betaM pM) (pi / r0 + ambient / betaT)
//                  (1 / (r^2 + r0^2) integrates to at most pi / r0 along any line; the
//                  ambient term a method adds (MethodUnit::ambient, the planes') is constant)
//   simplified     I betaS pi / (4 pi a1 w), w = sqrt(max(a0 / a1, 1e-12)) (its arctangent)
// times exp(-betaT d) for a point or spot light d away from the camera (its light has crossed at
// least that much medium), and returns 1 while the bound is at most 16384 (a frame of ordinary
// brightness stores Lin exactly as before), else the power of two that brings it to 16384: a
// factor of four under float16's largest value for a sampled method's overshoot at a light, which
// storedLin clamps. A light-color texture is taken to hold values of at most 1.
float linStorageScale(const ls::LightSetup& setup, const ls::MethodUnit& method);

}  // namespace lightscatter::detail
