#pragma once
// One validated Vulkan device per test binary (lavapipe unless LS_DEVICE says otherwise), with the
// Khronos validation layer and synchronization validation on. Every GPU test derives from GpuTest:
// any validation message during the test fails it. At the end of the binary, everything built on
// the device is destroyed (atTeardown), then the device itself; a message the layer reports then
// (an object left alive) fails the run.
#include <gtest/gtest.h>

#include <functional>
#include <memory>

#include "rendergraph/device.h"

namespace testing_support {

rg::Device& device();

// Registers what must be destroyed before the shared device (plugins, caches); run in reverse
// order.
void atTeardown(std::function<void()> destroy);

class GpuTest : public ::testing::Test {
  protected:
    void SetUp() override;
    void TearDown() override;
    rg::Device& dev() { return device(); }
};

}  // namespace testing_support
