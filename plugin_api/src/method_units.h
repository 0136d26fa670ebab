#pragma once
// The public Method as the frame graph's method (passes/registry): the registry lists the methods
// in the enum's order, Auto last and outside it.
#include <lightscatter/lightscatter.h>
#include "shared/method_unit.h"

namespace lightscatter::detail {

// Null for Method::Auto (and for a value outside the enum).
const ls::MethodUnit* methodUnit(Method m);

}  // namespace lightscatter::detail
