#include "beam_tree.h"

#include <cmath>

namespace ls::beam {
namespace {

// The plane of a polygon oriented so that the light is in front of it.
Plane facingLight(const Plane& p, const glm::dvec3& light) {
    return p.distance(light) >= 0.0 ? p : p.flipped();
}

}  // namespace

BeamTree::BeamTree(const glm::dvec3& light, const std::vector<Plane>& walls, double epsilon)
    : light_(light), epsilon_(epsilon) {
    // The frustum's walls, each with the outside behind it; what is in front of them all is one
    // open beam.
    Node open;
    open.kind = Kind::Open;
    if (walls.empty()) {
        root_ = add(open);
        return;
    }
    root_ = static_cast<uint32_t>(nodes_.size());
    for (size_t i = 0; i < walls.size(); ++i) {
        Node wall;
        wall.kind = Kind::Split;
        wall.plane = walls[i];
        const uint32_t self = add(wall);
        Node outside;
        outside.kind = Kind::Outside;
        nodes_[self].back = add(outside);
        nodes_[self].front =
            static_cast<uint32_t>(nodes_.size());  // the next wall, or the open leaf
    }
    add(open);
}

uint32_t BeamTree::add(Node node) {
    nodes_.push_back(node);
    return static_cast<uint32_t>(nodes_.size() - 1);
}

size_t BeamTree::insert(const Polygon& polygon) {
    const Plane plane = planeOf(polygon);
    // Seen edge-on from the light a polygon blocks nothing (its beam has no volume).
    if (!plane.valid() || polygon.size() < 3 || std::abs(plane.distance(light_)) <= epsilon_)
        return 0;
    size_t added = 0;
    insertAt(root_, polygon, facingLight(plane, light_), added);
    return added;
}

void BeamTree::insertAt(uint32_t node, const Polygon& polygon, const Plane& plane, size_t& added) {
    if (polygon.empty()) return;
    const Node& n = nodes_[node];
    switch (n.kind) {
        case Kind::Solid:
        case Kind::Blocker:
        case Kind::Outside:
            return;  // already hidden, or never lit
        case Kind::Open:
            attach(node, polygon, Kind::Solid, plane, Plane{});
            visible_.push_back({polygon, plane, false});
            ++added;
            return;
        case Kind::Split: {
            const Split parts = split(n.plane, polygon, epsilon_);
            const uint32_t back = n.back, front = n.front;  // `n` moves when nodes are added
            insertAt(back, parts.back, plane, added);
            insertAt(front, parts.front, plane, added);
            return;
        }
    }
}

void BeamTree::attach(uint32_t leaf, const Polygon& polygon, Kind inside, const Plane& solidPlane,
                      const Plane& stopper) {
    // One splitting plane through L and each edge; the polygon's beam is behind them all.
    const glm::dvec3 c = centroid(polygon);
    const Kind outside = nodes_[leaf].kind;  // what the rest of the leaf stays
    const Node keep = nodes_[leaf];
    uint32_t node = leaf;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3 &v0 = polygon[i], &v1 = polygon[(i + 1) % polygon.size()];
        Plane edge = Plane::through(light_, v0, v1);
        if (!edge.valid()) continue;  // an edge pointing at the light bounds nothing
        if (edge.distance(c) > 0.0) edge = edge.flipped();
        Node rest = keep;
        rest.kind = outside;
        const uint32_t front = add(rest);
        const uint32_t back = add(Node{});
        Node& split = nodes_[node];
        split = Node{};
        split.kind = Kind::Split;
        split.plane = edge;
        split.front = front;
        split.back = back;
        node = back;
    }
    Node& beam = nodes_[node];
    beam = keep;
    beam.kind = inside;
    beam.solidPlane = solidPlane;
    beam.stopperPlane = stopper;
}

void BeamTree::addBackplate(const Polygon& far) {
    const Plane plane = planeOf(far);
    if (!plane.valid()) return;
    backplateAt(root_, far, facingLight(plane, light_));
}

void BeamTree::backplateAt(uint32_t node, const Polygon& polygon, const Plane& plane) {
    if (polygon.empty()) return;
    const Node& n = nodes_[node];
    if (n.kind == Kind::Open) {
        visible_.push_back({polygon, plane, true});
        return;
    }
    if (n.kind != Kind::Split) return;
    const Split parts = split(n.plane, polygon, epsilon_);
    const uint32_t back = n.back, front = n.front;
    backplateAt(back, parts.back, plane);
    backplateAt(front, parts.front, plane);
}

