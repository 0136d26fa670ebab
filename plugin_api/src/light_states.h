#pragma once
// Each light's state across frames, by its identity (LightInput::id): its method's data
// (MethodUnit::makeData, remade when its method changes) and the options its chain last had (a
// method may grow them, the beam tree's buffer). What the graph keeps for a light on the GPU (its
// point-light table) the graph keeps under the same key (rg::PersistentStore).
#include <cstdint>
#include <map>
#include <memory>
#include <optional>

#include "shared/method_unit.h"

namespace lightscatter::detail {

class LightStates {
  public:
    struct State {
        const ls::MethodUnit* method = nullptr;
        std::unique_ptr<ls::LightData> data;
        std::optional<ls::ChainOptions> options;  // its chain's in the last frame recorded
        uint64_t lastFrame = 0;                   // the last frame recorded with the light
    };
    // The light's state for frame `frame` with `method` (its data made where new, or for another
    // method).
    State& of(uint64_t id, const ls::MethodUnit& method, uint64_t frame);
    // Forgets every light no frame from `unusedBefore` on had.
    void release(uint64_t unusedBefore);
    size_t size() const { return states_.size(); }

  private:
    std::map<uint64_t, State> states_;
};

}  // namespace lightscatter::detail
