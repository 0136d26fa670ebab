#include "persistent_store.h"

#include <vector>

namespace rg {

PersistentStore::Entry& PersistentStore::acquire(const std::string& name, uint64_t key,
                                                 const PersistentImageDesc& desc, uint32_t images,
                                                 uint64_t lastRecorded) {
    Entry& e = entries_[{name, key}];
    const bool shaped = e.images[0] && e.desc == desc && (images < 2 || e.images[1]);
    if (!shaped) {
        retireEntry(e, lastRecorded);
        // Both made before either is kept: a failure leaves the entry empty, not half made.
        std::array<std::unique_ptr<OwnedImage>, 2> made;
        for (uint32_t i = 0; i < images; ++i)
            made[i] = std::make_unique<OwnedImage>(
                device_, desc.format, desc.extent, desc.usage,
                images == 2 ? name + (i == 0 ? " A" : " B") : name, 1, 0, desc.depth);
        e = Entry{};
        e.desc = desc;
        e.images = std::move(made);
    }
    return e;
}

PersistentStore::~PersistentStore() {
    for (auto& [key, e] : entries_)
        for (VkImageView v : e.views)
            if (v) device_.vk().DestroyImageView(device_.device(), v, device_.allocator());
}

void PersistentStore::retireEntry(Entry& e, uint64_t lastRecorded) {
    if (!e.images[0]) return;
    auto old = std::make_shared<std::array<std::unique_ptr<OwnedImage>, 2>>(std::move(e.images));
    retired_.retire(lastRecorded, [old, views = e.views, &device = device_] {
        for (VkImageView v : views)
            if (v) device.vk().DestroyImageView(device.device(), v, device.allocator());
    });
    e.views = {};
}

void PersistentStore::release(uint64_t unusedBefore, uint64_t lastRecorded) {
    for (auto it = entries_.begin(); it != entries_.end();) {
        if (it->second.lastFrame < unusedBefore) {
            retireEntry(it->second, lastRecorded);
            it = entries_.erase(it);
        } else {
            ++it;
        }
    }
}

uint64_t PersistentStore::imageCount() const {
    uint64_t n = 0;
    for (const auto& [k, e] : entries_) n += (e.images[0] ? 1 : 0) + (e.images[1] ? 1 : 0);
    return n;
}

}  // namespace rg
