#pragma once
// Images a graph keeps across frames and across graphs (a table filled once and sampled after, a
// frame's history read by the next frame): a pass declares "my persistent image" or "my history"
// (RenderGraph::persistentImage, historyImages) under a key the caller gives each frame as host
// data. The key is opaque here: the caller decides what one stands for (a light of its own, the
// whole frame), and the same name and key find the same image in whatever graph asks for it.
// Frames run on the GPU in the order they are recorded, so each frame finds an image as the frames
// recorded before it left it, however many are in flight.
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "device.h"
#include "owned_image.h"
#include "retire_list.h"
#include "vk_equality.h"

namespace rg {

// The key of a persistent image for one frame (host data, FrameData::set).
struct PersistentKey {
    uint64_t value = 0;
};

// What a persistent image is, and how frames hand it to the next: left in `layout` after uses in
// `stages`; a frame's first use waits for `waitAccess` of the frame before (none for an image
// only read between writes), and its last use is made visible to `handAccess`.
struct PersistentImageDesc {
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{0, 0};
    uint32_t depth = 1;
    VkImageUsageFlags usage = 0;
    VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    VkPipelineStageFlags2 stages =
        VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    VkAccessFlags2 waitAccess = VK_ACCESS_2_NONE;
    VkAccessFlags2 handAccess = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    bool operator==(const PersistentImageDesc&) const = default;
};

// A persistent image's state as the frames recorded before this one left it.
struct PersistentState {
    bool written = false;  // some recorded frame wrote it (else its contents are undefined)
    uint64_t stamp = 0;    // what the last writer said its contents were made from
};

// A history's state for the frame being recorded.
struct HistoryState {
    bool valid = false;  // the previous image holds the frame just before this one's
    uint32_t age = 0;    // consecutive frames before this one that wrote it (0 when not valid)
};

class PersistentStore {
  public:
    // Images it lets go (a new shape, an entry released) are retired into `retired`.
    PersistentStore(const Device& device, RetireList& retired)
        : device_(device), retired_(retired) {}
    // Every frame that used its images must have completed.
    ~PersistentStore();
    PersistentStore(const PersistentStore&) = delete;
    PersistentStore& operator=(const PersistentStore&) = delete;

    // The images of (name, key): one, or two for a history (`images` 2), made here the first time
    // and again when `desc` changes (the old ones retired after frame `lastRecorded`).
    struct Entry {
        PersistentImageDesc desc;
        std::array<std::unique_ptr<OwnedImage>, 2> images;
        // Their views, made by the first executor that binds each (the images are the store's:
        // their identity is known, unlike an engine's handle, so the views outlive frames).
        std::array<VkImageView, 2> views{};
        std::array<bool, 2> written{};
        uint64_t stamp = 0;
        int latest = -1;         // a history's image the last frame that used it wrote
        uint64_t lastFrame = 0;  // the last frame recorded that used the entry
        uint64_t lastWrite = 0;  // the last frame recorded that wrote a history
        uint32_t age = 0;        // a history's run of consecutive frames
    };
    Entry& acquire(const std::string& name, uint64_t key, const PersistentImageDesc& desc,
                   uint32_t images, uint64_t lastRecorded);
    // Releases every entry no frame from `unusedBefore` on used; its images are destroyed once
    // frame `lastRecorded` (the last that may still read them) has completed.
    void release(uint64_t unusedBefore, uint64_t lastRecorded);
    size_t size() const { return entries_.size(); }
    uint64_t imageCount() const;  // the images it holds

  private:
    void retireEntry(Entry& e, uint64_t lastRecorded);

    const Device& device_;
    RetireList& retired_;
    std::map<std::pair<std::string, uint64_t>, Entry> entries_;
};

}  // namespace rg
