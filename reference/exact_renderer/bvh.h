#pragma once
// Exact ray queries against a scene's triangles in float64, for the CPU reference renderer: the
// reference's visibility must not inherit a shadow map's resolution or bias, so every shadow ray is
// traced against the triangles themselves.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace host::reference {

struct Triangle {
    glm::dvec3 a{0.0}, b{0.0}, c{0.0};
};

// A ray set up once for many triangle and box tests. The triangle test is the watertight one of
// Woop, Benthin and Wald (JCGT 2013): vertices are moved into a frame where the ray is the +z axis
// and the hit is decided by three 2D edge functions. Two triangles that share an edge compute that
// edge's function from the same two transformed vertices, so their values are exact negatives of
// each other and a ray can never slip between them (no epsilon, no gap at a shared edge or vertex).
struct PreparedRay {
    PreparedRay(const glm::dvec3& origin, const glm::dvec3& direction);

    glm::dvec3 origin;
    glm::dvec3 direction;
    glm::dvec3 inverse;  // 1 / direction, +-inf where a component is 0
    int kx = 0, ky = 1, kz = 2;
    double sx = 0.0, sy = 0.0, sz = 1.0;
};

// Distance t (in units of |direction|) of the ray's hit on the triangle within [tMin, tMax], edges
// and vertices included; nothing for a miss or a degenerate (zero-area, edge-on) triangle.
[[nodiscard]] std::optional<double> intersectTriangle(const PreparedRay& ray, const Triangle& tri,
                                                      double tMin, double tMax);

// One question for Bvh::anyHit.
struct OcclusionQuery {
    PreparedRay ray;
    double tMin = 0.0, tMax = 0.0;
};

struct RayHit {
    double t = 0.0;
    uint32_t triangle = 0;  // index into Bvh::triangles()
};

class EmbreeOcclusion;

// A bounding volume hierarchy built with binned SAH (median split where every centroid coincides).
// Where the build has Embree, anyHit traverses Embree's BVH over the same triangles instead
// (embree_occlusion.h) and tests each candidate with the same double test: the same answers,
// several times sooner.
class Bvh {
  public:
    // Who traverses for anyHit: Embree where the build has it, or always this BVH's own nodes
    // (the same answers, slower: for measuring what Embree saves).
    enum class Traversal { Embree, Own };

    Bvh() = default;
    explicit Bvh(std::vector<Triangle> triangles, Traversal traversal = Traversal::Embree);
    // Every primitive's triangles, in world space.
    static Bvh fromMesh(const MeshData& mesh, Traversal traversal = Traversal::Embree);

    // The nearest hit with t in [tMin, tMax].
    [[nodiscard]] std::optional<RayHit> closestHit(const PreparedRay& ray, double tMin,
                                                   double tMax) const;
    // Whether anything is hit with t in [tMin, tMax]; stops at the first hit found.
    [[nodiscard]] bool anyHit(const PreparedRay& ray, double tMin, double tMax) const;
    // anyHit of each query: hits[i] is 1 where queries[i] hits, else 0 (hits.size() ==
    // queries.size()). Through Embree, rays that go together (points of one view ray towards one
    // light) are traced as SIMD packets, which is where batching pays.
    void anyHit(std::span<const OcclusionQuery> queries, std::span<uint8_t> hits) const;
    // The same, always through this BVH's own nodes (what anyHit's Embree path must equal).
    [[nodiscard]] bool anyHitOwn(const PreparedRay& ray, double tMin, double tMax) const;
    // Whether anyHit goes through Embree.
    [[nodiscard]] bool usesEmbree() const { return embree_ != nullptr; }

    // In the BVH's own order (leaves hold consecutive runs).
    [[nodiscard]] const std::vector<Triangle>& triangles() const { return triangles_; }
    [[nodiscard]] std::size_t nodeCount() const { return nodes_.size(); }
    // The largest absolute coordinate of any vertex (0 for an empty BVH): the scale at which the
    // rounding of a hit distance must be judged.
    [[nodiscard]] double coordinateScale() const { return coordinateScale_; }

  private:
    struct Node {
        glm::dvec3 lo{0.0}, hi{0.0};
        uint32_t first = 0;  // leaf: first triangle; interior: index of the second child
        uint32_t count = 0;  // triangles in a leaf; 0 marks an interior node (first child follows)
    };

    uint32_t build(uint32_t begin, uint32_t end, std::vector<glm::dvec3>& centroids);

    std::vector<Triangle> triangles_;
    std::vector<Node> nodes_;
    double coordinateScale_ = 0.0;
    std::shared_ptr<const EmbreeOcclusion> embree_;  // shared by copies; owns its triangles
};

}  // namespace host::reference
