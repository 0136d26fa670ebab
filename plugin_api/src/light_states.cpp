#include "light_states.h"

namespace lightscatter::detail {

LightStates::State& LightStates::of(uint64_t id, const ls::MethodUnit& method, uint64_t frame) {
    State& s = states_[id];
    if (s.method != &method) {
        s.data = method.makeData();
        s.method = &method;
        s.options.reset();
    }
    s.lastFrame = frame;
    return s;
}

void LightStates::release(uint64_t unusedBefore) {
    std::erase_if(states_, [&](const auto& e) { return e.second.lastFrame < unusedBefore; });
}

}  // namespace lightscatter::detail
