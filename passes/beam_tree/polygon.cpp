#include "polygon.h"

#include <cmath>

namespace ls::beam {

Plane Plane::through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    if (!(len > 0.0)) return {glm::dvec3(0.0), 0.0};
    const glm::dvec3 u = n / len;
    return {u, -glm::dot(u, a)};
}

Plane planeOf(const Polygon& p) {
    glm::dvec3 n(0.0);
    for (size_t i = 0; i < p.size(); ++i) {
        const glm::dvec3& a = p[i];
        const glm::dvec3& b = p[(i + 1) % p.size()];
        n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                        (a.x - b.x) * (a.y + b.y));
    }
    const double len = glm::length(n);
    if (!(len > 0.0)) return {glm::dvec3(0.0), 0.0};
    const glm::dvec3 u = n / len;
    return {u, -glm::dot(u, centroid(p))};
}

double area(const Polygon& p) {
    glm::dvec3 n(0.0);
    for (size_t i = 1; i + 1 < p.size(); ++i) n += glm::cross(p[i] - p[0], p[i + 1] - p[0]);
    return 0.5 * glm::length(n);
}

glm::dvec3 centroid(const Polygon& p) {
    glm::dvec3 c(0.0);
    for (const auto& v : p) c += v;
    return p.empty() ? c : c / static_cast<double>(p.size());
}

Split split(const Plane& plane, const Polygon& polygon, double epsilon) {
    Split out;
    if (polygon.size() < 3) return out;
    std::vector<double> dist(polygon.size());
    bool anyFront = false, anyBack = false;
    for (size_t i = 0; i < polygon.size(); ++i) {
        dist[i] = plane.distance(polygon[i]);
        anyFront |= dist[i] > epsilon;
        anyBack |= dist[i] < -epsilon;
    }
    if (!anyBack) {  // in front, or within the plane's thickness
        out.front = polygon;
        return out;
    }
    if (!anyFront) {
        out.back = polygon;
        return out;
    }
    for (size_t i = 0; i < polygon.size(); ++i) {
        const size_t j = (i + 1) % polygon.size();
        const glm::dvec3 &a = polygon[i], &b = polygon[j];
        const double da = dist[i], db = dist[j];
        if (da >= -epsilon) out.front.push_back(a);
        if (da <= epsilon) out.back.push_back(a);
        // An edge from one side to the other, both beyond the thickness, is cut where it crosses.
        if ((da > epsilon && db < -epsilon) || (da < -epsilon && db > epsilon)) {
            const glm::dvec3 x = a + (b - a) * (da / (da - db));
            out.front.push_back(x);
            out.back.push_back(x);
        }
    }
    const double tiny = epsilon * epsilon * 1e-6;
    if (out.front.size() < 3 || area(out.front) <= tiny) out.front.clear();
    if (out.back.size() < 3 || area(out.back) <= tiny) out.back.clear();
    return out;
}

}  // namespace ls::beam
