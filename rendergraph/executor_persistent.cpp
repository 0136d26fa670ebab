// The executor's part in persistent images and histories (persistent_store.h): which of the
// store's images each declaration stands for this frame, and what the frame leaves in them.
#include "executor.h"
#include "vk_error.h"

namespace rg {

void GraphExecutor::bindPersistent(const FrameData& data, uint64_t frame) {
    bound_.assign(graph_.resources().size(), Bound{});
    for (uint32_t id = 0; id < graph_.resources().size(); ++id) {
        ResourceDecl& r = graph_.resources()[id];
        if (!r.persistent) continue;
        const ResourceDecl::Persistent& p = *r.persistent;
        if (!store_)
            throw VulkanError("persistent image '" + r.name +
                              "': the executor was made without a PersistentStore");
        const PersistentKey* key = data.find(p.key);
        if (!key)
            throw VulkanError("persistent image '" + r.name +
                              "': this frame gave no key for it (FrameData::set)");
        Bound& b = bound_[id];
        b.entry = &store_->acquire(p.storeName, key->value, p.desc, p.role == 0 ? 1 : 2, frame - 1);
        PersistentStore::Entry& e = *b.entry;
        if (p.role != 0) {
            // The image the frame before wrote is read; the other is written.
            const uint32_t read = e.latest >= 0 ? static_cast<uint32_t>(e.latest) : 0;
            b.image = p.role == 1 ? read : read ^ 1u;
            b.history.valid =
                e.latest >= 0 && e.lastWrite + 1 == frame && !data.discardsHistories();
            b.history.age = b.history.valid ? e.age : 0;
        }
        r.importedImage.image = e.images[b.image]->image();
        // An image no frame wrote holds nothing: the graph's first use transitions it.
        r.importedImage.initialLayout =
            e.written[b.image] ? r.declaredLayout : VK_IMAGE_LAYOUT_UNDEFINED;
    }
}

void GraphExecutor::commitPersistent(uint64_t frame) {
    lastFilled_.clear();
    for (uint32_t id = 0; id < bound_.size(); ++id) {
        Bound& b = bound_[id];
        if (!b.entry) continue;
        PersistentStore::Entry& e = *b.entry;
        const uint8_t role = graph_.resource(id).persistent->role;
        e.lastFrame = frame;
        if (role == 0 && b.wrote) {
            e.written[0] = true;
            e.stamp = b.stamp;
            lastFilled_.push_back(b.writer);
        } else if (role == 2) {
            e.written[b.image] = true;
            e.latest = static_cast<int>(b.image);
            e.lastWrite = frame;
            e.age = b.history.age + 1;
        }
    }
    bound_.clear();
}

GraphExecutor::Bound& GraphExecutor::bound(ImageRef ref, const char* asking) {
    if (ref.graph != graph_.id() || ref.id >= bound_.size() || !bound_[ref.id].entry)
        throw VulkanError(std::string(asking) +
                          ": the image is not one of the graph's persistent "
                          "images, or no frame is being recorded");
    return bound_[ref.id];
}

PersistentState PassContext::persistent(ImageRef ref) const {
    const GraphExecutor::Bound& b = executor_.bound(ref, "PassContext::persistent");
    return {b.entry->written[b.image], b.entry->stamp};
}

void PassContext::wrote(ImageRef ref, uint64_t stamp) {
    GraphExecutor::Bound& b = executor_.bound(ref, "PassContext::wrote");
    b.wrote = true;
    b.stamp = stamp;
    b.writer = passName();
}

HistoryState PassContext::history(ImageRef ref) const {
    return executor_.bound(ref, "PassContext::history").history;
}

}  // namespace rg
