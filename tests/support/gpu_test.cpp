#include "gpu_test.h"

#include <iostream>
#include <vector>

namespace testing_support {
namespace {

std::unique_ptr<rg::Device> gDevice;
std::vector<std::function<void()>> gTeardown;

// Destroys what the tests built, then the device and its instance, and fails the binary on any
// validation message reported meanwhile: leaked objects are reported at vkDestroyDevice.
class DeviceTeardown : public ::testing::Environment {
  public:
    void TearDown() override {
        if (!gDevice) return;
        for (auto it = gTeardown.rbegin(); it != gTeardown.rend(); ++it) (*it)();
        gTeardown.clear();
        for (const auto& m : gDevice->takeMessages())
            ADD_FAILURE() << "validation at teardown: " << m;
        const size_t before = rg::validationMessagesInProcess();
        gDevice.reset();
        const size_t reported = rg::validationMessagesInProcess() - before;
        EXPECT_EQ(reported, 0u)
            << "the validation layer reported " << reported
            << " message(s) while the device was destroyed (objects left alive)";
    }
};

[[maybe_unused]] ::testing::Environment* const gEnvironment =
    ::testing::AddGlobalTestEnvironment(new DeviceTeardown);

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

void atTeardown(std::function<void()> destroy) {
    gTeardown.push_back(std::move(destroy));
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
