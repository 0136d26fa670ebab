// Seed 004's beam tree on configurations whose visible set is known: a light at the origin looking
// down -z, squares and boxes in front of it.
#include <gtest/gtest.h>

#include <cmath>

#include "beam_tree/beam_tree.h"
#include "beam_tree/occluders.h"

using namespace ls::beam;

namespace {

// A square of side `side` centred on the -z axis at depth z (< 0), facing the light.
Polygon square(double side, double z, double x = 0.0, double y = 0.0) {
    const double h = side / 2;
    return {{x - h, y - h, z}, {x + h, y - h, z}, {x + h, y + h, z}, {x - h, y + h, z}};
}

double visibleArea(const BeamTree& t, bool backplate = false) {
    double a = 0;
    for (const auto& v : t.visibleSet())
        if (v.backplate == backplate) a += area(v.polygon);
    return a;
}

OrientedBox box(glm::dvec3 center, glm::dvec3 half) {
    OrientedBox b;
    b.center = center;
    b.halfExtents = half;
    return b;
}

}  // namespace

TEST(BeamTree, ClassifiesPointsAroundOneSquare) {
    BeamTree t({0, 0, 0}, {});
    EXPECT_EQ(t.insert(square(2.0, -2.0)), 1u);
    EXPECT_EQ(t.classify({0, 0, -1}), Region::Lit);            // between light and square
    EXPECT_EQ(t.classify({0, 0, -3}), Region::Uncertain);      // behind it (no inner volume)
    EXPECT_EQ(t.classify({0.9, 0.9, -3}), Region::Uncertain);  // behind its corner, inside the beam
    EXPECT_EQ(t.classify({1.6, 0, -3}), Region::Lit);          // beside the beam (it widens to 1.5)
    EXPECT_EQ(t.classify({0, 0, 3}), Region::Lit);             // behind the light
    EXPECT_TRUE(t.isInside({0, 0, -10}));
    EXPECT_FALSE(t.isInside({0, 0, -1.5}));
    // A point on the square itself is in front of it (thick plane), so lit.
    EXPECT_EQ(t.classify({0.3, 0.2, -2.0}), Region::Lit);
}

TEST(BeamTree, WallsBoundTheLightsFrustum) {
    const LightFrustum f = spotFrustum({0, 0, 0}, {0, 0, -1}, 0.5, 10.0);
    BeamTree t(f.position, f.walls);
    EXPECT_EQ(t.classify({0, 0, -5}), Region::Lit);
    EXPECT_EQ(t.classify({5, 0, -5}), Region::Outside);  // tan(0.5) = 0.55: x = 5 at z = -5 is out
    EXPECT_EQ(t.classify({0, 0, 5}), Region::Outside);   // behind the spot
    t.addBackplate(f.far);
    const double side = 2 * 10.0 * std::tan(0.5);
    EXPECT_NEAR(visibleArea(t, true), side * side, 1e-9);
}

// Front to back, a near square hides part of a far one: the far one's visible part is its area
// minus the near square's shadow on it. Back to front, the far square claims the beams first and
// the near one falls into its solid space, lost: the order is the caller's duty (seed 004, 4.2).
TEST(BeamTree, FrontToBackInsertionGivesTheVisibleSet) {
    BeamTree t({0, 0, 0}, {});
    t.insert(square(1.0, -2.0));
    t.insert(square(4.0, -6.0));
    // The near square's shadow at z = -6 has side 3.
    EXPECT_NEAR(visibleArea(t), 1.0 + (16.0 - 9.0), 1e-9);
    EXPECT_EQ(t.classify({0, 0, -4}), Region::Uncertain);
    EXPECT_EQ(t.classify({1.8, 0, -5.9}), Region::Lit);
    EXPECT_EQ(t.classify({1.8, 0, -6.5}), Region::Uncertain);

    BeamTree wrong({0, 0, 0}, {});
    wrong.insert(square(4.0, -6.0));
    wrong.insert(square(1.0, -2.0));
    EXPECT_NEAR(visibleArea(wrong), 16.0, 1e-9);
    EXPECT_EQ(wrong.classify({0, 0, -4}), Region::Lit);  // behind the near square, wrongly lit
}

