#pragma once
// What a method that carries state from one frame to the next reads besides its history images
// (rg::RenderGraph::historyImages, which the graph keeps and swaps): the frame before's constants,
// to reproject what it left (froxels' temporal mode). The plugin gives them to each record().
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "frame_constants.h"

namespace ls {

struct PreviousFrame {
    // The frame before's first light's constants (its camera and the medium); meaningful where
    // the history is valid (rg::PassContext::history).
    FrameConstants constants{};
    // A light of this frame differs from the frame before's (moved, turned, or its color, range
    // or cone changed), or the frame has another set of lights: a history's light is not this
    // frame's, which reprojection cannot follow.
    bool lightsChanged = false;
    // The largest angle (radians) by which a light moved or turned since the frame before, as
    // lightJump() measures it; infinite where the frame has another set of lights.
    float lightJump = 0.0f;
    // The frame before itself differed from the one before it (its camera or a light), or came
    // first: what it left in a history was made by a frame in motion.
    bool beforeMoved = true;
};

// Whether `a` and `b` hold the same light: where it is, where it points, its intensity, range and
// cone. (Its shadow map's frustum may follow the camera; what it casts is the light's.)
inline bool sameLight(const FrameConstants& a, const FrameConstants& b) {
    return a.lightPos == b.lightPos && a.lightDir == b.lightDir &&
           a.lightIntensity == b.lightIntensity && a.lightFalloff == b.lightFalloff;
}

// How far the light of `b` moved from where `a` had it, as an angle (radians): the turn of its
// direction (a sun, a spot's axis), the widening of a spot's cone, and its displacement over its
// distance from the camera (a point or spot light as the camera sees it move). What its shafts do
// on screen follows it, whatever its intensity.
inline float lightJump(const FrameConstants& a, const FrameConstants& b) {
    auto angle = [](glm::vec3 u, glm::vec3 v) {
        const float c = glm::dot(glm::normalize(u), glm::normalize(v));
        return std::acos(std::clamp(c, -1.0f, 1.0f));
    };
    float jump = 0.0f;
    if (glm::length(glm::vec3(a.lightDir)) > 0.0f && glm::length(glm::vec3(b.lightDir)) > 0.0f)
        jump = angle(glm::vec3(a.lightDir), glm::vec3(b.lightDir));
    jump = std::max(jump, std::abs(std::acos(std::clamp(a.lightDir.w, -1.0f, 1.0f)) -
                                   std::acos(std::clamp(b.lightDir.w, -1.0f, 1.0f))));
    const float distance = glm::length(glm::vec3(b.lightPos) - glm::vec3(b.cameraPos));
    const float moved = glm::length(glm::vec3(b.lightPos) - glm::vec3(a.lightPos));
    if (moved > 0.0f) jump = std::max(jump, std::atan2(moved, distance));
    return jump;
}

}  // namespace ls
