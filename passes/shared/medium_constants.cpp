#include "medium_constants.h"

#include <algorithm>
#include <cmath>

#include "lightscatter/limits.h"

namespace ls {

static_assert(lightscatter::limits::kMaxFogVolumes == LS_MAX_FOG_VOLUMES,
              "the frame constants hold kMaxFogVolumes volumes");

bool fogVolumeMatters(const FogVolumeParams& volume, const CameraParams& camera,
                      const LightParams& light) {
    if (!(volume.density > 0.0f)) return false;
    const glm::mat4 m = glm::transpose(camera.projection * camera.view);  // rows as columns
    const glm::vec4 planes[6] = {m[3] + m[0], m[3] - m[0], m[3] + m[1],
                                 m[3] - m[1], m[2],        m[3] - m[2]};
    const int count = camera.infiniteFar ? 5 : 6;
    const float radius = glm::length(volume.halfExtents);
    const bool pointLike = light.kind != LightType::Directional;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 n(planes[i]);
        const float len = glm::length(n);
        if (!(len > 1e-30f)) continue;
        // A light outside this plane widens the hull beyond it: the plane bounds nothing.
        if (pointLike && glm::dot(n, light.position) + planes[i].w < 0.0f) continue;
        if ((glm::dot(n, volume.center) + planes[i].w) / len < -radius) return false;
    }
    return true;
}

void writeMediumConstants(FrameConstants& f, const CameraParams& camera, const LightParams& light,
                          const MediumParams& medium) {
    f.medium = glm::vec4(medium.density, medium.baseHeight,
                         medium.heightFog ? medium.falloff : 0.0f, 0.0f);
    int kept = 0;
    float scale = 1e30f;
    if (medium.heightFog && medium.falloff > 0.0f) scale = std::min(scale, 1.0f / medium.falloff);
    const glm::vec3 bt = medium.betaT();
    const float densest = std::max({bt.x, bt.y, bt.z}) * medium.maxDensity();
    if (densest > 0.0f) scale = std::min(scale, 0.2f / densest);
    for (const FogVolumeParams& v : medium.volumes) {
        if (!fogVolumeMatters(v, camera, light)) continue;
        // A fade is resolved by pieces of its width; a hard box, whose density jumps at its
        // faces, by pieces of a quarter of its smallest half extent (integrate.glsl weighs a
        // piece by its mean density).
        const float smallest = std::min({v.halfExtents.x, v.halfExtents.y, v.halfExtents.z});
        scale = std::min(scale, v.fade > 0.0f ? v.fade : 0.25f * smallest);
        if (kept == LS_MAX_FOG_VOLUMES) continue;
        glm::mat4 box(0.0f);
        for (int j = 0; j < 3; ++j) {
            const glm::vec3 axis = v.axes[j];
            // Column j of the stored matrix is row j of the world -> local transform.
            box[j] = glm::vec4(axis, -glm::dot(axis, v.center));
        }
        box[3] = glm::vec4(v.halfExtents, v.fade);
        f.fogVolumes[kept] = box;
        f.fogDensity[kept / 4][kept % 4] = v.density;
        ++kept;
    }
    f.medium.w = static_cast<float>(kept);
    f.mediumScale = glm::vec4(std::max(scale, 1e-6f), 0.0f, 0.0f, 0.0f);
}

}  // namespace ls
