#include "motion.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace host::bench {
namespace {

// The start camera's right: the motions run across the view, where they move most pixels.
glm::dvec3 cameraRight(const CameraDesc& c) {
    const glm::dvec3 forward = glm::normalize(glm::dvec3(c.target) - glm::dvec3(c.position));
    const glm::dvec3 right = glm::cross(forward, glm::dvec3(c.up));
    return glm::length(right) > 1e-9 ? glm::normalize(right) : glm::dvec3(1, 0, 0);
}

glm::dvec3 rotate(const glm::dvec3& v, double degrees, const glm::dvec3& axis) {
    return glm::dvec3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), axis) *
                      glm::dvec4(v, 0.0));
}

}  // namespace

const char* motionName(MotionKind what) {
    switch (what) {
        case MotionKind::Light:
            return "light";
        case MotionKind::Camera:
            return "camera";
        case MotionKind::Still:
            return "still";
    }
    return "?";
}

SceneDesc poseAt(const SceneDesc& start, MotionKind what, const Motion& motion, int frame) {
    SceneDesc s = start;
    if (what == MotionKind::Still) return s;
    const double k = frame;
    const glm::dvec3 right = cameraRight(start.camera);
    if (what == MotionKind::Camera) {
        const CameraDesc& c = start.camera;
        const glm::dvec3 position =
            glm::dvec3(c.position) + right * (motion.cameraMetresPerFrame * k);
        // A positive angle about up turns forward towards the left; the camera turns right.
        const glm::dvec3 look = rotate(glm::dvec3(c.target) - glm::dvec3(c.position),
                                       -motion.cameraDegreesPerFrame * k, glm::dvec3(c.up));
        s.camera.position = glm::vec3(position);
        s.camera.target = glm::vec3(position + look);
        return s;
    }
    LightDesc& l = s.light;
    if (l.type == lightscatter::LightType::Directional) {
        // About the axis that turns the direction towards the camera's right (up, when the sun
        // shines along that right vector itself).
        const glm::dvec3 d = glm::normalize(glm::dvec3(l.direction));
        glm::dvec3 axis = glm::cross(d, right);
        axis = glm::length(axis) > 1e-9 ? glm::normalize(axis) : glm::dvec3(start.camera.up);
        l.direction = glm::vec3(glm::normalize(rotate(d, motion.lightDegreesPerFrame * k, axis)));
    } else {
        l.position = glm::vec3(glm::dvec3(l.position) + right * (motion.lightMetresPerFrame * k));
    }
    return s;
}

}  // namespace host::bench
