#pragma once
// Planes and convex polygons in double precision, and splitting a polygon by a thick plane (seed
// 004, 4.3: a plane has a thickness epsilon, so that points within it are classified the same way
// however rounding falls).
#include <glm/glm.hpp>

#include <vector>

namespace ls::beam {

// dot(n, p) + d, n unit: positive in front.
struct Plane {
    glm::dvec3 n{0.0, 0.0, 1.0};
    double d = 0.0;
    [[nodiscard]] double distance(const glm::dvec3& p) const { return glm::dot(n, p) + d; }
    // Through three points, normal along (b - a) x (c - a); invalid (n = 0) when they are
    // collinear.
    static Plane through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);
    [[nodiscard]] Plane flipped() const { return {-n, -d}; }
    [[nodiscard]] bool valid() const { return glm::dot(n, n) > 0.5; }
};

// A convex planar polygon, vertices in order.
using Polygon = std::vector<glm::dvec3>;

struct Split {
    Polygon back, front;  // either may be empty
};

// Splits `polygon` by `plane` of thickness `epsilon`: a vertex within epsilon of the plane belongs
// to both sides, so a polygon lying in the plane (coplanar input) goes whole to the front, and an
// edge crossing the plane is cut at the crossing. Pieces with under three vertices or no area are
// dropped.
Split split(const Plane& plane, const Polygon& polygon, double epsilon);

// The polygon's plane (Newell's normal, robust for nearly degenerate input); invalid for no area.
Plane planeOf(const Polygon& polygon);
double area(const Polygon& polygon);
glm::dvec3 centroid(const Polygon& polygon);

}  // namespace ls::beam