void BeamTree::insertStopper(const Polygon& polygon) {
    const Plane plane = planeOf(polygon);
    if (!plane.valid() || polygon.size() < 3 || std::abs(plane.distance(light_)) <= epsilon_)
        return;
    stopAt(root_, polygon, facingLight(plane, light_));
}

void BeamTree::stopAt(uint32_t node, const Polygon& polygon, const Plane& plane) {
    if (polygon.empty()) return;
    const Node& n = nodes_[node];
    switch (n.kind) {
        case Kind::Open:
        case Kind::Outside:
        case Kind::Blocker:  // a nearer stopper already darkens this beam
            return;
        case Kind::Solid: {
            // Seed 004, figure 5.5: the stopper's beam inside the solid beam becomes a blocker
            // leaf.
            const Plane solid = n.solidPlane;
            attach(node, polygon, Kind::Blocker, solid, plane);
            return;
        }
        case Kind::Split: {
            const Split parts = split(n.plane, polygon, epsilon_);
            const uint32_t back = n.back, front = n.front;
            stopAt(back, parts.back, plane);
            stopAt(front, parts.front, plane);
            return;
        }
    }
}

void BeamTree::markAllUncertain() {
    for (Node& n : nodes_)
        if (n.kind == Kind::Open) {
            n.kind = Kind::Solid;
            n.solidPlane = Plane{glm::dvec3(0.0), -1.0};  // nothing is in front of it
        }
    visible_.clear();
}

Region BeamTree::classify(const glm::dvec3& p) const {
    uint32_t node = root_;
    while (nodes_[node].kind == Kind::Split)
        node = nodes_[node].plane.distance(p) < -epsilon_ ? nodes_[node].back : nodes_[node].front;
    const Node& n = nodes_[node];
    switch (n.kind) {
        case Kind::Outside:
            return Region::Outside;
        case Kind::Open:
            return Region::Lit;
        case Kind::Solid:
            return n.solidPlane.distance(p) >= -epsilon_ ? Region::Lit : Region::Uncertain;
        case Kind::Blocker:
            if (n.solidPlane.distance(p) >= -epsilon_) return Region::Lit;
            return n.stopperPlane.distance(p) >= -epsilon_ ? Region::Uncertain : Region::Unlit;
        case Kind::Split:
            break;
    }
    return Region::Outside;
}

bool BeamTree::isInside(const glm::dvec3& p) const {
    const Region r = classify(p);
    return r == Region::Uncertain || r == Region::Unlit;
}

BeamTree::Parts BeamTree::partition(const Polygon& polygon) const {
    Parts parts;
    partitionAt(root_, polygon, parts);
    return parts;
}

void BeamTree::partitionAt(uint32_t node, const Polygon& polygon, Parts& parts) const {
    if (polygon.empty()) return;
    const Node& n = nodes_[node];
    switch (n.kind) {
        case Kind::Outside:
            return;
        case Kind::Open:
            parts.lit.push_back(polygon);
            return;
        case Kind::Solid: {
            // Program 5: the leaf's polygon plane separates what is in front of the visible set.
            Split s = split(n.solidPlane, polygon, epsilon_);
            if (!s.front.empty()) parts.lit.push_back(std::move(s.front));
            if (!s.back.empty()) parts.uncertain.push_back(std::move(s.back));
            return;
        }
        case Kind::Blocker: {
            Split s = split(n.solidPlane, polygon, epsilon_);
            if (!s.front.empty()) parts.lit.push_back(std::move(s.front));
            Split t = split(n.stopperPlane, s.back, epsilon_);
            if (!t.front.empty()) parts.uncertain.push_back(std::move(t.front));
            if (!t.back.empty()) parts.unlit.push_back(std::move(t.back));
            return;
        }
        case Kind::Split: {
            const Split s = split(n.plane, polygon, epsilon_);
            partitionAt(n.back, s.back, parts);
            partitionAt(n.front, s.front, parts);
            return;
        }
    }
}

}  // namespace ls::beam
