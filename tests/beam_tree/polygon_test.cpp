// Splitting convex polygons by thick planes (seed 004, 4.3).
#include <gtest/gtest.h>

#include "beam_tree/polygon.h"

using namespace ls::beam;

namespace {

Polygon unitSquare(double z = 0.0) {
    return {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}};
}
const Plane kXHalf{{1, 0, 0}, -0.5};  // x = 0.5, front at x > 0.5

}  // namespace

TEST(Polygon, SplitCutsAtTheCrossingAndKeepsTheArea) {
    const Split s = split(kXHalf, unitSquare(), 1e-9);
    EXPECT_NEAR(area(s.front), 0.5, 1e-12);
    EXPECT_NEAR(area(s.back), 0.5, 1e-12);
    for (const auto& v : s.front) EXPECT_GE(v.x, 0.5 - 1e-12);
    for (const auto& v : s.back) EXPECT_LE(v.x, 0.5 + 1e-12);
}

TEST(Polygon, APolygonWithinThePlanesThicknessGoesWholeToTheFront) {
    const Plane z{{0, 0, 1}, 0.0};
    const Polygon nearlyIn{{0, 0, 1e-4}, {1, 0, -1e-4}, {1, 1, 1e-4}, {0, 1, -1e-4}};
    const Split thick = split(z, nearlyIn, 1e-3);
    EXPECT_EQ(thick.front.size(), 4u);
    EXPECT_TRUE(thick.back.empty());
    // Without the thickness the same polygon is cut into slivers.
    const Split thin = split(z, nearlyIn, 0.0);
    EXPECT_FALSE(thin.front.empty());
    EXPECT_FALSE(thin.back.empty());
}

TEST(Polygon, AVertexOnThePlaneBelongsToBothSides) {
    const Polygon triangle{{0.5, 0, 0}, {1, 1, 0}, {0, 1, 0}};  // first vertex on x = 0.5
    const Split s = split(kXHalf, triangle, 1e-9);
    EXPECT_EQ(s.front.size(), 3u);
    EXPECT_EQ(s.back.size(), 3u);
    EXPECT_NEAR(area(s.front) + area(s.back), area(triangle), 1e-12);
}

TEST(Polygon, PlaneOfIsNewellsNormal) {
    const Plane p = planeOf(unitSquare(2.0));
    EXPECT_NEAR(p.n.z, 1.0, 1e-12);
    EXPECT_NEAR(p.distance({5, 5, 2}), 0.0, 1e-12);
    EXPECT_FALSE(planeOf({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}).valid());  // collinear: no plane
}
