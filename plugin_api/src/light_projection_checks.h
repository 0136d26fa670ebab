#pragma once
// A spot's or directional light's shadowViewProjection checked against the light it projects: a
// matrix of another light, of another space or of an earlier frame renders without complaint, as
// a white wedge and black air, so each rule is refused beyond a tolerance that float32 matrices of
// any real scene keep well within.
#include <glm/glm.hpp>
#include <string>

#include <lightscatter/lightscatter.h>

namespace lightscatter::detail {

// The tolerances lightscatter.h states (Light::position, direction, outerConeAngleDegrees).
// A spot's apex: this fraction of the light's reach, plus kApexFromOrigin of the distance of
// `position` from the origin (float32 rounds the matrix's translation by that much).
inline constexpr double kApexOfReach = 1e-3;
inline constexpr double kApexFromOrigin = 1e-5;
inline constexpr double kAxisDegrees = 0.1;   // the light's direction against the matrix's axis
inline constexpr double kConeDegrees = 0.01;  // how far a spot's cone may pass its frustum's side

// What of the light the matrix is checked against.
struct ProjectedLight {
    LightType type = LightType::Spot;
    glm::dvec3 position{0.0}, direction{0.0, -1.0, 0.0};  // direction: a unit vector
    double outerConeAngleDegrees = 0.0;
    double range = 0.0;
    bool shadowed = false;  // a shadow map, not only a light color
    bool shadowReversedZ = false;
};

// Refuses (InvalidInput naming `at`.position, .direction or .outerConeAngleDegrees, and
// `at`.shadowViewProjection) a matrix that breaks a rule: a spot's apex off its position, its axis
// off its direction, and with a shadow map a cone wider than the frustum; a directional light's
// axis off its direction (with a shadow map, signed by the way its depth grows). `m` is not
// singular (checked before).
void checkLightProjection(const glm::mat4& m, const ProjectedLight& light, const std::string& at);

}  // namespace lightscatter::detail
