#include "point_table.h"

#include <array>
#include <cstring>

namespace ls {

rg::PersistentImageDesc pointTableDesc() {
    rg::PersistentImageDesc d;
    d.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    d.extent = {kTableWidth, kTableHeight};
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    return d;
}

uint64_t pointTableStamp(const FrameConstants& c, MiePhase phase, bool nonUniform) {
    // A non-uniform medium's table has no extinction (point_table.comp): its coefficients of
    // extinction change nothing in it, and it differs from a homogeneous one of the same medium.
    const glm::vec3 betaT = nonUniform ? glm::vec3(0.0f) : glm::vec3(c.betaT);
    const std::array<float, 16> key{c.betaR.x,
                                    c.betaR.y,
                                    c.betaR.z,
                                    c.betaR.w /* g */,
                                    c.betaM.x,
                                    c.betaM.y,
                                    c.betaM.z,
                                    betaT.x,
                                    betaT.y,
                                    betaT.z,
                                    c.betaT.w /* r0 */,
                                    c.lutInfo.x,
                                    c.lutInfo.y,
                                    c.lutInfo.z,
                                    static_cast<float>(phase),
                                    nonUniform ? 1.0f : 0.0f};
    // FNV-1a over the values' bits: a change in any of them changes the stamp (a collision would
    // need two media 2^-64 apart in likelihood).
    uint64_t h = 1469598103934665603ull;
    for (float v : key) {
        uint32_t bits = 0;
        std::memcpy(&bits, &v, sizeof bits);
        for (int b = 0; b < 4; ++b) {
            h ^= (bits >> (8 * b)) & 0xffu;
            h *= 1099511628211ull;
        }
    }
    return h;
}

}  // namespace ls
