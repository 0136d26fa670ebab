#include "float64_model/gauss_kronrod.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "float64_model/medium.h"
#include "float64_model/ray_geometry.h"
#include "test_util.h"

namespace ls::ref {
namespace {

using test::near3;

double powi(double x, int n) {
    double r = 1.0;
    for (int i = 0; i < n; ++i) r *= x;
    return r;
}

// The K15 rule integrates polynomials up to degree 22 exactly: one segment, no refinement.
TEST(GaussKronrod, Degree21PolynomialExactOnOneSegment) {
    const Interval piece{-0.3, 1.7};
    QuadOptions one;
    one.maxSegments = 1;
    const QuadResult r = integrateAdaptive(
        [](double x) { return glm::dvec3(powi(x, 21), powi(x, 20), 1.0); }, {&piece, 1}, one);
    const glm::dvec3 exact((powi(1.7, 22) - powi(-0.3, 22)) / 22.0,
                           (powi(1.7, 21) - powi(-0.3, 21)) / 21.0, 2.0);
    EXPECT_TRUE(near3(r.value, exact, 1e-14));
    EXPECT_EQ(r.evaluations, 15);
}

// The embedded G7 rule is exact to degree 13 and not beyond, so the error estimate vanishes for
// x^13 and not for x^14: this pins the Gauss weights and which nodes they belong to.
TEST(GaussKronrod, EmbeddedGaussRuleHasDegree13) {
    const Interval piece{0.0, 1.0};
    QuadOptions one;
    one.maxSegments = 1;
    const QuadResult r13 =
        integrateAdaptive([](double x) { return glm::dvec3(powi(x, 13)); }, {&piece, 1}, one);
    const QuadResult r14 =
        integrateAdaptive([](double x) { return glm::dvec3(powi(x, 14)); }, {&piece, 1}, one);
    EXPECT_LT(r13.error.x, 1e-15);
    EXPECT_GT(r14.error.x, 1e-9);
    EXPECT_NEAR(r13.value.x, 1.0 / 14.0, 1e-15);
}

TEST(GaussKronrod, AdaptiveSmoothIntegrandsPerChannel) {
    const Interval piece{0.0, kPi};
    const QuadResult r = integrateAdaptive(
        [](double x) {
            return glm::dvec3(std::sin(x), std::exp(3.0 * x), 1e-30 * std::cos(x / 2));
        },
        {&piece, 1});
    EXPECT_TRUE(r.converged);
    EXPECT_TRUE(near3(r.value, {2.0, (std::exp(3.0 * kPi) - 1.0) / 3.0, 2e-30}, 1e-12));
}

// A narrow peak of width 1e-2 inside [-1e4, 1e4], resolved by a geometric mesh around it.
TEST(GaussKronrod, NarrowPeakWithItsMesh) {
    const double w = 1e-2;
    auto f = [w](double x) { return glm::dvec3(1.0 / ((x - 3.3) * (x - 3.3) + w * w)); };
    const double exact = (std::atan((1e4 - 3.3) / w) + std::atan((1e4 + 3.3) / w)) / w;
    const Interval whole{-1e4, 1e4};
    std::vector<double> cuts{3.3};
    appendGeometricMesh(cuts, 3.3, w, 1.0, -1e4, 1e4);
    appendGeometricMesh(cuts, 3.3, w, -1.0, -1e4, 1e4);
    const QuadResult meshed = integrateAdaptive(f, splitAt({&whole, 1}, cuts));
    EXPECT_TRUE(meshed.converged);
    EXPECT_NEAR(meshed.value.x / exact, 1.0, 1e-10);
}

// Why the spot's cone crossings must be breakpoints: a lit stretch that falls between the nodes
// of the first rule is invisible (both rules give 0, so the error estimate is 0 too).
TEST(GaussKronrod, NarrowBoxIsMissedWithoutBreakpoints) {
    auto box = [](double x) { return glm::dvec3(x >= 3.3 && x <= 3.31 ? 1.0 : 0.0); };
    const Interval whole{-1e4, 1e4};
    const QuadResult blind = integrateAdaptive(box, {&whole, 1});
    EXPECT_EQ(blind.value.x, 0.0);
    const QuadResult split = integrateAdaptive(box, splitAt({&whole, 1}, {3.3, 3.31}));
    EXPECT_NEAR(split.value.x, 0.01, 1e-15);
}

TEST(GaussKronrod, JumpAtPieceBoundaryIsExact) {
    auto step = [](double x) { return glm::dvec3(x < 0.3 ? 1.0 : 5.0); };
    const std::vector<Interval> pieces{{0.0, 0.3}, {0.3, 1.0}};
    const QuadResult r = integrateAdaptive(step, pieces);
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.value.x, 0.3 + 5.0 * 0.7, 1e-14);
    // Inside a piece the jump still converges, through bisection, to the requested tolerance.
    const Interval whole{0.0, 1.0};
    QuadOptions loose;
    loose.relTol = 1e-8;
    const QuadResult inner = integrateAdaptive(step, {&whole, 1}, loose);
    EXPECT_NEAR(inner.value.x, 3.8, 1e-7);
}

TEST(GaussKronrod, SegmentBudgetReportsNonConvergence) {
    const Interval whole{0.0, 1.0};
    QuadOptions tight;
    tight.maxSegments = 3;
    const QuadResult r = integrateAdaptive(
        [](double x) { return glm::dvec3(x < 1.0 / 3.0 ? 1.0 : 0.0); }, {&whole, 1}, tight);
    EXPECT_FALSE(r.converged);
}

TEST(GaussKronrod, EmptyAndZeroWidthPieces) {
    const std::vector<Interval> pieces{{1.0, 1.0}, {2.0, 1.0}};
    const QuadResult r = integrateAdaptive([](double) { return glm::dvec3(1.0); }, pieces);
    EXPECT_EQ(r.value, glm::dvec3(0.0));
    EXPECT_TRUE(r.converged);
}

}  // namespace
}  // namespace ls::ref
