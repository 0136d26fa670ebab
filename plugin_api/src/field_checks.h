#pragma once
// The pieces every check of an engine's field is made of: the refusal it throws and the words
// and numbers of its message, written alike whichever field it names.
#include <glm/glm.hpp>
#include <string>

#include <lightscatter/lightscatter.h>

namespace lightscatter::detail {

// Throws InvalidInput, "lightscatter: " and `message`.
[[noreturn]] void fail(const std::string& message);

// A number for a message ("%g").
std::string num(double v);
// A float for a message: the shortest text that reads back as the same float, so that a value
// refused beside a bound never reads as the bound itself ("0.99000001", not "0.99").
std::string floatText(float v);
// A distance for a message: four figures (the planes read from a float32 matrix are not exact).
std::string metres(double v);
// The bounds of lightscatter.h's limits, in the one message every range check gives.
std::string rangeText(double lo, double hi);

bool finite(float v);
// `v`, every component finite.
glm::vec3 vec(const Vec3& v, const std::string& field);
// `v` within [lo, hi]; `why` says what the bounds are (the unit, and the limit they come from).
// The bounds are compared as the floats nearest them, the type `v` was given in: a value written
// as the bound is accepted, and the message quotes the floats compared.
float inRange(float v, const std::string& field, double lo, double hi, const std::string& why);
glm::vec3 vecInRange(const Vec3& v, const std::string& field, double lo, double hi,
                     const std::string& why);

}  // namespace lightscatter::detail
