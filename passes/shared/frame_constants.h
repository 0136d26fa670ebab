#pragma once
// The per-frame constants every scattering shader reads (shaders/shared/frame.glsl, std140).
#include <glm/glm.hpp>

namespace ls {

struct FrameConstants {
    glm::mat4 viewProj;
    glm::mat4 rayBasis;        // columns 0-2: world vectors x, y, 1 of the ray through NDC (x, y)
    glm::mat4 lightViewProj;
    glm::vec4 cameraPos;       // w: near
    glm::vec4 cameraForward;   // w: far
    glm::vec4 screenSize;      // w, h, 1/w, 1/h
    glm::vec4 lightPos;
    glm::vec4 lightDir;        // w: cos(half angle)
    glm::vec4 lightIntensity;  // w: spot range
    glm::vec4 lightScreen;     // xy: NDC, z: sign of clip w, w: on screen
    glm::vec4 betaR;           // w: g
    glm::vec4 betaM;           // w: max distance
    glm::vec4 betaT;           // w: r0
    glm::vec4 depthInfo;       // reversed, infinite, near, far
    glm::vec4 shadowInfo;      // size, 1/size, reversed, bias
    glm::vec4 epipolar;        // slices, samples, initial step, refinement threshold
    glm::vec4 epipolar2;       // bilateral threshold, fix-up max steps, tree levels, ratio mode
    glm::vec4 lutInfo;         // log range of hEff / r0, width, height, -
    glm::vec4 simplified;      // seed 004's light model: a0 / a1 (at least 1e-12), 1 / a1, -, -
    glm::vec4 cubeFace;        // x: the cube face an epipolar per-face pass marches, y: 1 in view
    glm::vec4 epipolar3;       // x: in-scattering refinement threshold (0: off), yzw: -
    // x: the power of two Lin is stored with in float16 targets, y: 1 / x
    glm::vec4 linStorage{1.0f, 1.0f, 0.0f, 0.0f};
    glm::mat4 cubeFaceViewProj[6];  // point light's cube shadow map: world -> clip per face
};
static_assert(sizeof(FrameConstants) == 3 * 64 + 19 * 16 + 6 * 64, "std140 layout of frame.glsl");

}  // namespace ls
