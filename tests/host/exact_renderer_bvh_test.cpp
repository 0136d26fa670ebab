// The reference's ray queries: the watertight triangle test, the BVH against a brute-force loop
// over the same triangles, closed meshes that a ray must never slip through, and Embree's
// traversal answering exactly as the double BVH's own on rays that graze edges by a few ulps.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "exact_renderer/bvh.h"
#include "exact_renderer/embree_occlusion.h"

namespace {

using host::reference::Bvh;
using host::reference::EmbreeOcclusion;
using host::reference::intersectTriangle;
using host::reference::OcclusionQuery;
using host::reference::PreparedRay;
using host::reference::Triangle;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::optional<double> bruteClosest(const std::vector<Triangle>& tris, const PreparedRay& ray,
                                   double tMin, double tMax) {
    std::optional<double> best;
    for (const Triangle& t : tris) {
        if (const auto hit = intersectTriangle(ray, t, tMin, best ? *best : tMax)) best = hit;
    }
    return best;
}

bool bruteAny(const std::vector<Triangle>& tris, const PreparedRay& ray, double tMin, double tMax) {
    for (const Triangle& t : tris) {
        if (intersectTriangle(ray, t, tMin, tMax)) return true;
    }
    return false;
}

// Vertices are rounded to float, as MeshData stores them.
glm::dvec3 asFloat(const glm::dvec3& p) {
    return glm::dvec3(glm::vec3(p));
}

glm::dvec3 randomUnit(std::mt19937_64& rng) {
    std::normal_distribution<double> n;
    for (;;) {
        const glm::dvec3 v(n(rng), n(rng), n(rng));
        if (glm::length(v) > 1e-6) return glm::normalize(v);
    }
}

// A soup of triangles of mixed sizes, with some degenerate and duplicated ones.
std::vector<Triangle> randomSoup(std::mt19937_64& rng, int count) {
    std::uniform_real_distribution<double> pos(-10.0, 10.0);
    std::uniform_real_distribution<double> size(0.01, 3.0);
    std::vector<Triangle> tris;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 c(pos(rng), pos(rng), pos(rng));
        const double s = i % 17 == 0 ? 15.0 : size(rng);
        Triangle t{asFloat(c + s * randomUnit(rng)), asFloat(c + s * randomUnit(rng)),
                   asFloat(c + s * randomUnit(rng))};
        if (i % 53 == 0) t.c = t.b;                         // zero area
        if (i % 61 == 0 && !tris.empty()) t = tris.back();  // duplicate
        tris.push_back(t);
    }
    return tris;
}

glm::dvec3 randomDirection(std::mt19937_64& rng, int i) {
    glm::dvec3 d = randomUnit(rng);
    // Axis-parallel rays make the slab test divide by zero; they must still work.
    if (i % 7 == 0) d.x = 0.0;
    if (i % 11 == 0) d.y = 0.0;
    if (i % 13 == 0) d = glm::dvec3(0.0, 0.0, i % 2 ? 1.0 : -1.0);
    return glm::length(d) > 0.0 ? d : glm::dvec3(1.0, 0.0, 0.0);
}

