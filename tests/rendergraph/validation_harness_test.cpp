// The harness itself: a deliberately missing barrier must be reported, or every "no validation
// message" assertion in the GPU tests would prove nothing.
#include "rendergraph/vk_error.h"
#include "support/gpu_test.h"

using testing_support::GpuTest;

class ValidationHarness : public GpuTest {};

TEST_F(ValidationHarness, MissingBarrierIsReportedAsAHazard) {
    const rg::Device& d = dev();
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = 4096;
    info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkBuffer a, b;
    RG_VK(vkCreateBuffer(d.device(), &info, nullptr, &a));
    RG_VK(vkCreateBuffer(d.device(), &info, nullptr, &b));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(d.device(), a, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size * 2;
    alloc.memoryTypeIndex =
        d.findMemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VkDeviceMemory mem;
    RG_VK(vkAllocateMemory(d.device(), &alloc, nullptr, &mem));
    RG_VK(vkBindBufferMemory(d.device(), a, mem, 0));
    RG_VK(vkBindBufferMemory(d.device(), b, mem, req.size));
    d.submitAndWait([&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, a, 0, VK_WHOLE_SIZE, 7u);
        VkBufferCopy region{0, 0, 4096};
        vkCmdCopyBuffer(cmd, a, b, 1, &region);  // reads what the fill wrote, with no barrier
    });
    vkDestroyBuffer(d.device(), a, nullptr);
    vkDestroyBuffer(d.device(), b, nullptr);
    vkFreeMemory(d.device(), mem, nullptr);
    const auto messages = dev().takeMessages();  // taken here so TearDown sees none
    bool hazard = false;
    for (const auto& m : messages)
        hazard |= m.find("SYNC-HAZARD-READ-AFTER-WRITE") != std::string::npos;
    EXPECT_TRUE(hazard) << "synchronization validation did not report the missing barrier ("
                        << messages.size() << " messages)";
}
