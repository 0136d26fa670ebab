#pragma once
// GPU tests of the plugin: one plugin on the validated test device, shared by the tests of a binary
// so pipelines are built once.
#include <optional>

#include <lightscatter/lightscatter.h>
#include "support/gpu_test.h"
#include "test_frame.h"

namespace plugin_test {

// The test device as the engine's context: its handles, enabled features and instance version.
lightscatter::VulkanContext contextOf(const rg::Device& d);

lightscatter::Plugin& plugin();

class PluginGpuTest : public testing_support::GpuTest {
  protected:
    lightscatter::FrameReport run(TestFrame& frame, lightscatter::Method method,
                                  std::optional<lightscatter::Settings> settings = std::nullopt) {
        if (!settings) settings = smallSettings(frame.spec().screen);
        return plugin().render(frame.description(method, lightscatter::Profile::Custom, *settings));
    }
};

}  // namespace plugin_test