TEST(ReferenceTriangle, HitsAtTheExpectedDistanceAndRespectsTheRange) {
    const Triangle tri{{0, 0, -2}, {1, 0, -2}, {0, 1, -2}};
    const PreparedRay ray({0, 0, 0}, {0.25, 0.25, -2.0});
    const auto t = intersectTriangle(ray, tri, 0.0, kInf);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 1.0, 1e-15);  // in units of the (unnormalised) direction
    EXPECT_FALSE(intersectTriangle(ray, tri, 0.0, 0.99));
    EXPECT_FALSE(intersectTriangle(ray, tri, 1.01, kInf));
    EXPECT_FALSE(intersectTriangle(PreparedRay({0, 0, 0}, {0.75, 0.75, -2.0}), tri, 0.0, kInf));
    EXPECT_FALSE(intersectTriangle(PreparedRay({0, 0, 0}, {0.25, 0.25, 2.0}), tri, 0.0, kInf));
    // Both windings are hit.
    EXPECT_TRUE(intersectTriangle(ray, Triangle{tri.a, tri.c, tri.b}, 0.0, kInf));
    // A vertex and an edge belong to the triangle.
    EXPECT_TRUE(intersectTriangle(PreparedRay({0, 0, 0}, {1, 0, -2}), tri, 0.0, kInf));
    EXPECT_TRUE(intersectTriangle(PreparedRay({0, 0, 0}, {0.5, 0, -2}), tri, 0.0, kInf));
    // Degenerate triangles and edge-on rays never hit.
    EXPECT_FALSE(intersectTriangle(ray, Triangle{tri.a, tri.b, tri.b}, 0.0, kInf));
    EXPECT_FALSE(intersectTriangle(PreparedRay({-1, 0.2, -2}, {1, 0, 0}), tri, 0.0, kInf));
}

TEST(ReferenceBvh, MatchesBruteForceOnRandomSoups) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> pos(-14.0, 14.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hits = 0, anyTrue = 0, checked = 0;
    for (const int count : {1, 2, 5, 37, 300, 3000}) {
        const std::vector<Triangle> tris = randomSoup(rng, count);
        const Bvh bvh(tris);
        EXPECT_EQ(bvh.triangles().size(), tris.size());
        for (int i = 0; i < 3000; ++i) {
            const PreparedRay ray(glm::dvec3(pos(rng), pos(rng), pos(rng)),
                                  randomDirection(rng, i));
            const double tMin = i % 3 == 0 ? 0.0 : 5.0 * unit(rng);
            const double tMax = i % 4 == 0 ? kInf : tMin + 20.0 * unit(rng);
            const auto expected = bruteClosest(tris, ray, tMin, tMax);
            const auto actual = bvh.closestHit(ray, tMin, tMax);
            ASSERT_EQ(expected.has_value(), actual.has_value()) << count << " triangles, ray " << i;
            if (expected) {
                ++hits;
                EXPECT_EQ(actual->t, *expected) << count << " triangles, ray " << i;
                const auto again =
                    intersectTriangle(ray, bvh.triangles()[actual->triangle], tMin, tMax);
                ASSERT_TRUE(again);
                EXPECT_EQ(*again, actual->t);
            }
            const bool any = bvh.anyHit(ray, tMin, tMax);
            EXPECT_EQ(any, bruteAny(tris, ray, tMin, tMax)) << count << " triangles, ray " << i;
            anyTrue += any;
            ++checked;
        }
    }
    // Both outcomes must be well represented, or the comparison proves little.
    EXPECT_GT(hits, checked / 10);
    EXPECT_LT(hits, checked - checked / 10);
    EXPECT_GT(anyTrue, hits / 2);
}

TEST(ReferenceBvh, EmptyBvhHitsNothing) {
    const Bvh bvh;
    const PreparedRay ray({0, 0, 0}, {0, 0, -1});
    EXPECT_FALSE(bvh.closestHit(ray, 0.0, kInf));
    EXPECT_FALSE(bvh.anyHit(ray, 0.0, kInf));
    EXPECT_EQ(bvh.coordinateScale(), 0.0);
}

struct ClosedMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<glm::uvec3> faces;
    std::vector<Triangle> triangles() const {
        std::vector<Triangle> out;
        for (const glm::uvec3& f : faces)
            out.push_back({vertices[f.x], vertices[f.y], vertices[f.z]});
        return out;
    }
};

