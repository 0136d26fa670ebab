#pragma once
// A test hook for the out-of-memory paths: every Vulkan object creation and memory allocation the
// runtime (and what is built on it) makes is a numbered fault point, and one of them can be made to
// fail as if the driver had returned VK_ERROR_OUT_OF_DEVICE_MEMORY. Tests walk the points in turn
// and check that each failure surfaces as one error, leaks nothing, and that the next attempt
// works.
#include <cstdint>

#include "vk_error.h"

namespace rg {

// Makes the nth fault point from now fail (1: the next one); 0 disarms.
void failNthVulkanCreation(uint64_t n);
// Fault points passed since the process started (tests count a frame's points with it).
uint64_t vulkanCreationCount();

namespace detail {
bool creationFails();  // counts one fault point; true when it is the armed one
// The armed point's failure, as the driver's VK_ERROR_OUT_OF_DEVICE_MEMORY. [[noreturn]], so that
// a compiler sees the handle the skipped call would have made is never read (clang's
// -Wsometimes-uninitialized).
[[noreturn]] inline void injectedFailure(const char* call) {
    check(VK_ERROR_OUT_OF_DEVICE_MEMORY, call);
    throw VulkanError(call);  // not reached: check() throws for any error
}
}  // namespace detail

}  // namespace rg

// RG_VK for calls that create or allocate: the call is not made when the fault point fails.
#define RG_VK_CREATE(call)                                                              \
    (::rg::detail::creationFails() ? ::rg::detail::injectedFailure(#call " [injected]") \
                                   : ::rg::check((call), #call))
