#include "float64_model/interval.h"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "float64_model/ray_geometry.h"

namespace ls::ref {
namespace {

void expectIntervals(const std::vector<Interval>& actual, const std::vector<Interval>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
        EXPECT_DOUBLE_EQ(actual[i].begin, expected[i].begin) << "interval " << i;
        EXPECT_DOUBLE_EQ(actual[i].end, expected[i].end) << "interval " << i;
    }
}

TEST(Interval, NormaliseClipsSortsMergesAndDropsInvalid) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<Interval> in{{7.0, 12.0}, {-3.0, 1.0}, {2.0, 4.0}, {3.0, 5.0},
                                   {6.0, 6.0},  {nan, 2.0},  {9.0, 8.0}, {5.0, 5.5}};
    expectIntervals(normalizeIntervals(in, 10.0), {{0.0, 1.0}, {2.0, 5.5}, {7.0, 10.0}});
    EXPECT_TRUE(normalizeIntervals(in, 0.0).empty());
    EXPECT_TRUE(normalizeIntervals(in, nan).empty());
}

TEST(Interval, Intersect) {
    const std::vector<Interval> a{{0.0, 2.0}, {3.0, 6.0}, {8.0, 9.0}};
    const std::vector<Interval> b{{1.0, 4.0}, {5.0, 8.5}};
    expectIntervals(intersectIntervals(a, b), {{1.0, 2.0}, {3.0, 4.0}, {5.0, 6.0}, {8.0, 8.5}});
    EXPECT_TRUE(intersectIntervals(a, {}).empty());
}

TEST(Interval, SplitAtInteriorPointsOnly) {
    const std::vector<Interval> in{{0.0, 2.0}, {3.0, 4.0}};
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expectIntervals(splitAt(in, {3.5, 1.0, 0.0, 2.5, 1.0, nan, 4.0}),
                    {{0.0, 1.0}, {1.0, 2.0}, {3.0, 3.5}, {3.5, 4.0}});
}

TEST(Interval, GeometricMeshCoversEveryScale) {
    std::vector<double> pts;
    appendGeometricMesh(pts, 1.0, 0.5, 1.0, 0.0, 40.0);
    const std::vector<double> expected{1.5, 3.0, 9.0, 33.0};
    EXPECT_EQ(pts, expected);
    pts.clear();
    appendGeometricMesh(pts, 1.0, 0.5, -1.0, -10.0, 40.0);
    const std::vector<double> down{0.5, -1.0, -7.0};
    EXPECT_EQ(pts, down);
    pts.clear();
    appendGeometricMesh(pts, 0.0, 0.0, 1.0, 0.0, 1.0);  // a zero step must not loop forever
    EXPECT_TRUE(pts.empty());
}

}  // namespace
}  // namespace ls::ref