// Seed 004's bounding volumes: a box behind a box, each the outer volume of an object with an inner
// box inside. Visible set: the near box's light-facing face and the far box's face minus the near
// one's shadow; behind an inner box the light is certainly gone.
TEST(BeamTree, TheVisibleSetOfABoxBehindABox) {
    const LightFrustum f = spotFrustum({0, 0, 0}, {0, 0, -1}, 0.8, 20.0);
    std::vector<Occluder> boxes(2);
    boxes[0].outer = box({0, 0, -6.5}, {2, 2, 0.5});  // far, listed first: the build sorts them
    boxes[0].inner = box({0, 0, -6.5}, {1.5, 1.5, 0.4});
    boxes[1].outer = box({0, 0, -2.5}, {0.5, 0.5, 0.5});
    boxes[1].inner = box({0, 0, -2.5}, {0.25, 0.25, 0.25});
    const LightVolume v = buildLightVolume(f, boxes);
    // Light-facing faces: only the z = -2 and z = -6 faces (a light on the axis is behind the
    // planes of every side face).
    EXPECT_EQ(v.outerPolygons, 2u);
    EXPECT_NEAR(visibleArea(v.tree), 1.0 + (16.0 - 9.0), 1e-9);
    EXPECT_EQ(v.tree.classify({0, 0, -1.5}), Region::Lit);
    EXPECT_EQ(v.tree.classify({0.45, 0, -2.1}),
              Region::Uncertain);  // inside the near outer box, not its inner
    EXPECT_EQ(v.tree.classify({0, 0, -2.5}), Region::Unlit);   // behind the near inner box's face
    EXPECT_EQ(v.tree.classify({0, 0, -4.0}), Region::Unlit);   // in its shadow
    EXPECT_EQ(v.tree.classify({1.8, 0, -5.95}), Region::Lit);  // lit part of the far face
    EXPECT_EQ(v.tree.classify({1.8, 0, -6.05}),
              Region::Uncertain);                               // inside the far outer box only
    EXPECT_EQ(v.tree.classify({0.5, 0, -8.0}), Region::Unlit);  // behind the far inner box
    EXPECT_EQ(v.tree.classify({0, 0, 1.0}), Region::Outside);
}

// Coplanar input: two squares sharing an edge, and a duplicate of one. The thick planes keep the
// shared edge from leaving slivers, and the duplicate adds nothing.
TEST(BeamTree, ThickPlanesOnCoplanarInput) {
    BeamTree t({0, 0, 0}, {});
    EXPECT_EQ(t.insert(square(1.0, -2.0, -0.5)), 1u);
    t.insert(square(1.0, -2.0, 0.5));
    EXPECT_NEAR(visibleArea(t), 2.0, 1e-9);
    EXPECT_EQ(t.insert(square(1.0, -2.0, -0.5)), 0u);  // the same square again: already solid
    EXPECT_NEAR(visibleArea(t), 2.0, 1e-9);
    // A point within the thickness of the shared edge's plane is classified the same way whichever
    // way rounding falls: in front of both beams' edge planes (seed 004's rule for points on a
    // plane), so lit, a seam epsilon wide. Beyond the thickness it is behind the squares.
    const Region seam = t.classify({0.0, 0.2, -3.0});
    EXPECT_EQ(t.classify({1e-9, 0.2, -3.0}), seam);
    EXPECT_EQ(t.classify({-1e-9, 0.2, -3.0}), seam);
    EXPECT_EQ(seam, Region::Lit);
    EXPECT_EQ(t.classify({0.01, 0.2, -3.0}), Region::Uncertain);
    EXPECT_EQ(t.classify({-0.01, 0.2, -3.0}), Region::Uncertain);
    // A polygon seen edge-on from the light blocks nothing.
    EXPECT_EQ(t.insert({{0, 0, -1}, {0, 1, -1}, {0, 1, -3}, {0, 0, -3}}), 0u);
}

// Partitioning a sampling plane (seed 004, 4.4 and 5.3): its parts by region add up to it, and each
// part is where classify() says.
TEST(BeamTree, PartitionSortsAPolygonsPartsByRegion) {
    const LightFrustum f = spotFrustum({0, 0, 0}, {0, 0, -1}, 0.8, 20.0);
    std::vector<Occluder> boxes(1);
    boxes[0].outer = box({0, 0, -2.5}, {0.5, 0.5, 0.5});
    boxes[0].inner = box({0, 0, -2.5}, {0.25, 0.25, 0.25});
    const LightVolume v = buildLightVolume(f, boxes);
    const Polygon plane = square(12.0, -4.0);  // larger than the frustum there (side 8.24)
    const BeamTree::Parts parts = v.tree.partition(plane);
    double lit = 0, uncertain = 0, unlit = 0;
    for (const auto& p : parts.lit) lit += area(p);
    for (const auto& p : parts.uncertain) uncertain += area(p);
    for (const auto& p : parts.unlit) unlit += area(p);
    const double frustumSide = 2 * 4.0 * std::tan(0.8);
    // Shadows at z = -4: the outer box's front face (z = -2, side 1) spans side 2; the inner box's
    // (z = -2.25, side 0.5) spans 0.5 * 4 / 2.25.
    const double outerShadow = 2.0 * 2.0, innerShadow = std::pow(0.5 * 4.0 / 2.25, 2);
    EXPECT_NEAR(lit + uncertain + unlit, frustumSide * frustumSide, 1e-6);
    EXPECT_NEAR(unlit, innerShadow, 1e-6);
    EXPECT_NEAR(uncertain, outerShadow - innerShadow, 1e-6);
    for (const auto& p : parts.lit) EXPECT_EQ(v.tree.classify(centroid(p)), Region::Lit);
    for (const auto& p : parts.uncertain)
        EXPECT_EQ(v.tree.classify(centroid(p)), Region::Uncertain);
    for (const auto& p : parts.unlit) EXPECT_EQ(v.tree.classify(centroid(p)), Region::Unlit);
}

