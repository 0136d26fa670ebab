// The device features the plugin needs: the chain an engine enables them with (or its own
// structures, turned on field by field), the check of what an engine says it enabled (Vulkan has no
// query for a device's enabled features), and the optional ones it uses where they are enabled.
#include <cstddef>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "device_features.h"

namespace lightscatter {
namespace {

// One feature: where Vulkan 1.2/1.3 (or 1.0) keeps it, and the structure of its own that an engine
// may use instead.
struct Need {
    const char* name;
    VkStructureType versioned;
    size_t versionedOffset;
    const char* versionedName;
    VkStructureType own;  // VK_STRUCTURE_TYPE_MAX_ENUM: none
    size_t ownOffset;
    const char* ownName;
    const char* why;
};

constexpr size_t kCoreOffset = offsetof(VkPhysicalDeviceFeatures2, features);

const Need kNeeds[] = {
    {"synchronization2", VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
     offsetof(VkPhysicalDeviceVulkan13Features, synchronization2),
     "VkPhysicalDeviceVulkan13Features",
     VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES,
     offsetof(VkPhysicalDeviceSynchronization2Features, synchronization2),
     "VkPhysicalDeviceSynchronization2Features", "every barrier is a vkCmdPipelineBarrier2"},
    {"dynamicRendering", VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
     offsetof(VkPhysicalDeviceVulkan13Features, dynamicRendering),
     "VkPhysicalDeviceVulkan13Features",
     VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES,
     offsetof(VkPhysicalDeviceDynamicRenderingFeatures, dynamicRendering),
     "VkPhysicalDeviceDynamicRenderingFeatures", "graphics passes use vkCmdBeginRendering"},
    {"maintenance4", VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
     offsetof(VkPhysicalDeviceVulkan13Features, maintenance4), "VkPhysicalDeviceVulkan13Features",
     VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES,
     offsetof(VkPhysicalDeviceMaintenance4Features, maintenance4),
     "VkPhysicalDeviceMaintenance4Features",
     "compute shaders give their workgroup size as LocalSizeId"},
    {"separateDepthStencilLayouts", VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
     offsetof(VkPhysicalDeviceVulkan12Features, separateDepthStencilLayouts),
     "VkPhysicalDeviceVulkan12Features",
     VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SEPARATE_DEPTH_STENCIL_LAYOUTS_FEATURES,
     offsetof(VkPhysicalDeviceSeparateDepthStencilLayoutsFeatures, separateDepthStencilLayouts),
     "VkPhysicalDeviceSeparateDepthStencilLayoutsFeatures",
     "depth and stencil of one texture are in different layouts"},
    {"hostQueryReset", VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
     offsetof(VkPhysicalDeviceVulkan12Features, hostQueryReset), "VkPhysicalDeviceVulkan12Features",
     VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_HOST_QUERY_RESET_FEATURES,
     offsetof(VkPhysicalDeviceHostQueryResetFeatures, hostQueryReset),
     "VkPhysicalDeviceHostQueryResetFeatures", "timestamp queries are reset on the host"},
    {"shaderStorageImageExtendedFormats", VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
     kCoreOffset + offsetof(VkPhysicalDeviceFeatures, shaderStorageImageExtendedFormats),
     "VkPhysicalDeviceFeatures2::features", VK_STRUCTURE_TYPE_MAX_ENUM, 0, nullptr,
     "the min/max trees and the interpolation source are RG16F/RG16UI storage images"},
    {"shaderClipDistance", VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
     kCoreOffset + offsetof(VkPhysicalDeviceFeatures, shaderClipDistance),
     "VkPhysicalDeviceFeatures2::features", VK_STRUCTURE_TYPE_MAX_ENUM, 0, nullptr,
     "the planes method clips its planes to a spot's pyramid with clip distances"},
    {"fragmentStoresAndAtomics", VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
     kCoreOffset + offsetof(VkPhysicalDeviceFeatures, fragmentStoresAndAtomics),
     "VkPhysicalDeviceFeatures2::features", VK_STRUCTURE_TYPE_MAX_ENUM, 0, nullptr,
     "epipolar's unwarp and fix-up composite into the engine's color from fragment shaders"},
};

// Features the plugin asks for where the physical device has them, and uses where the engine
// enabled them; never required. Each is a field of VkPhysicalDeviceFeatures.
struct Optional {
    const char* name;
    size_t offset;
};

const Optional kOptional[] = {
    // The composite's path that blends two sources (with the engine's color) in one draw.
    {"dualSrcBlend", offsetof(VkPhysicalDeviceFeatures, dualSrcBlend)},
};

VkBool32& field(VkPhysicalDeviceFeatures& f, size_t offset) {
    return *reinterpret_cast<VkBool32*>(reinterpret_cast<char*>(&f) + offset);
}

VkBool32 field(const VkPhysicalDeviceFeatures& f, size_t offset) {
    return *reinterpret_cast<const VkBool32*>(reinterpret_cast<const char*>(&f) + offset);
}

template <typename Base>
Base* find(Base* chain, VkStructureType type) {
    for (Base* s = chain; s; s = s->pNext)
        if (s->sType == type) return s;
    return nullptr;
}

// The VkBool32 of `need` in `core` or in a structure of `chain`, or null when the chain holds no
// structure for it.
VkBool32* flag(VkPhysicalDeviceFeatures& core, VkBaseOutStructure* chain, const Need& need) {
    if (need.versioned == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2)
        return &field(core, need.versionedOffset - kCoreOffset);
    if (auto* s = find(chain, need.versioned))
        return reinterpret_cast<VkBool32*>(reinterpret_cast<char*>(s) + need.versionedOffset);
    if (need.own == VK_STRUCTURE_TYPE_MAX_ENUM) return nullptr;
    if (auto* s = find(chain, need.own))
        return reinterpret_cast<VkBool32*>(reinterpret_cast<char*>(s) + need.ownOffset);
    return nullptr;
}

// Whether any structure of `chain` turns `need` on (an engine may list both of its structures).
bool turnedOn(const VkBaseInStructure* chain, const Need& need) {
    for (const VkBaseInStructure* s = chain; s; s = s->pNext) {
        size_t offset = 0;
        if (s->sType == need.versioned)
            offset = need.versionedOffset;
        else if (need.own != VK_STRUCTURE_TYPE_MAX_ENUM && s->sType == need.own)
            offset = need.ownOffset;
        else
            continue;
        if (*reinterpret_cast<const VkBool32*>(reinterpret_cast<const char*>(s) + offset))
            return true;
    }
    return false;
}

std::string holder(const Need& n) {
    return n.ownName ? std::string(n.versionedName) + " or " + n.ownName
                     : std::string(n.versionedName);
}

// Turns on every need in `core` and the structures `pNext` chains, and the optional features
// `has` has (null: none), or throws naming what the chain lacks, changing nothing.
void merge(const char* function, VkPhysicalDeviceFeatures& core, void* pNext,
           const VkPhysicalDeviceFeatures* has) {
    auto* chain = static_cast<VkBaseOutStructure*>(pNext);
    std::vector<VkBool32*> flags;
    std::string missing;
    for (const Need& n : kNeeds) {
        flags.push_back(flag(core, chain, n));
        if (!flags.back())
            missing += (missing.empty() ? "" : "; ") + holder(n) + " (for " + n.name + ")";
    }
    if (!missing.empty())
        throw InvalidInput(std::string("lightscatter: ") + function + ": the chain holds no " +
                           missing +
                           "; add it to the chain, or start from "
                           "lightscatter::requiredDeviceFeatures()");
    for (VkBool32* f : flags) *f = VK_TRUE;
    if (has) detail::addOptionalFeatures(core, *has);
}

}  // namespace

DeviceFeatures requiredDeviceFeatures() {
    DeviceFeatures f;
    f.chain();
    enableRequiredDeviceFeatures(f.core);
    return f;
}

void enableRequiredDeviceFeatures(VkPhysicalDeviceFeatures2& features) {
    if (features.sType != VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2)
        throw InvalidInput(
            "lightscatter: enableRequiredDeviceFeatures: features.sType is not "
            "VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2");
    merge("enableRequiredDeviceFeatures", features.features, features.pNext, nullptr);
}

void mergeRequiredDeviceFeatures(VkPhysicalDeviceFeatures& core, void* pNext) {
    merge("mergeRequiredDeviceFeatures", core, pNext, nullptr);
}

namespace detail {

void mergeWithOptional(VkPhysicalDeviceFeatures& core, void* pNext,
                       const VkPhysicalDeviceFeatures& has) {
    merge("mergeRequiredDeviceFeatures", core, pNext, &has);
}

void addOptionalFeatures(VkPhysicalDeviceFeatures& core, const VkPhysicalDeviceFeatures& has) {
    for (const Optional& o : kOptional)
        if (field(has, o.offset)) field(core, o.offset) = VK_TRUE;
}

std::vector<std::string> featuresOff(const VkPhysicalDeviceFeatures2& chain, bool coreOnly) {
    std::vector<std::string> off;
    for (const Need& n : kNeeds) {
        if (coreOnly && n.versioned != VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2) continue;
        if (!turnedOn(reinterpret_cast<const VkBaseInStructure*>(&chain), n)) off.push_back(n.name);
    }
    return off;
}

ls::DeviceCapabilities enabledCapabilities(const VkPhysicalDeviceFeatures2& enabled) {
    ls::DeviceCapabilities c;
    c.dualSourceBlend = enabled.features.dualSrcBlend == VK_TRUE;
    return c;
}

void checkEnabledFeatures(const VkPhysicalDeviceFeatures2* enabled) {
    if (!enabled)
        throw InvalidInput(
            "lightscatter: context.enabledFeatures is null: pass the feature chain the "
            "device was created with (VkDeviceCreateInfo::pNext; "
            "lightscatter::requiredDeviceFeatures() makes one)");
    if (enabled->sType != VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2)
        throw InvalidInput(
            "lightscatter: context.enabledFeatures does not start with a "
            "VkPhysicalDeviceFeatures2 (sType VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2)");
    const auto* chain = reinterpret_cast<const VkBaseInStructure*>(enabled);
    std::string missing;
    for (const Need& n : kNeeds) {
        if (turnedOn(chain, n)) continue;
        missing += std::string(missing.empty() ? "" : "; ") + n.name + " (" + holder(n) + ": " +
                   n.why + ")";
    }
    if (!missing.empty())
        throw InvalidInput(
            "lightscatter: context.enabledFeatures: the device was created without " + missing +
            "; enable them at vkCreateDevice (lightscatter::requiredDeviceFeatures or "
            "enableRequiredDeviceFeatures)");
}

}  // namespace detail
}  // namespace lightscatter
