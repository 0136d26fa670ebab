#include "bvh.h"

#include "embree_occlusion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include <glm/common.hpp>

namespace host::reference {
namespace {

constexpr uint32_t kLeafSize = 4;      // below this a split is not worth a node
constexpr uint32_t kMaxLeafSize = 16;  // above this SAH may not choose a leaf
constexpr int kBins = 16;
// Past this depth splits are medians, so the depth (and the traversal stack) stays bounded even for
// geometry that SAH would peel off one triangle at a time.
constexpr int kMaxSahDepth = 48;
constexpr int kStackSize = 128;

// Rounding in the slab test may shift a box's entry and exit by a few ulps; widening the interval
// by 2 gamma(3) (Ize, "Robust BVH ray traversal", JCGT 2013) keeps a box whose triangle the exact
// test would hit from being rejected.
constexpr double kEps = std::numeric_limits<double>::epsilon() * 0.5;
constexpr double kSlabWiden = 2.0 * (3.0 * kEps) / (1.0 - 3.0 * kEps);

struct Box {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
    void add(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void add(const Box& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    [[nodiscard]] bool empty() const { return lo.x > hi.x; }
    [[nodiscard]] double halfArea() const {
        if (empty()) return 0.0;
        const glm::dvec3 e = hi - lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

Box triangleBox(const Triangle& t) {
    Box b;
    b.add(t.a);
    b.add(t.b);
    b.add(t.c);
    return b;
}

// Entry distance of the ray into the box within [tMin, tMax], or nothing when it misses.
bool slab(const PreparedRay& r, const glm::dvec3& lo, const glm::dvec3& hi, double tMin,
          double tMax, double& enter) {
    double t0 = tMin;
    double t1 = tMax;
    for (int i = 0; i < 3; ++i) {
        double a = (lo[i] - r.origin[i]) * r.inverse[i];
        double b = (hi[i] - r.origin[i]) * r.inverse[i];
        if (a > b) std::swap(a, b);
        a -= std::abs(a) * kSlabWiden;
        b += std::abs(b) * kSlabWiden;
        // 0 * inf (a ray parallel to the slab, its origin on the slab's plane) is NaN: the ray lies
        // in the closed slab, and NaN compares false, so the bounds are left alone.
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        if (t0 > t1) return false;
    }
    enter = t0;
    return true;
}

int largestAxis(const glm::dvec3& e) {
    return e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
}

}  // namespace

PreparedRay::PreparedRay(const glm::dvec3& o, const glm::dvec3& d)
    : origin(o), direction(d), inverse(1.0 / d.x, 1.0 / d.y, 1.0 / d.z) {
    const glm::dvec3 ad = glm::abs(d);
    kz = largestAxis(ad);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    // Keeps the winding, and so the sign convention of the edge functions, the same for every ray.
    if (d[kz] < 0.0) std::swap(kx, ky);
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = 1.0 / d[kz];
}

std::optional<double> intersectTriangle(const PreparedRay& r, const Triangle& tri, double tMin,
                                        double tMax) {
    const glm::dvec3 a = tri.a - r.origin;
    const glm::dvec3 b = tri.b - r.origin;
    const glm::dvec3 c = tri.c - r.origin;
    const double ax = a[r.kx] - r.sx * a[r.kz];
    const double ay = a[r.ky] - r.sy * a[r.kz];
    const double bx = b[r.kx] - r.sx * b[r.kz];
    const double by = b[r.ky] - r.sy * b[r.kz];
    const double cx = c[r.kx] - r.sx * c[r.kz];
    const double cy = c[r.ky] - r.sy * c[r.kz];
    // Edge functions; bvh.cpp is built without FMA contraction so that p*q - s*t is rounded the
    // same way in both triangles of a shared edge (exact negatives), which is what makes it
    // watertight.
    const double u = cx * by - cy * bx;
    const double v = ax * cy - ay * cx;
    const double w = bx * ay - by * ax;
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return std::nullopt;
    const double det = u + v + w;
    if (det == 0.0 || !std::isfinite(det)) return std::nullopt;
    const double t = (u * r.sz * a[r.kz] + v * r.sz * b[r.kz] + w * r.sz * c[r.kz]) / det;
    if (!(t >= tMin && t <= tMax)) return std::nullopt;
    return t;
}

Bvh::Bvh(std::vector<Triangle> triangles, Traversal traversal) {
    for (const Triangle& t : triangles) {
        for (const glm::dvec3& p : {t.a, t.b, t.c}) {
            const glm::dvec3 m = glm::abs(p);
            coordinateScale_ = std::max({coordinateScale_, m.x, m.y, m.z});
        }
    }
    if (triangles.empty()) return;
    if (triangles.size() >= std::numeric_limits<uint32_t>::max() / 2) {
        throw std::length_error("reference BVH: too many triangles");
    }
    std::vector<glm::dvec3> centroids(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        centroids[i] = (triangles[i].a + triangles[i].b + triangles[i].c) / 3.0;
    }
    triangles_ = std::move(triangles);
    nodes_.reserve(2 * triangles_.size());
    build(0, static_cast<uint32_t>(triangles_.size()), centroids);
    if (traversal == Traversal::Embree) embree_ = makeEmbreeOcclusion(triangles_, coordinateScale_);
}

Bvh Bvh::fromMesh(const MeshData& mesh, Traversal traversal) {
    std::vector<Triangle> triangles;
    auto vertex = [&](uint32_t index) -> glm::dvec3 {
        if (index >= mesh.vertices.size()) {
            throw std::out_of_range("reference BVH: vertex index " + std::to_string(index) +
                                    " past the mesh's " + std::to_string(mesh.vertices.size()) +
                                    " vertices");
        }
        return glm::dvec3(mesh.vertices[index].position);
    };
    for (const Primitive& p : mesh.primitives) {
        if (std::size_t{p.firstIndex} + p.indexCount > mesh.indices.size()) {
            throw std::out_of_range("reference BVH: primitive indices past the index buffer");
        }
        for (uint32_t i = 0; i + 2 < p.indexCount; i += 3) {
            const uint32_t* idx = &mesh.indices[p.firstIndex + i];
            triangles.push_back({vertex(idx[0]), vertex(idx[1]), vertex(idx[2])});
        }
    }
    return Bvh(std::move(triangles), traversal);
}

// Builds the subtree over triangles_[begin, end) (reordering that range and `centroids` alike)
// and returns its root's index.
uint32_t Bvh::build(uint32_t begin, uint32_t end, std::vector<glm::dvec3>& centroids) {
    struct Task {
        uint32_t begin, end;
        int depth;
        uint32_t parent;  // node whose `first` gets this subtree's index; UINT32_MAX for the root
    };
    // An explicit work list instead of recursion: pathological inputs must not overflow the
    // stack. The first child is pushed last so it is built next and lands right after its parent.
    std::vector<Task> work{{begin, end, 0, std::numeric_limits<uint32_t>::max()}};
    const uint32_t root = static_cast<uint32_t>(nodes_.size());
    while (!work.empty()) {
        const Task task = work.back();
        work.pop_back();
        const uint32_t index = static_cast<uint32_t>(nodes_.size());
        if (task.parent != std::numeric_limits<uint32_t>::max()) nodes_[task.parent].first = index;
        nodes_.emplace_back();

        Box bounds, centroidBounds;
        for (uint32_t i = task.begin; i < task.end; ++i) {
            bounds.add(triangleBox(triangles_[i]));
            centroidBounds.add(centroids[i]);
        }
        nodes_[index].lo = bounds.lo;
        nodes_[index].hi = bounds.hi;
        const uint32_t count = task.end - task.begin;
        auto makeLeaf = [&] {
            nodes_[index].first = task.begin;
            nodes_[index].count = count;
        };
        if (count <= kLeafSize) {
            makeLeaf();
            continue;
        }

        const glm::dvec3 extent = centroidBounds.hi - centroidBounds.lo;
        const int axis = largestAxis(extent);
        uint32_t mid = task.begin + count / 2;
        bool median = extent[axis] <= 0.0 || task.depth >= kMaxSahDepth;
        if (!median) {
            std::array<Box, kBins> binBox;
            std::array<uint32_t, kBins> binCount{};
            const double scale = kBins / extent[axis];
            auto binOf = [&](uint32_t i) {
                const double x = (centroids[i][axis] - centroidBounds.lo[axis]) * scale;
                return std::clamp(static_cast<int>(x), 0, kBins - 1);
            };
            for (uint32_t i = task.begin; i < task.end; ++i) {
                const int bin = binOf(i);
                binBox[bin].add(triangleBox(triangles_[i]));
                ++binCount[bin];
            }
            // Sweeps from the right to get each suffix's area and count, then from the left.
            std::array<double, kBins> rightCost{};
            Box right;
            uint32_t rightCount = 0;
            for (int b = kBins - 1; b > 0; --b) {
                right.add(binBox[b]);
                rightCount += binCount[b];
                rightCost[b] = right.halfArea() * rightCount;
            }
            Box left;
            uint32_t leftCount = 0;
            double bestCost = std::numeric_limits<double>::infinity();
            int bestSplit = -1;
            for (int b = 1; b < kBins; ++b) {
                left.add(binBox[b - 1]);
                leftCount += binCount[b - 1];
                if (leftCount == 0 || leftCount == count) continue;
                const double cost = left.halfArea() * leftCount + rightCost[b];
                if (cost < bestCost) {
                    bestCost = cost;
                    bestSplit = b;
                }
            }
            // SAH with a traversal step costing one triangle test.
            const double leafCost = static_cast<double>(count);
            const double splitCost = 1.0 + bestCost / std::max(bounds.halfArea(), 1e-300);
            if (bestSplit < 0) {
                median = true;
            } else if (splitCost >= leafCost && count <= kMaxLeafSize) {
                makeLeaf();
                continue;
            } else {
                std::vector<uint32_t> order(count);
                std::iota(order.begin(), order.end(), task.begin);
                const auto split = std::stable_partition(
                    order.begin(), order.end(), [&](uint32_t i) { return binOf(i) < bestSplit; });
                mid = task.begin + static_cast<uint32_t>(split - order.begin());
                std::vector<Triangle> tris;
                std::vector<glm::dvec3> cents;
                tris.reserve(count);
                cents.reserve(count);
                for (uint32_t i : order) {
                    tris.push_back(triangles_[i]);
                    cents.push_back(centroids[i]);
                }
                std::copy(tris.begin(), tris.end(), triangles_.begin() + task.begin);
                std::copy(cents.begin(), cents.end(), centroids.begin() + task.begin);
            }
        }
        if (median) {
            std::vector<uint32_t> order(count);
            std::iota(order.begin(), order.end(), task.begin);
            std::nth_element(order.begin(), order.begin() + count / 2, order.end(),
                             [&](uint32_t x, uint32_t y) {
                                 return centroids[x][axis] < centroids[y][axis] ||
                                        (centroids[x][axis] == centroids[y][axis] && x < y);
                             });
            std::vector<Triangle> tris;
            std::vector<glm::dvec3> cents;
            for (uint32_t i : order) {
                tris.push_back(triangles_[i]);
                cents.push_back(centroids[i]);
            }
            std::copy(tris.begin(), tris.end(), triangles_.begin() + task.begin);
            std::copy(cents.begin(), cents.end(), centroids.begin() + task.begin);
            mid = task.begin + count / 2;
        }
        // Second child first onto the list, so the first child is built next, at index + 1.
        work.push_back({mid, task.end, task.depth + 1, index});
        work.push_back({task.begin, mid, task.depth + 1, std::numeric_limits<uint32_t>::max()});
    }
    return root;
}

std::optional<RayHit> Bvh::closestHit(const PreparedRay& ray, double tMin, double tMax) const {
    if (nodes_.empty()) return std::nullopt;
    std::optional<RayHit> hit;
    double best = tMax;
    std::array<std::pair<uint32_t, double>, kStackSize> stack;
    int top = 0;
    double enter = 0.0;
    if (!slab(ray, nodes_[0].lo, nodes_[0].hi, tMin, best, enter)) return std::nullopt;
    stack[top++] = {0u, enter};
    while (top > 0) {
        const auto [index, entry] = stack[--top];
        if (entry > best) continue;  // a nearer hit was found since this box was pushed
        const Node& node = nodes_[index];
        if (node.count > 0) {
            for (uint32_t i = node.first; i < node.first + node.count; ++i) {
                if (const std::optional<double> t =
                        intersectTriangle(ray, triangles_[i], tMin, best)) {
                    best = *t;
                    hit = RayHit{*t, i};
                }
            }
            continue;
        }
        const uint32_t children[2] = {index + 1, node.first};
        double entries[2];
        bool hits[2];
        for (int c = 0; c < 2; ++c) {
            hits[c] =
                slab(ray, nodes_[children[c]].lo, nodes_[children[c]].hi, tMin, best, entries[c]);
        }
        // The nearer child goes on top, so its hits can prune the farther one.
        const int nearer = hits[0] && hits[1] && entries[1] < entries[0] ? 1 : 0;
        for (int c : {1 - nearer, nearer}) {
            if (hits[c]) stack[top++] = {children[c], entries[c]};
        }
    }
    return hit;
}

bool Bvh::anyHit(const PreparedRay& ray, double tMin, double tMax) const {
    if (embree_ != nullptr)
        if (const std::optional<bool> hit = embree_->anyHit(ray, tMin, tMax)) return *hit;
    return anyHitOwn(ray, tMin, tMax);
}

void Bvh::anyHit(std::span<const OcclusionQuery> queries, std::span<uint8_t> hits) const {
    if (hits.size() != queries.size())
        throw std::invalid_argument("reference BVH: one hit flag per occlusion query");
    std::fill(hits.begin(), hits.end(), EmbreeOcclusion::kUnanswered);
    if (embree_ != nullptr) embree_->anyHit(queries, hits);
    for (std::size_t i = 0; i < queries.size(); ++i)
        if (hits[i] == EmbreeOcclusion::kUnanswered)
            hits[i] = anyHitOwn(queries[i].ray, queries[i].tMin, queries[i].tMax) ? 1 : 0;
}

bool Bvh::anyHitOwn(const PreparedRay& ray, double tMin, double tMax) const {
    if (nodes_.empty()) return false;
    std::array<uint32_t, kStackSize> stack;
    int top = 0;
    stack[top++] = 0;
    double enter = 0.0;
    while (top > 0) {
        const uint32_t index = stack[--top];
        const Node& node = nodes_[index];
        if (!slab(ray, node.lo, node.hi, tMin, tMax, enter)) continue;
        if (node.count > 0) {
            for (uint32_t i = node.first; i < node.first + node.count; ++i) {
                if (intersectTriangle(ray, triangles_[i], tMin, tMax)) return true;
            }
            continue;
        }
        stack[top++] = node.first;
        stack[top++] = index + 1;
    }
    return false;
}

}  // namespace host::reference
