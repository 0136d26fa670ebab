#pragma once
// Seed 004's beam tree (Nilsson, chapter 4 and appendix B): a solid BSP tree whose splitting planes
// all pass through the light L, so that every leaf is a beam (an infinite pyramid with apex L).
// Polygons inserted front to back from the light carve the light's frustum into open beams (they
// see the backplate) and solid beams (they end at the polygon that first blocks them: the visible
// set). Stopper polygons (the inner bounding volumes, 5.2.1) then mark where a solid beam is
// certainly dark. Plain C++ on the CPU; no Vulkan.
#include <cstdint>
#include <vector>

#include "polygon.h"

namespace ls::beam {

// Where a point is, as seen from the light.
enum class Region : uint8_t {
    Outside,    // outside the light's frustum
    Lit,        // in front of the visible set: nothing between it and the light
    Uncertain,  // behind an outer bounding volume's surface, not known to be behind an inner one
    Unlit,      // behind an inner bounding volume: certainly shadowed
};

// One polygon of the visible set: the part of an inserted polygon (or of the backplate) the light
// sees, and its plane oriented with the light in front.
struct VisiblePolygon {
    Polygon polygon;
    Plane plane;
    bool backplate = false;
};

class BeamTree {
  public:
    // `walls`: planes through the light bounding its frustum, normals pointing into it (a spot's
    // four bounding walls, seed 004's footnote; none for a point light). `epsilon`: the planes'
    // thickness, in the scene's units (seed 004 suggests 1 mm for metres).
    BeamTree(const glm::dvec3& light, const std::vector<Plane>& walls, double epsilon = 1e-3);

    // Inserts an occluder polygon (convex, planar). Callers insert front to back from the light,
    // and polygons must not intersect: then the parts that reach open beams are exactly what the
    // light sees of it. Returns how many visible pieces it added.
    size_t insert(const Polygon& polygon);

    // Adds the parts of the light's far polygon (the backplate) that open beams reach to the
    // visible set; call after every occluder.
    void addBackplate(const Polygon& far);

    // Section 5.2.1: an inner bounding volume's polygon. Its parts inside solid beams become the
    // beams' stopper planes: behind them the beam is certainly dark. Insert front to back, after
    // every outer polygon.
    void insertStopper(const Polygon& polygon);

    // An occluder's outer box holds the light: its object may stand anywhere around the light, so
    // nothing the light reaches is certainly lit. Every open beam becomes uncertain.
    void markAllUncertain();

    [[nodiscard]] Region classify(const glm::dvec3& p) const;
    // Seed 004's isInside (Program 2): whether p is behind the visible set (solid space).
    [[nodiscard]] bool isInside(const glm::dvec3& p) const;

    // Cuts a polygon by the beams it crosses and sorts its pieces by region (4.4, 5.2.1).
    struct Parts {
        std::vector<Polygon> lit, uncertain, unlit;
    };
    [[nodiscard]] Parts partition(const Polygon& polygon) const;

    [[nodiscard]] const std::vector<VisiblePolygon>& visibleSet() const { return visible_; }
    [[nodiscard]] size_t nodeCount() const { return nodes_.size(); }
    [[nodiscard]] const glm::dvec3& light() const { return light_; }
    [[nodiscard]] double epsilon() const { return epsilon_; }

  private:
    enum class Kind : uint8_t { Split, Open, Solid, Blocker, Outside };
    struct Node {
        Kind kind = Kind::Open;
        Plane plane;  // Split: front is the side the light's beam continues on
        uint32_t front = 0, back = 0;
        Plane solidPlane;    // Solid, Blocker: the visible polygon's plane, the light in front
        Plane stopperPlane;  // Blocker: the inner polygon's plane, the light in front
    };

    uint32_t add(Node node);
    void insertAt(uint32_t node, const Polygon& polygon, const Plane& plane, size_t& added);
    // Seed 004's attachPolygon (Program 4): turns an open leaf into the beam of `polygon`.
    void attach(uint32_t leaf, const Polygon& polygon, Kind inside, const Plane& solidPlane,
                const Plane& stopper);
    void stopAt(uint32_t node, const Polygon& polygon, const Plane& plane);
    void backplateAt(uint32_t node, const Polygon& polygon, const Plane& plane);
    void partitionAt(uint32_t node, const Polygon& polygon, Parts& parts) const;

    glm::dvec3 light_;
    double epsilon_;
    std::vector<Node> nodes_;
    uint32_t root_ = 0;
    std::vector<VisiblePolygon> visible_;
};

}  // namespace ls::beam
