#include "medium_checks.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "enum_checks.h"
#include "field_checks.h"

namespace lightscatter::detail {
namespace {

const std::string kPerMetre = "1/m; lightscatter.h, limits::kMaxCoefficient";
const std::string kDensity = "a factor of the coefficients; lightscatter.h, limits::kMaxDensity";
const std::string kMetres = "metres; lightscatter.h, limits::kMaxLength";

ls::FogVolumeParams setupVolume(const FogVolume& v, const std::string& at) {
    ls::FogVolumeParams p;
    p.center =
        vecInRange(v.center, at + ".center", -limits::kMaxLength, limits::kMaxLength, kMetres);
    p.halfExtents =
        vecInRange(v.halfExtents, at + ".halfExtents", 0.0, limits::kMaxLength, kMetres);
    p.density = inRange(v.density, at + ".density", 0.0, limits::kMaxDensity, kDensity);
    p.fade = inRange(v.fade, at + ".fade", 0.0, limits::kMaxLength, kMetres);
    // A rotation or a reflection: the local coordinates are then distances, as the fade and the
    // half extents are. A scaled or sheared frame would stretch both without a word.
    constexpr double kTolerance = 1e-3;
    for (int j = 0; j < 3; ++j) {
        const std::string axis = at + ".axes[" + std::to_string(j) + "]";
        const glm::dvec3 a(vec(v.axes[j], axis));
        if (std::fabs(glm::length(a) - 1.0) > kTolerance)
            fail(
                axis + " has length " + num(glm::length(a)) +
                ": the axes must be unit vectors (within 1e-3; put the box's size in halfExtents)");
        for (int k = 0; k < j; ++k) {
            const double d = glm::dot(a, glm::dvec3(v.axes[k][0], v.axes[k][1], v.axes[k][2]));
            if (std::fabs(d) > kTolerance)
                fail(axis + " and " + at + ".axes[" + std::to_string(k) + "] have dot product " +
                     num(d) + ": the axes must be orthogonal (within 1e-3)");
        }
        p.axes[j] = glm::vec3(glm::normalize(a));
    }
    return p;
}

}  // namespace

ls::MediumParams setupMedium(const Medium& m) {
    ls::MediumParams s;
    s.betaR = vecInRange(m.betaR, "medium.betaR", 0.0, limits::kMaxCoefficient, kPerMetre);
    s.betaM = vecInRange(m.betaM, "medium.betaM", 0.0, limits::kMaxCoefficient, kPerMetre);
    s.sigmaA = vecInRange(m.sigmaA, "medium.sigmaA", 0.0, limits::kMaxCoefficient, kPerMetre);
    if (!(m.g > -1.0f && m.g < 1.0f)) fail("medium.g = " + num(m.g) + ": must be in (-1, 1)");
    s.g = m.g;
    checkMiePhase(m.phase, "medium.phase");
    s.phase = m.phase;
    if (!(m.maxDistance > 0.0f && m.maxDistance <= limits::kMaxLength))
        fail("medium.maxDistance = " + num(m.maxDistance) + ": must be in (0, " +
             num(limits::kMaxLength) + "] (metres; lightscatter.h, limits::kMaxLength)");
    s.maxDistance = m.maxDistance;
    s.density = inRange(m.density, "medium.density", 0.0, limits::kMaxDensity, kDensity);
    if (m.heightFog) {
        s.heightFog = true;
        s.baseHeight = inRange(m.heightFog->baseHeight, "medium.heightFog.baseHeight",
                               -limits::kMaxLength, limits::kMaxLength, kMetres);
        s.falloff = inRange(m.heightFog->falloff, "medium.heightFog.falloff", 0.0,
                            limits::kMaxFogFalloff, "1/m; lightscatter.h, limits::kMaxFogFalloff");
    }
    if (m.fogVolumes.size() > limits::kMaxFogVolumes)
        fail("medium.fogVolumes holds " + std::to_string(m.fogVolumes.size()) +
             " volumes: at most " + std::to_string(limits::kMaxFogVolumes) +
             " (lightscatter.h, limits::kMaxFogVolumes)");
    for (size_t i = 0; i < m.fogVolumes.size(); ++i)
        s.volumes.push_back(
            setupVolume(m.fogVolumes[i], "medium.fogVolumes[" + std::to_string(i) + "]"));
    // The densest point scatters and extinguishes maxDensity() times the coefficients: that is
    // what the shaders' bounds (limits.h) must hold.
    const float coefficient = std::max({s.betaR.x, s.betaR.y, s.betaR.z, s.betaM.x, s.betaM.y,
                                        s.betaM.z, s.sigmaA.x, s.sigmaA.y, s.sigmaA.z});
    if (double(s.maxDensity()) * coefficient > limits::kMaxCoefficient)
        fail("medium.density plus the fog volumes' densities (" + num(s.maxDensity()) +
             ") times the largest coefficient (" + num(coefficient) + " /m) is " +
             num(double(s.maxDensity()) * coefficient) + " /m: must be at most " +
             num(limits::kMaxCoefficient) + " (" + kPerMetre + ")");
    if (!s.nonUniform()) {
        // Homogeneous: the density is the coefficients' factor everywhere (exact at 1).
        s.betaR *= s.density;
        s.betaM *= s.density;
        s.sigmaA *= s.density;
        s.density = 1.0f;
    }
    return s;
}

}  // namespace lightscatter::detail
