// An engine image destroyed and made again that gets the old one's VkImage handle back (issue
// #24): with a pooled host allocator and the validation layer's unique handles off, as engines
// ship, the plugin must render into the new image. A binary of its own: the layer keeps its handle
// wrapping per process, and an instance without unique handles beside one with them (the other
// test binaries' shared device) leaves the layer's state inconsistent (seen as a hang in the next
// test's vkAllocateCommandBuffers on lavapipe).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <vector>

#include "test_frame.h"

namespace plugin_test {
namespace {

using lightscatter::Method;
using lightscatter::Profile;

// A host allocator that hands a freed block back to the next request of its size, as engines'
// pooled allocators do: a driver that places its objects in it gives a new image the handle of
// the image destroyed just before.
class PooledAllocator {
  public:
    PooledAllocator() {
        callbacks_.pUserData = this;
        callbacks_.pfnAllocation = [](void* self, size_t size, size_t alignment,
                                      VkSystemAllocationScope) {
            return static_cast<PooledAllocator*>(self)->allocate(size, alignment);
        };
        callbacks_.pfnReallocation = [](void* self, void* old, size_t size, size_t alignment,
                                        VkSystemAllocationScope) {
            return static_cast<PooledAllocator*>(self)->reallocate(old, size, alignment);
        };
        callbacks_.pfnFree = [](void* self, void* p) {
            static_cast<PooledAllocator*>(self)->free(p);
        };
    }
    ~PooledAllocator() {
        for (auto& [key, blocks] : free_)
            for (void* p : blocks) std::free(p);
    }
    const VkAllocationCallbacks* callbacks() const { return &callbacks_; }

  private:
    using Key = std::pair<size_t, size_t>;  // size, alignment
    void* allocate(size_t size, size_t alignment) {
        std::lock_guard lock(mutex_);
        const Key key{size, alignment};
        auto& blocks = free_[key];
        void* p = nullptr;
        if (!blocks.empty()) {
            p = blocks.back();
            blocks.pop_back();
        } else {
            p = std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
        }
        if (p) live_[p] = key;
        return p;
    }
    void* reallocate(void* old, size_t size, size_t alignment) {
        if (!old) return allocate(size, alignment);
        if (size == 0) {
            free(old);
            return nullptr;
        }
        size_t oldSize = 0;
        {
            std::lock_guard lock(mutex_);
            oldSize = live_.at(old).first;
        }
        void* p = allocate(size, alignment);
        if (p) {
            std::memcpy(p, old, std::min(size, oldSize));
            free(old);
        }
        return p;
    }
    void free(void* p) {
        if (!p) return;
        std::lock_guard lock(mutex_);
        const Key key = live_.at(p);
        live_.erase(p);
        free_[key].push_back(p);
    }
    VkAllocationCallbacks callbacks_{};
    std::mutex mutex_;
    std::map<Key, std::vector<void*>> free_;
    std::map<void*, Key> live_;
};

// The engine's color image destroyed and made again gets the old one's VkImage handle back (a
// pooled allocator, the layer's unique handles off): the plugin renders into the new image, as a
// fresh plugin does, and the layer has nothing to say.
TEST(RecycledHandleGpu, AnImageMadeAgainWithTheSameHandleIsANewImage) {
    PooledAllocator pool;
    rg::DeviceOptions options;
    options.validation = true;
    options.syncValidation = true;
    options.uniqueHandles = false;
    options.allocator = pool.callbacks();
    options.announce = false;
    rg::Device device(options);
    {
        lightscatter::PluginCreateInfo info;
        info.context = {device.instance(),
                        device.physical(),
                        device.device(),
                        device.queue(),
                        device.queueFamily(),
                        &device.enabledFeatures(),
                        device.instanceApiVersion()};
        info.allocator = pool.callbacks();
        lightscatter::Plugin engines(info);
        TestFrame frame(device, sceneWith(spotOverGrille(), {48, 32}));
        const auto settings = smallSettings({48, 32});
        for (const Method method : {Method::Epipolar, Method::BruteForce}) {
            SCOPED_TRACE(lightscatter::methodName(method));
            engines.render(frame.description(method, Profile::Custom, settings));
            const VkImage before = frame.colorImage();
            const VkImage after = frame.recreateColor();
            ASSERT_EQ(before, after) << "the allocator did not give the handle back: the test "
                                        "would not test what it says";
            engines.render(frame.description(method, Profile::Custom, settings));
            const std::vector<float> color = frame.color();
            frame.resetColor();
            lightscatter::Plugin fresh(info);
            fresh.render(frame.description(method, Profile::Custom, settings));
            const std::vector<float> expected = frame.color();
            EXPECT_EQ(color, expected);
            EXPECT_NE(color, std::vector<float>(color.size(), frame.spec().background))
                << "nothing was composited";
        }
    }
    for (const auto& m : device.takeMessages()) ADD_FAILURE() << "validation: " << m;
}

}  // namespace
}  // namespace plugin_test
