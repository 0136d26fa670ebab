#pragma once
// One validated Vulkan device per test binary (lavapipe unless LS_DEVICE says otherwise), with the
// Khronos validation layer and synchronization validation on. Every GPU test derives from GpuTest:
// any validation message during the test fails it.
#include <gtest/gtest.h>

#include <memory>

#include "rendergraph/device.h"

namespace testing_support {

rg::Device& device();

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;
    rg::Device& dev() { return device(); }
};

}  // namespace testing_support
