#include "plugin_fixture.h"

#include <memory>

namespace plugin_test {

lightscatter::Plugin& plugin() {
    static std::unique_ptr<lightscatter::Plugin> p;
    if (!p) {
        const rg::Device& d = testing_support::device();
        p = std::make_unique<lightscatter::Plugin>(lightscatter::VulkanContext{
            d.instance(), d.physical(), d.device(), d.queue(), d.queueFamily(),
            &d.enabledFeatures(), d.instanceApiVersion()});
        testing_support::atTeardown([] { p.reset(); });
    }
    return *p;
}

}  // namespace plugin_test
