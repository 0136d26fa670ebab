#include "device_shared.h"

#include <map>
#include <memory>
#include <mutex>
#include <tuple>

namespace lightscatter::detail {
namespace {

// A wrapper of the device of its own, so that it outlives any one plugin.
struct DeviceShared {
    explicit DeviceShared(const rg::ExternalDevice& d) : device(d), state(device) {}
    rg::Device device;
    ls::SharedState state;
};

}  // namespace

ls::Shared sharedFor(const rg::ExternalDevice& d) {
    using Key = std::tuple<VkDevice, PFN_vkGetInstanceProcAddr, const VkAllocationCallbacks*>;
    static std::mutex mutex;
    static std::map<Key, std::weak_ptr<DeviceShared>> devices;
    std::lock_guard lock(mutex);
    const Key key{d.device, d.getInstanceProcAddr, d.allocator};
    std::shared_ptr<DeviceShared> found = devices[key].lock();
    if (!found) {
        found = std::make_shared<DeviceShared>(d);
        devices[key] = found;
        // Devices of plugins all gone are forgotten (a handle may be reused for a new device).
        std::erase_if(devices, [](const auto& entry) { return entry.second.expired(); });
    }
    return ls::Shared(found, &found->state);
}

}  // namespace lightscatter::detail
