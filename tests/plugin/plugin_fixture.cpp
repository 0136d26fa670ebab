#include "plugin_fixture.h"

#include <memory>

namespace plugin_test {

lightscatter::VulkanContext contextOf(const rg::Device& d) {
    return {d.instance(),         d.physical(),          d.device(), d.queue(), d.queueFamily(),
            &d.enabledFeatures(), d.instanceApiVersion()};
}

lightscatter::Plugin& plugin() {
    static std::unique_ptr<lightscatter::Plugin> p;
    if (!p) {
        p = std::make_unique<lightscatter::Plugin>(contextOf(testing_support::device()));
        testing_support::atTeardown([] { p.reset(); });
    }
    return *p;
}

}  // namespace plugin_test
