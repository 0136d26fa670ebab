#include "retire_list.h"

namespace rg {

void RetireList::retire(uint64_t lastUse, std::function<void()> destroy) {
    pending_.push_back({lastUse, std::move(destroy)});
}

void RetireList::collect(uint64_t completed) {
    // In order of retirement: memory retired after the objects bound to it goes after them.
    while (!pending_.empty() && pending_.front().lastUse <= completed) {
        auto destroy = std::move(pending_.front().destroy);
        pending_.pop_front();
        destroy();
    }
}

void RetireList::collectAll() {
    collect(UINT64_MAX);
}

}  // namespace rg
