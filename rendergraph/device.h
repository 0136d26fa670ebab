#pragma once
// Vulkan 1.3 device bring-up: instance (optionally with the Khronos validation layer and
// synchronization validation), device choice, one queue, debug-utils naming, and the validation
// messages collected for tests to assert on.
#include <vulkan/vulkan.h>

#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "vulkan_functions.h"

namespace rg {

struct DeviceOptions {
    bool validation = false;     // VK_LAYER_KHRONOS_validation; refused loudly if missing
    bool syncValidation = true;  // with validation: synchronization validation too
    // Case-insensitive substring of the device name. Empty: the LS_DEVICE environment variable,
    // then the first discrete GPU, integrated GPU, virtual GPU, CPU (lavapipe), in that order.
    std::string deviceName;
    bool announce = true;      // print which device was picked to stderr
    bool echoMessages = true;  // print validation messages to stderr as they arrive
    std::vector<std::string> instanceExtensions;  // e.g. the window system's surface extensions
    bool swapchain = false;                       // enable VK_KHR_swapchain on the device
    // Where the runtime's Vulkan entry points come from; null: the Vulkan loader's.
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
    // The host allocator of every object made on the device, the instance and device included.
    const VkAllocationCallbacks* allocator = nullptr;
    // With validation: the layer's own unique handles (its default). Off, it passes the driver's
    // handles through, as engines ship.
    bool uniqueHandles = true;
};

// An engine's own Vulkan objects, wrapped without taking ownership (plugin integration).
struct ExternalDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    // The engine's entry points (null: the Vulkan loader's) and host allocator (null: Vulkan's),
    // used for every call and every object the runtime makes on this device.
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
    const VkAllocationCallbacks* allocator = nullptr;
};

// Every validation message of every Device in this process so far. It outlives the devices, so a
// caller can read what the layer reported while a device and its instance were destroyed (objects
// left alive are reported then), when no Device is left to ask.
size_t validationMessagesInProcess();

class Device {
  public:
    explicit Device(const DeviceOptions& options = {});
    // Wraps an engine's device, which must have the features and extensions this runtime needs
    // (Vulkan 1.3 synchronization2, dynamicRendering, maintenance4; VK_KHR_push_descriptor).
    explicit Device(const ExternalDevice& external);
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    // The entry points every Vulkan call of the runtime goes through.
    const VulkanFunctions& vk() const { return vk_; }
    // The host allocator every object of the runtime is made and destroyed with (null: Vulkan's).
    const VkAllocationCallbacks* allocator() const { return allocator_; }
    VkInstance instance() const { return instance_; }
    // The VkApplicationInfo::apiVersion the instance was created with (VK_API_VERSION_1_3); 0 for
    // an external device, whose instance only its creator knows.
    uint32_t instanceApiVersion() const { return instanceApiVersion_; }
    VkPhysicalDevice physical() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamily() const { return queueFamily_; }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    std::string name() const { return properties_.deviceName; }
    std::string driverName() const { return driverName_; }
    bool isCpu() const { return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
    double timestampPeriodNs() const { return properties_.limits.timestampPeriod; }
    uint32_t timestampValidBits() const { return timestampBits_; }

    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags props) const;
    const VkPhysicalDeviceMemoryProperties& memoryProperties() const { return memory_; }
    VkDeviceSize maxAllocationSize() const {
        return maxAllocation_;
    }  // Vulkan 1.1's limit; 0 unknown

    // The feature chain the device was created with (core -> 1.1 -> 1.2 -> 1.3); all off for an
    // external device, whose features only its creator knows.
    const VkPhysicalDeviceFeatures2& enabledFeatures() const { return enabled_.core; }

    // Debug-utils names and labels; no-ops when the extension is absent.
    void setName(VkObjectType type, uint64_t handle, const std::string& name) const;
    template <typename T>
    void setName(T handle, VkObjectType type, const std::string& name) const {
        setName(type, reinterpret_cast<uint64_t>(handle), name);
    }
    void beginLabel(VkCommandBuffer cmd, const std::string& name) const;
    void endLabel(VkCommandBuffer cmd) const;

    // Submits a recorded command buffer and waits for it: on `fence` (left reset for reuse), or on
    // the queue when there is none.
    void submitAndWait(VkCommandBuffer cmd, VkFence fence = VK_NULL_HANDLE) const;

    // Records with `record` into a one-time command buffer, submits it and waits.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

    // Validation messages (warnings and errors) received since the last call.
    std::vector<std::string> takeMessages();
    size_t messageCount() const;

  private:
    static VKAPI_ATTR VkBool32 VKAPI_CALL
    onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT type,
              const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
    void destroy();
    void loadProperties();
    void createOneShotPool();
    void createInstance(const DeviceOptions& options);
    void pickPhysicalDevice(const DeviceOptions& options);
    void createDevice(const DeviceOptions& options);

    VulkanFunctions vk_;
    const VkAllocationCallbacks* allocator_ = nullptr;
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkCommandPool oneShotPool_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    uint32_t instanceApiVersion_ = 0;
    uint32_t timestampBits_ = 0;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memory_{};
    VkDeviceSize maxAllocation_ = 0;
    struct EnabledFeatures {
        VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        VkPhysicalDeviceVulkan11Features v11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
        VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
        VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    } enabled_;  // Device is neither copied nor moved, so the chain's pointers stay valid
    std::string driverName_;
    bool validation_ = false;
    bool owns_ = true;
    bool debugUtils_ = false;
    bool echo_ = true;
    mutable std::mutex messagesMutex_;
    std::vector<std::string> messages_;
};

}  // namespace rg