// Overlapping outer boxes: their faces cut one another in the front-to-back order, and the parts
// inside the other box fall behind its faces. Behind either box is uncertain, behind the first's
// inner box dark, and beside both lit.
TEST(BeamTree, OverlappingOuterBoxesKeepTheirOwnShadows) {
    std::vector<Occluder> boxes(3);
    boxes[0].outer = box({0, 0, -3}, {1, 1, 1});
    boxes[0].inner = box({0, 0, -3}, {0.5, 0.5, 0.5});
    boxes[1].outer = box({1.5, 0, -3.2}, {1, 0.5, 0.5});  // overlaps the first
    boxes[2].outer = box({10, 0, -3}, {1, 1, 1});         // far from both
    const LightFrustum f = spotFrustum({0.75, 0, 5}, {0, 0, -1}, 0.8, 30.0);
    const LightVolume v = buildLightVolume(f, boxes);
    const glm::dvec3 L(0.75, 0, 5);
    auto behind = [&](glm::dvec3 p, double t) { return L + t * (p - L); };
    EXPECT_EQ(v.tree.classify(behind({2.3, 0.0, -2.7}, 1.3)), Region::Uncertain);  // the second's
    EXPECT_EQ(v.tree.classify(behind({0.0, 0.0, -2.0}, 1.5)), Region::Unlit);      // first's inner
    EXPECT_EQ(v.tree.classify(behind({0.0, 0.9, -2.0}, 1.3)), Region::Uncertain);
    EXPECT_EQ(v.tree.classify(behind({2.3, 0.8, -2.7}, 1.3)), Region::Lit);  // over the second
    EXPECT_EQ(v.tree.classify({0.75, 0.0, 0.0}), Region::Lit);
    EXPECT_EQ(v.tree.classify(behind({2.3, 0.0, -2.7}, 0.99)), Region::Lit);  // just in front of it
}

// The test frames' spot over a thin plate (a grille's outer box): everything under the plate, down
// to the ground, is uncertain; the space around it lit.
TEST(BeamTree, AThinPlateUnderASpotMakesTheSpaceBelowItUncertain) {
    const glm::dvec3 light(0.3, 6.0, 0.2);
    const LightFrustum f = spotFrustum(light, {0, -1, 0}, 30.0 * M_PI / 180.0, 20.0);
    Occluder plate;
    plate.outer = box({0.06, 3.0, -0.8}, {1.07, 0.01, 0.81});
    LightVolume v = buildLightVolume(f, {plate});
    for (double y : {2.9, 2.0, 1.0, 0.1})
        for (double x : {-0.5, 0.0, 0.5})
            for (double z : {-1.2, -0.8, -0.4}) {
                // The beam from the light through the plate widens below it.
                const glm::dvec3 p(light.x + (x - light.x) * (6.0 - y) / 3.0 * 0.9, y,
                                   light.z + (z - light.z) * (6.0 - y) / 3.0 * 0.9);
                EXPECT_EQ(v.tree.classify(p), Region::Uncertain) << p.x << " " << p.y << " " << p.z;
            }
    EXPECT_EQ(v.tree.classify({0.3, 4.0, 0.2}), Region::Lit);
    EXPECT_EQ(v.tree.classify({2.5, 1.0, 0.2}), Region::Lit);
}

// A box standing on a floor far from the light: the floor's nearest point is nearer the light than
// the box's, yet the box hides part of the floor. The order must come from what hides what, not
// from distances: the box's shadow on the floor is uncertain, never lit.
TEST(BeamTree, ABoxOnAFloorFartherThanTheFloorsNearestPointStillCastsItsShadow) {
    const glm::dvec3 light(0, 5, 0);
    const LightFrustum f = spotFrustum(light, glm::normalize(glm::dvec3(1, -0.5, 0)), 1.0, 40.0);
    std::vector<Occluder> scene(2);
    scene[0].outer = box({0, -0.1, 0}, {20, 0.1, 20});  // nearest point 5 m below the light
    scene[1].outer = box({8, 1, 0}, {0.5, 1, 0.5});     // nearest point 8 m away
    scene[1].inner = box({8, 1, 0}, {0.4, 0.9, 0.4});
    const LightVolume v = buildLightVolume(f, scene);
    // On the line from the light through the box's centre, past the box, above the floor.
    const glm::dvec3 d = glm::dvec3(8, 1, 0) - light;
    EXPECT_EQ(v.tree.classify(light + 1.15 * d), Region::Unlit);      // behind the inner box
    EXPECT_EQ(v.tree.classify(light + 0.5 * d), Region::Lit);         // between light and box
    EXPECT_EQ(v.tree.classify({9.2, 0.05, 3.0}), Region::Lit);        // beside the shadow
    EXPECT_EQ(v.tree.classify({4.0, -0.5, 0.0}), Region::Uncertain);  // under the floor's face
}
