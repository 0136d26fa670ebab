#pragma once
// Host data a pass reads when it is recorded (this frame's constants, a CPU-built placement): a
// declared resource of the graph like an image or a buffer, whose value is given to each record()
// rather than captured by the pass. A graph may then be kept and recorded again for later frames,
// and frames may be recorded ahead, without a pass reading an object someone changed since.
#include <cstdint>
#include <string>
#include <vector>

#include "resources.h"

namespace rg {

namespace detail {
// One address per type: a HostDataRef<T> is only ever given a T (no RTTI needed).
template <typename T>
const void* hostDataTag() {
    static const char tag = 0;
    return &tag;
}
}  // namespace detail

template <typename T>
struct HostDataRef {
    uint32_t graph = 0;
    uint32_t id = kInvalidIndex;
    bool valid() const { return id != kInvalidIndex; }
};

struct HostDataDecl {
    std::string name;
    const void* tag = nullptr;  // the type declared
};

// The values of one record(): a pointer per declared host data, valid while record() runs (the
// command buffer keeps copies of whatever a pass records from them).
class FrameData {
  public:
    template <typename T>
    FrameData& set(HostDataRef<T> ref, const T& value) {
        put(ref.graph, ref.id, detail::hostDataTag<T>(), &value);
        return *this;
    }
    // The value for (graph, id), or null where none was given or its type differs.
    const void* find(uint32_t graph, uint32_t id, const void* tag) const;
    template <typename T>
    const T* find(HostDataRef<T> ref) const {
        return static_cast<const T*>(find(ref.graph, ref.id, detail::hostDataTag<T>()));
    }
    // A camera cut: every history the frame reads is taken as holding nothing (HistoryState).
    FrameData& discardHistories(bool discard) {
        discardHistories_ = discard;
        return *this;
    }
    bool discardsHistories() const { return discardHistories_; }

  private:
    struct Entry {
        uint32_t graph = 0, id = kInvalidIndex;
        const void* tag = nullptr;
        const void* value = nullptr;
    };
    void put(uint32_t graph, uint32_t id, const void* tag, const void* value);
    std::vector<Entry> entries_;
    bool discardHistories_ = false;
};

}  // namespace rg
