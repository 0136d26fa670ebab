#pragma once
// Every method of the frame graph, in the order of lightscatter::Method (the public enum lists
// them in the same order; tests hold the two together by name).
#include <string>
#include <vector>

#include "shared/method_unit.h"

namespace ls {

const std::vector<const MethodUnit*>& methodRegistry();
// The method of that name; null when there is none.
const MethodUnit* findMethod(const std::string& name);

}  // namespace ls
