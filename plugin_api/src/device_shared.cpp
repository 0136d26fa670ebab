#include "device_shared.h"

#include "device_features.h"
#include "vulkan_versions.h"

#include <map>
#include <memory>
#include <mutex>
#include <tuple>

namespace lightscatter::detail {
namespace {

// A wrapper of the device of its own, so that it outlives any one plugin.
struct DeviceShared {
    DeviceShared(const rg::ExternalDevice& d, ls::DeviceCapabilities c)
        : device(d), state(device, c) {}
    rg::Device device;
    ls::SharedState state;
};

// Refuses a creation before anything is made from it.
const PluginCreateInfo& checked(const PluginCreateInfo& info) {
    const VulkanContext& c = info.context;
    auto null = [](const char* field) {
        throw InvalidInput(std::string("lightscatter: context.") + field + " is VK_NULL_HANDLE");
    };
    if (info.framesInFlight < 1 || info.framesInFlight > kMaxFramesInFlight)
        throw InvalidInput("lightscatter: framesInFlight is " +
                           std::to_string(info.framesInFlight) + "; it must be 1 to " +
                           std::to_string(kMaxFramesInFlight));
    if (!c.instance) null("instance");
    if (!c.physicalDevice) null("physicalDevice");
    if (!c.device) null("device");
    if (!c.queue) null("queue");
    // Versions first: a device below 1.3 cannot enable what the feature check would ask for.
    checkApiVersions(info);
    checkEnabledFeatures(c.enabledFeatures);
    return info;
}

}  // namespace

rg::ExternalDevice externalDevice(const PluginCreateInfo& info) {
    const VulkanContext& c = checked(info).context;
    return {c.instance,    c.physicalDevice,         c.device,      c.queue,
            c.queueFamily, info.getInstanceProcAddr, info.allocator};
}

ls::Shared sharedFor(const PluginCreateInfo& info) {
    const rg::ExternalDevice d = externalDevice(info);
    const ls::DeviceCapabilities capabilities = enabledCapabilities(*info.context.enabledFeatures);
    using Key = std::tuple<VkDevice, PFN_vkGetInstanceProcAddr, const VkAllocationCallbacks*, bool>;
    static std::mutex mutex;
    static std::map<Key, std::weak_ptr<DeviceShared>> devices;
    std::lock_guard lock(mutex);
    const Key key{d.device, d.getInstanceProcAddr, d.allocator, capabilities.dualSourceBlend};
    std::shared_ptr<DeviceShared> found = devices[key].lock();
    if (!found) {
        found = std::make_shared<DeviceShared>(d, capabilities);
        devices[key] = found;
        // Devices of plugins all gone are forgotten (a handle may be reused for a new device).
        std::erase_if(devices, [](const auto& entry) { return entry.second.expired(); });
    }
    return ls::Shared(found, &found->state);
}

}  // namespace lightscatter::detail