// A box [-1, 1]^3 (12 triangles sharing 8 vertices: every face diagonal is a shared edge too) and
// an octahedron (4 triangles meet at every vertex), turned by an arbitrary rotation so that no edge
// is axis-aligned, rounded to float.
std::vector<ClosedMesh> closedMeshes() {
    const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, 3)));
    auto place = [&](std::vector<glm::dvec3> v) {
        for (glm::dvec3& p : v) p = asFloat(glm::dvec3(turn * glm::dvec4(p * 1.3, 1.0)) + 0.25);
        return v;
    };
    ClosedMesh box;
    for (int i = 0; i < 8; ++i)
        box.vertices.push_back({i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1});
    box.vertices = place(box.vertices);
    box.faces = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    ClosedMesh octa;
    octa.vertices = place({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}});
    octa.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                  {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return {box, octa};
}

TEST(ReferenceBvh, NoRayLeaksThroughSharedEdgesOrVertices) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int rays = 0;
    for (const ClosedMesh& mesh : closedMeshes()) {
        const std::vector<Triangle> tris = mesh.triangles();
        const Bvh bvh(tris);
        glm::dvec3 centre(0.0);
        for (const glm::dvec3& v : mesh.vertices)
            centre += v / static_cast<double>(mesh.vertices.size());
        // Targets exactly on edges (every edge of every face, so the diagonals too) and vertices.
        std::vector<glm::dvec3> targets = mesh.vertices;
        for (const glm::uvec3& f : mesh.faces) {
            for (int e = 0; e < 3; ++e) {
                const glm::dvec3 a = mesh.vertices[f[e]], b = mesh.vertices[f[(e + 1) % 3]];
                for (int k = 0; k < 40; ++k) targets.push_back(a + unit(rng) * (b - a));
                targets.push_back(0.5 * (a + b));
            }
        }
        for (const glm::dvec3& target : targets) {
            for (int k = 0; k < 4; ++k) {
                // From inside (near the centre, and anywhere in a smaller copy) ...
                const glm::dvec3 inside =
                    k == 0 ? centre : centre + 0.3 * unit(rng) * randomUnit(rng);
                const glm::dvec3 d = target - inside;
                const PreparedRay in(inside, glm::normalize(d));
                ASSERT_TRUE(bvh.anyHit(in, 0.0, kInf)) << "leak from inside towards an edge";
                const auto hit = bvh.closestHit(in, 0.0, kInf);
                ASSERT_TRUE(hit);
                EXPECT_NEAR(hit->t, glm::length(d), 1e-12);
                // ... and from outside, entering at the same point and going on inside: a leak
                // there would make the far side the closest hit.
                const glm::dvec3 away = glm::normalize(target - centre + 0.5 * randomUnit(rng));
                const glm::dvec3 outside = target + (3.0 + unit(rng)) * away;
                const PreparedRay out(outside, glm::normalize(target - outside));
                const auto entry = bvh.closestHit(out, 0.0, kInf);
                ASSERT_TRUE(entry);
                EXPECT_NEAR(entry->t, glm::length(target - outside), 1e-9)
                    << "entered past an edge";
                rays += 2;
            }
        }
        // Random directions from inside never escape either.
        for (int i = 0; i < 2000; ++i) {
            const PreparedRay ray(centre + 0.2 * randomUnit(rng), randomDirection(rng, i));
            EXPECT_TRUE(bvh.anyHit(ray, 0.0, kInf));
            ++rays;
        }
    }
    EXPECT_GT(rays, 5000);
}

