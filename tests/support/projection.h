#pragma once
// Vulkan-convention projections (clip y down, depth in [0, 1]) in the four depth conventions.
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace testing_support {

inline glm::mat4 vulkanPerspective(float fovY, float aspect, float nearP, float farP, bool reversed,
                                   bool infinite) {
    glm::mat4 p(0.0f);
    const float f = 1.0f / std::tan(fovY * 0.5f);
    p[0][0] = f / aspect;
    p[1][1] = -f;
    p[2][3] = -1.0f;
    if (infinite) {
        p[2][2] = reversed ? 0.0f : -1.0f;
        p[3][2] = reversed ? nearP : -nearP;
    } else if (reversed) {
        p[2][2] = nearP / (farP - nearP);
        p[3][2] = farP * nearP / (farP - nearP);
    } else {
        p[2][2] = farP / (nearP - farP);
        p[3][2] = farP * nearP / (nearP - farP);
    }
    return p;
}

inline glm::mat4 vulkanOrtho(float halfWidth, float halfHeight, float nearP, float farP) {
    glm::mat4 p = glm::orthoRH_ZO(-halfWidth, halfWidth, -halfHeight, halfHeight, nearP, farP);
    p[1][1] = -p[1][1];
    return p;
}

}  // namespace testing_support
