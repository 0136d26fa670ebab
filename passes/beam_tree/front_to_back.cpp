#include "front_to_back.h"

#include <algorithm>
#include <numeric>

namespace ls::beam {
namespace {

struct Node {
    Plane plane;
    std::vector<Polygon> on;  // in the splitter's plane (within epsilon)
    int front = -1, back = -1;
};

struct Work {
    int node;
    std::vector<Polygon> polygons;
};

}  // namespace

std::vector<Polygon> frontToBack(std::vector<Polygon> polygons, const glm::dvec3& eye,
                                 double epsilon) {
    // Largest first: the subsets below keep this order, so every node splits by its largest
    // polygon.
    std::vector<double> areas(polygons.size());
    for (size_t i = 0; i < polygons.size(); ++i) areas[i] = area(polygons[i]);
    std::vector<size_t> order(polygons.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return areas[a] > areas[b]; });
    std::vector<Polygon> sorted;
    sorted.reserve(polygons.size());
    for (size_t i : order)
        if (planeOf(polygons[i]).valid()) sorted.push_back(std::move(polygons[i]));

    std::vector<Node> nodes;
    std::vector<Work> work;
    if (!sorted.empty()) {
        nodes.emplace_back();
        work.push_back({0, std::move(sorted)});
    }
    while (!work.empty()) {
        Work w = std::move(work.back());
        work.pop_back();
        Node node;
        node.plane = planeOf(w.polygons[0]);
        std::vector<Polygon> front, back;
        for (Polygon& p : w.polygons) {
            double lo = 1e300, hi = -1e300;
            for (const glm::dvec3& v : p) {
                const double s = node.plane.distance(v);
                lo = std::min(lo, s);
                hi = std::max(hi, s);
            }
            if (lo >= -epsilon && hi <= epsilon) {
                node.on.push_back(std::move(p));
            } else if (lo >= -epsilon) {
                front.push_back(std::move(p));
            } else if (hi <= epsilon) {
                back.push_back(std::move(p));
            } else {
                Split s = split(node.plane, p, epsilon);
                if (!s.front.empty()) front.push_back(std::move(s.front));
                if (!s.back.empty()) back.push_back(std::move(s.back));
            }
        }
        const int index = w.node;
        if (!front.empty()) {
            node.front = static_cast<int>(nodes.size());
            nodes.emplace_back();
            work.push_back({node.front, std::move(front)});
        }
        if (!back.empty()) {
            node.back = static_cast<int>(nodes.size());
            nodes.emplace_back();
            work.push_back({node.back, std::move(back)});
        }
        nodes[static_cast<size_t>(index)] = std::move(node);
    }

    // Traverse: the eye's side of each plane first, then the plane's own polygons, then the far
    // side. A stack of nodes to open (>= 0) and nodes whose polygons to emit (encoded as -1 - i).
    std::vector<Polygon> out;
    std::vector<int> stack;
    if (!nodes.empty()) stack.push_back(0);
    while (!stack.empty()) {
        const int item = stack.back();
        stack.pop_back();
        if (item < 0) {
            for (Polygon& p : nodes[static_cast<size_t>(-1 - item)].on) out.push_back(std::move(p));
            continue;
        }
        const Node& n = nodes[static_cast<size_t>(item)];
        const bool eyeInFront = n.plane.distance(eye) >= 0.0;
        const int nearSide = eyeInFront ? n.front : n.back, farSide = eyeInFront ? n.back : n.front;
        // Pushed in reverse: near side, then this node's polygons, then the far side.
        if (farSide >= 0) stack.push_back(farSide);
        stack.push_back(-1 - item);
        if (nearSide >= 0) stack.push_back(nearSide);
    }
    return out;
}

}  // namespace ls::beam
