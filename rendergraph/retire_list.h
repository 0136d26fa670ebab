#pragma once
// Objects that frames already recorded may still use on the GPU (a graph no longer chosen, memory
// grown out of, a view of an engine image), destroyed once those frames have completed instead of
// waiting for the device: an engine's frame loop never stalls on the runtime.
#include <cstdint>
#include <deque>
#include <functional>

namespace rg {

class RetireList {
  public:
    RetireList() = default;
    RetireList(const RetireList&) = delete;
    RetireList& operator=(const RetireList&) = delete;
    // Destroys what is left: its owner knows the GPU is done with every frame.
    ~RetireList() { collectAll(); }

    // `destroy` runs once frame `lastUse` (the last frame that may use the object) has completed.
    // Frames are numbered in the order they are recorded.
    void retire(uint64_t lastUse, std::function<void()> destroy);
    // Runs what frames up to `completed` used, in the order it was retired.
    void collect(uint64_t completed);
    void collectAll();
    size_t size() const { return pending_.size(); }

  private:
    struct Pending {
        uint64_t lastUse = 0;
        std::function<void()> destroy;
    };
    std::deque<Pending> pending_;
};

}  // namespace rg
