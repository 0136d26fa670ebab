// The out-of-memory message says while doing what: the innermost activity, even after the
// exception has unwound it.
#include <gtest/gtest.h>

#include <new>
#include <string>

#include "activity.h"

TEST(HostActivity, TheInnermostActivityOutlivesTheException) {
    EXPECT_STREQ(host::currentActivity(), "");
    try {
        host::Activity outer("running lightscatter render");
        host::Activity inner("loading big.gltf");
        EXPECT_STREQ(host::currentActivity(), "loading big.gltf");
        throw std::bad_alloc();
    } catch (const std::bad_alloc&) {
        EXPECT_STREQ(host::currentActivity(), "loading big.gltf");
    }
    host::Activity next("writing x.png");
    EXPECT_STREQ(host::currentActivity(), "writing x.png");
}
