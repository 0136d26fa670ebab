#pragma once

#include <vector>

#include "density.h"
#include "ray.h"

namespace ls::ref {

// Places along a ray with a unit direction (any sign, unsorted) where m changes character, for
// splitting quadrature pieces as lightFeatureDistances does for the light: where the ray crosses
// the base height, and where its part above it falls off, on a geometric mesh from its densest
// point there of first step 1 / (16 k |dy|) (a thin layer would otherwise fit between the nodes of
// a rule); and each box of non-zero density's faces, fade planes and centre planes
// (boxWeightKinks).
[[nodiscard]] std::vector<double> densityFeatureDistances(const Density& density, const Ray& ray);

}  // namespace ls::ref
