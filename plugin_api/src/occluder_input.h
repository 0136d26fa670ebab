#pragma once
// The engine's occluders handed to the beam tree, whose folder checks them
// (passes/beam_tree/occluder_checks.h).
#include <vector>

#include <lightscatter/lightscatter.h>
#include "beam_tree/occluders.h"

namespace lightscatter::detail {

// The occluders checked (at most kMaxOccluders, each box valid) and in double, for the beam tree.
std::vector<ls::beam::Occluder> beamOccluders(const std::vector<Occluder>& occluders);

}  // namespace lightscatter::detail