// Embree decides in float which boxes a ray enters; the answer must still be the double test's.
// Rays aimed at points on triangles' edges and vertices, and at points moved off an edge by
// distances from 1e-14 to 1e-5 of the scene (inside and outside: float rounding alone would
// misjudge most of these), with tMax ending exactly at the target half the time, and from origins
// so far out that the double BVH must answer instead.
TEST(ReferenceBvh, EmbreeAnswersAsTheDoubleBvhOnRaysThatGrazeEdges) {
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<double> pos(-14.0, 14.0);
    const std::vector<Triangle> tris = randomSoup(rng, 400);
    const Bvh bvh(tris);
#ifdef LS_REFERENCE_EMBREE
    ASSERT_TRUE(bvh.usesEmbree()) << "built with Embree, but the BVH does not use it";
#endif
    std::vector<OcclusionQuery> queries;
    for (int i = 0; i < 12000; ++i) {
        const Triangle& t = tris[static_cast<std::size_t>(i) % tris.size()];
        const glm::dvec3 corners[3] = {t.a, t.b, t.c};
        const int e = i % 3;
        const glm::dvec3 a = corners[e], b = corners[(e + 1) % 3], c = corners[(e + 2) % 3];
        glm::dvec3 target = i % 5 == 0 ? a : a + unit(rng) * (b - a);
        // Off the edge, in the triangle's plane, towards the inside (even i) or the outside.
        const glm::dvec3 edge = b - a;
        glm::dvec3 inward = (c - a) - edge * (glm::dot(c - a, edge) / glm::dot(edge, edge));
        if (glm::length(inward) > 0.0 && i % 4 != 0) {
            const double offset = std::pow(10.0, -14.0 + 9.0 * unit(rng)) * 14.0;
            target += (i % 2 == 0 ? offset : -offset) * glm::normalize(inward);
        }
        const double far = i % 97 == 0 ? 1e4 : 1.0;  // beyond Embree's reach: the own BVH
        const glm::dvec3 origin = far * glm::dvec3(pos(rng), pos(rng), pos(rng));
        const glm::dvec3 d = target - origin;
        if (!(glm::length(d) > 0.0)) continue;
        const double distance = glm::length(d);
        const double tMin = i % 3 == 0 ? 0.0 : distance * unit(rng) * 0.5;
        const double tMax = i % 2 == 0 ? distance : (i % 3 == 0 ? kInf : distance * 1.5);
        queries.push_back({PreparedRay(origin, d / distance), tMin, tMax});
    }
    std::vector<uint8_t> batch(queries.size());
    bvh.anyHit(queries, batch);
    int hits = 0, misses = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
        const OcclusionQuery& q = queries[i];
        const bool own = bvh.anyHitOwn(q.ray, q.tMin, q.tMax);
        ASSERT_EQ(own, bruteAny(tris, q.ray, q.tMin, q.tMax)) << "query " << i;
        ASSERT_EQ(bvh.anyHit(q.ray, q.tMin, q.tMax), own) << "query " << i;
        ASSERT_EQ(batch[i] != 0, own) << "query " << i << " (batched)";
        (own ? hits : misses) += 1;
    }
    // Both answers are well represented, so a traversal answering either one always would fail.
    EXPECT_GT(hits, static_cast<int>(queries.size()) / 10);
    EXPECT_GT(misses, static_cast<int>(queries.size()) / 10);
    std::vector<uint8_t> wrongSize(queries.size() + 1);
    EXPECT_THROW(bvh.anyHit(queries, wrongSize), std::invalid_argument);
}

TEST(ReferenceBvh, FromMeshTakesEveryPrimitiveAndRejectsBadIndices) {
    host::MeshData mesh;
    for (const glm::vec3& p : {glm::vec3(0, 0, -1), glm::vec3(1, 0, -1), glm::vec3(0, 1, -1),
                               glm::vec3(0, 0, -3), glm::vec3(-1, 0, -3), glm::vec3(0, -1, -3)}) {
        mesh.vertices.push_back({p, {0, 0, 1}, {0, 0}});
    }
    mesh.indices = {0, 1, 2, 3, 4, 5};
    mesh.primitives = {{0, 3, -1}, {3, 3, -1}};
    const Bvh bvh = Bvh::fromMesh(mesh);
    EXPECT_EQ(bvh.triangles().size(), 2u);
    EXPECT_DOUBLE_EQ(bvh.coordinateScale(), 3.0);
    const auto second = bvh.closestHit(PreparedRay({-0.1, -0.1, 0}, {0, 0, -1}), 0.0, kInf);
    ASSERT_TRUE(second);
    EXPECT_NEAR(second->t, 3.0, 1e-15);
    mesh.indices[4] = 99;
    EXPECT_THROW((void)Bvh::fromMesh(mesh), std::out_of_range);
}

}  // namespace
