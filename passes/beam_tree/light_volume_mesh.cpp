#include "light_volume_mesh.h"

namespace ls::beam {
namespace {

void push(std::vector<glm::vec4>& out, const glm::dvec3& a, const glm::dvec3& b,
          const glm::dvec3& c) {
    out.emplace_back(glm::vec3(a), 1.0f);
    out.emplace_back(glm::vec3(b), 1.0f);
    out.emplace_back(glm::vec3(c), 1.0f);
}

// A triangle wound so that its normal points away from `inside`.
void pushOutward(std::vector<glm::vec4>& out, const glm::dvec3& a, const glm::dvec3& b,
                 const glm::dvec3& c, const glm::dvec3& inside) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    if (glm::dot(n, (a + b + c) / 3.0 - inside) >= 0.0)
        push(out, a, b, c);
    else
        push(out, a, c, b);
}

void appendFan(std::vector<glm::vec4>& out, const Polygon& p) {
    for (size_t i = 1; i + 1 < p.size(); ++i) push(out, p[0], p[i], p[i + 1]);
}

}  // namespace

void appendLitPyramids(const BeamTree& tree, std::vector<glm::vec4>& out) {
    const glm::dvec3 L = tree.light();
    for (const VisiblePolygon& v : tree.visibleSet()) {
        const Polygon& p = v.polygon;
        if (p.size() < 3) continue;
        // A point inside the pyramid: between the apex and the base's centroid.
        const glm::dvec3 inside = 0.5 * (L + centroid(p));
        for (size_t i = 1; i + 1 < p.size(); ++i) pushOutward(out, p[0], p[i], p[i + 1], inside);
        for (size_t i = 0; i < p.size(); ++i)
            pushOutward(out, L, p[i], p[(i + 1) % p.size()], inside);
    }
}

void appendPartitioned(const BeamTree& tree, const Polygon& polygon,
                       std::vector<glm::vec4>& uncertain, std::vector<glm::vec4>* lit) {
    const BeamTree::Parts parts = tree.partition(polygon);
    for (const Polygon& p : parts.uncertain) appendFan(uncertain, p);
    if (lit)
        for (const Polygon& p : parts.lit) appendFan(*lit, p);
}

}  // namespace ls::beam
