#include "host_data.h"

namespace rg {

void FrameData::put(uint32_t graph, uint32_t id, const void* tag, const void* value) {
    for (Entry& e : entries_)
        if (e.graph == graph && e.id == id) {
            e = {graph, id, tag, value};
            return;
        }
    entries_.push_back({graph, id, tag, value});
}

const void* FrameData::find(uint32_t graph, uint32_t id, const void* tag) const {
    for (const Entry& e : entries_)
        if (e.graph == graph && e.id == id) return e.tag == tag ? e.value : nullptr;
    return nullptr;
}

}  // namespace rg
