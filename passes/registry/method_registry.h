#pragma once
// Every method of the frame graph, in lightscatter/methods.inc's order: the public enum's, from the
// same list.
#include <vector>

#include "shared/method_unit.h"

namespace ls {

const std::vector<const MethodUnit*>& methodRegistry();

}  // namespace ls
