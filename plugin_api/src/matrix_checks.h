#pragma once
// The checks every matrix an engine gives goes through (the camera's, a light's shadow and cube
// face projections).
#include <glm/glm.hpp>
#include <string>

#include <lightscatter/lightscatter.h>

namespace lightscatter::detail {

// `m` as GLM reads it, every element finite.
glm::mat4 matrix(const Mat4& m, const std::string& field);

// Every element 0: the default of an engine that never set the matrix.
bool allZero(const Mat4& m);

// How far a matrix is from singular: |det| over the product of its rows' lengths (Hadamard's
// bound), 1 for orthogonal rows, 0 for a singular matrix; scale-free, so metres or kilometres do
// not matter.
double conditioning(const glm::dmat4& d);
// The same about the point at the centre of the matrix's clip volume (a translation scales no
// direction): a light or camera a hundred kilometres from the origin has a large last column, not
// a singular matrix.
double conditioning(const glm::mat4& m);

// A world -> clip matrix's scale: products with points within limits::kMaxLength must stay far
// from FLT_MAX, and its largest element far from the subnormals.
void checkMatrixScale(const glm::mat4& m, const std::string& field);

}  // namespace lightscatter::detail
