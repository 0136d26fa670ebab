#pragma once
// The public Method as the frame graph's method: the registry and the enum are made from one list
// (lightscatter/methods.inc), in one order, Auto after them.
#include <lightscatter/lightscatter.h>
#include "registry/method_registry.h"
#include "shared/method_unit.h"

namespace lightscatter::detail {

// Null for Method::Auto (and for a value outside the enum).
inline const ls::MethodUnit* methodUnit(Method m) {
    const auto& all = ls::methodRegistry();
    const auto i = static_cast<size_t>(m);
    return i < all.size() ? all[i] : nullptr;
}

}  // namespace lightscatter::detail
