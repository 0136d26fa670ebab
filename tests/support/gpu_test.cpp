#include "gpu_test.h"

#include <iostream>

namespace testing_support {
namespace {

std::unique_ptr<rg::Device> gDevice;

}  // namespace

rg::Device& device() {
    if (!gDevice) {
        rg::DeviceOptions options;
        options.validation = true;
        options.syncValidation = true;
        options.echoMessages = true;
        gDevice = std::make_unique<rg::Device>(options);
    }
    return *gDevice;
}

void GpuTest::SetUp() {
    // Messages left over from outside a test (device creation) count against the first test.
    (void)device();
}

void GpuTest::TearDown() {
    const auto messages = device().takeMessages();
    for (const auto& m : messages) ADD_FAILURE() << "validation: " << m;
}

}  // namespace testing_support
