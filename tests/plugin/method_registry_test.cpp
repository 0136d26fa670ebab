// The public Method and the frame graph's registry of methods (passes/registry), both made from
// lightscatter/methods.inc, list the same methods in the same order: a method missing from either
// side, or out of order, fails here.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include <lightscatter/lightscatter.h>
#include "method_units.h"
#include "registry/method_registry.h"

using lightscatter::Method;

TEST(MethodRegistry, ListsTheEnumsMethodsInItsOrder) {
    const auto& units = ls::methodRegistry();
    ASSERT_EQ(units.size(), static_cast<size_t>(Method::Auto)) << "Auto is last and not a unit";
    std::set<std::string> names;
    for (size_t i = 0; i < units.size(); ++i) {
        const auto m = static_cast<Method>(i);
        EXPECT_EQ(lightscatter::detail::methodUnit(m), units[i]);
        EXPECT_STREQ(lightscatter::methodName(m), units[i]->name());
        EXPECT_EQ(lightscatter::parseMethod(units[i]->name()), m);
        names.insert(units[i]->name());
    }
    EXPECT_EQ(names.size(), units.size()) << "two methods share a name";
    EXPECT_EQ(lightscatter::detail::methodUnit(Method::Auto), nullptr);
    EXPECT_STREQ(lightscatter::methodName(Method::Auto), "auto");
    EXPECT_EQ(lightscatter::parseMethod("auto"), Method::Auto);
    EXPECT_EQ(lightscatter::methodNames().size(), units.size() + 1);
}
