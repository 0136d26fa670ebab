#pragma once

#include <span>
#include <vector>

namespace ls::ref {

// A closed stretch [begin, end] of a ray, in metres from the camera along the view direction.
struct Interval {
    double begin = 0.0;
    double end = 0.0;
};

// Clips every interval to [0, length], drops empty or NaN ones, sorts them and merges overlaps, so
// that a list of lit intervals always means "V = 1 on their union": a caller that hands in
// overlapping shadow-map segments must not count the overlap twice.
std::vector<Interval> normalizeIntervals(std::span<const Interval> intervals, double length);

// Intersection of two normalised lists (each sorted and disjoint); the result is normalised too.
std::vector<Interval> intersectIntervals(std::span<const Interval> a, std::span<const Interval> b);

}  // namespace ls::ref
