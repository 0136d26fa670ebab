// The composite into the engine's color as it is: each color format an engine may hand over as a
// render target (attachment usage, no STORAGE), which the plugin blends into with a pass of its
// own, against the R16G16B16A16_SFLOAT storage path on the same frame: the same result within the
// format's own precision, after its clamp and rounding. With dual-source blending and without.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "plugin_fixture.h"
#include "rendergraph/format_info.h"
#include "support/gpu_test.h"

namespace plugin_test {
namespace {

using lightscatter::Method;
using lightscatter::Profile;

constexpr VkExtent2D kScreen{48, 32};

constexpr VkFormat kTargets[] = {
    VK_FORMAT_B10G11R11_UFLOAT_PACK32, VK_FORMAT_A2B10G10R10_UNORM_PACK32,
    VK_FORMAT_R16G16B16A16_SFLOAT,     VK_FORMAT_R32G32B32A32_SFLOAT,
    VK_FORMAT_B8G8R8A8_UNORM,          VK_FORMAT_B8G8R8A8_SRGB,
    VK_FORMAT_R8G8B8A8_UNORM,          VK_FORMAT_R8G8B8A8_SRGB};

bool unorm(VkFormat f) {
    return f == VK_FORMAT_A2B10G10R10_UNORM_PACK32 || f == VK_FORMAT_B8G8R8A8_UNORM ||
           f == VK_FORMAT_R8G8B8A8_UNORM;
}
bool srgb(VkFormat f) {
    return f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_R8G8B8A8_SRGB;
}

double srgbToLinear(double e) {
    return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}
double linearToSrgb(double v) {
    return v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

// What the format stores of a linear value v in channel c (0 red, 1 green, 2 blue): its clamp,
// and the distance to the next value it can hold there (its precision at v).
struct Stored {
    double value, step;
};
Stored stored(VkFormat f, int c, double v) {
    if (unorm(f)) {
        const double levels = f == VK_FORMAT_A2B10G10R10_UNORM_PACK32 ? 1023.0 : 255.0;
        v = std::clamp(v, 0.0, 1.0);
        return {v, 1.0 / levels};
    }
    if (srgb(f)) {
        v = std::clamp(v, 0.0, 1.0);
        const double e = linearToSrgb(v);
        return {v, srgbToLinear(std::min(1.0, e + 1.0 / 255.0)) - srgbToLinear(e)};
    }
    const int mantissa = f == VK_FORMAT_B10G11R11_UFLOAT_PACK32 ? (c == 2 ? 5 : 6)
                         : f == VK_FORMAT_R16G16B16A16_SFLOAT   ? 10
                                                                : 23;
    if (f == VK_FORMAT_B10G11R11_UFLOAT_PACK32) v = std::max(v, 0.0);
    // Below the smallest normal value the step stays that of the smallest exponent.
    const double minNormal = f == VK_FORMAT_R32G32B32A32_SFLOAT ? 1.2e-38 : 6.1e-5;
    return {v, std::ldexp(std::max(std::abs(v), minNormal), -mantissa)};
}

// Texels packed as each format packs them, and back: the test's own codec, so that the images are
// filled and read without the device's conversions.
uint32_t toUnorm(double v, double levels) {
    return uint32_t(std::lround(std::clamp(v, 0.0, 1.0) * levels));
}
uint16_t toHalf(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    const uint32_t sign = (bits >> 16) & 0x8000u;
    const float a = std::abs(v);
    if (a < 6.103515625e-05f)  // below the smallest normal: a multiple of 2^-24
        return uint16_t(sign | uint32_t(std::lround(std::ldexp(double(a), 24))));
    int e;
    const double m = std::frexp(double(a), &e);                    // a = m 2^e, m in [0.5, 1)
    uint32_t mantissa = uint32_t(std::lround(std::ldexp(m, 11)));  // 1024..2048
    if (mantissa == 2048) {
        mantissa = 1024;
        ++e;
    }
    return uint16_t(sign | (uint32_t(e + 14) << 10) | (mantissa - 1024));
}
double fromHalf(uint16_t h) {
    const uint32_t e = (h >> 10) & 0x1fu, m = h & 0x3ffu;
    const double v =
        e == 0 ? std::ldexp(double(m), -24) : std::ldexp(double(m | 0x400u), int(e) - 25);
    return (h & 0x8000u) ? -v : v;
}
// An unsigned float of `mantissa` bits and a 5-bit exponent (B10G11R11's channels).
uint32_t toSmallFloat(double v, int mantissa) {
    if (!(v > 0.0)) return 0;
    int e;
    const double m = std::frexp(v, &e);
    if (e - 1 < -14)  // denormal: a multiple of 2^(-14 - mantissa)
        return uint32_t(std::lround(std::ldexp(v, 14 + mantissa)));
    uint32_t q = uint32_t(std::lround(std::ldexp(m, mantissa + 1)));
    if (q == (2u << mantissa)) {
        q >>= 1;
        ++e;
    }
    return (uint32_t(e - 1 + 15) << mantissa) | (q - (1u << mantissa));
}
double fromSmallFloat(uint32_t bits, int mantissa) {
    const uint32_t e = bits >> mantissa, m = bits & ((1u << mantissa) - 1);
    return e == 0 ? std::ldexp(double(m), -14 - mantissa)
                  : std::ldexp(double(m | (1u << mantissa)), int(e) - 15 - mantissa);
}

std::vector<uint8_t> pack(VkFormat f, const std::vector<float>& rgba) {
    const size_t n = rgba.size() / 4, bytes = rg::texelBytes(f);
    std::vector<uint8_t> out(n * bytes);
    for (size_t i = 0; i < n; ++i) {
        const float* p = &rgba[i * 4];
        uint8_t* o = &out[i * bytes];
        uint32_t word = 0;
        switch (f) {
            case VK_FORMAT_R32G32B32A32_SFLOAT:
                std::memcpy(o, p, 16);
                continue;
            case VK_FORMAT_R16G16B16A16_SFLOAT:
                for (int c = 0; c < 4; ++c) {
                    const uint16_t h = toHalf(p[c]);
                    std::memcpy(o + 2 * c, &h, 2);
                }
                continue;
            case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
                word = toSmallFloat(p[0], 6) | (toSmallFloat(p[1], 6) << 11) |
                       (toSmallFloat(p[2], 5) << 22);
                break;
            case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
                word = toUnorm(p[0], 1023) | (toUnorm(p[1], 1023) << 10) |
                       (toUnorm(p[2], 1023) << 20) | (toUnorm(p[3], 3) << 30);
                break;
            default: {  // 8-bit RGBA or BGRA, UNORM or sRGB
                const bool bgra = f == VK_FORMAT_B8G8R8A8_UNORM || f == VK_FORMAT_B8G8R8A8_SRGB;
                for (int c = 0; c < 4; ++c) {
                    const double v =
                        srgb(f) && c < 3 ? linearToSrgb(std::clamp(double(p[c]), 0.0, 1.0)) : p[c];
                    o[bgra && c < 3 ? 2 - c : c] = uint8_t(toUnorm(v, 255));
                }
                continue;
            }
        }
        std::memcpy(o, &word, 4);
    }
    return out;
}

std::vector<float> unpack(VkFormat f, const std::vector<uint8_t>& bytes) {
    const size_t size = rg::texelBytes(f), n = bytes.size() / size;
    std::vector<float> out(n * 4);
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* t = &bytes[i * size];
        float* p = &out[i * 4];
        uint32_t word = 0;
        std::memcpy(&word, t, std::min<size_t>(4, size));
        switch (f) {
            case VK_FORMAT_R32G32B32A32_SFLOAT:
                std::memcpy(p, t, 16);
                break;
            case VK_FORMAT_R16G16B16A16_SFLOAT:
                for (int c = 0; c < 4; ++c) {
                    uint16_t h;
                    std::memcpy(&h, t + 2 * c, 2);
                    p[c] = float(fromHalf(h));
                }
                break;
            case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
                p[0] = float(fromSmallFloat(word & 0x7ffu, 6));
                p[1] = float(fromSmallFloat((word >> 11) & 0x7ffu, 6));
                p[2] = float(fromSmallFloat(word >> 22, 5));
                p[3] = 1.0f;
                break;
            case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
                for (int c = 0; c < 3; ++c) p[c] = float(((word >> (10 * c)) & 0x3ffu) / 1023.0);
                p[3] = float((word >> 30) / 3.0);
                break;
            default: {
                const bool bgra = f == VK_FORMAT_B8G8R8A8_UNORM || f == VK_FORMAT_B8G8R8A8_SRGB;
                for (int c = 0; c < 4; ++c) {
                    const double e = t[bgra && c < 3 ? 2 - c : c] / 255.0;
                    p[c] = float(srgb(f) && c < 3 ? srgbToLinear(e) : e);
                }
            }
        }
    }
    return out;
}

// A gradient from 0.05 to 0.8, different per channel, so that both the multiply by T and the add
// of Lin show in every format.
std::vector<float> background() {
    std::vector<float> b(size_t{kScreen.width} * kScreen.height * 4);
    for (uint32_t y = 0; y < kScreen.height; ++y)
        for (uint32_t x = 0; x < kScreen.width; ++x) {
            float* p = &b[(size_t{y} * kScreen.width + x) * 4];
            const float u = float(x) / float(kScreen.width - 1);
            const float v = float(y) / float(kScreen.height - 1);
            p[0] = 0.05f + 0.75f * u;
            p[1] = 0.05f + 0.75f * v;
            p[2] = 0.05f + 0.375f * (u + v);
            p[3] = 1.0f;
        }
    return b;
}

class CompositeGpu : public PluginGpuTest {
  protected:
    // An image of `format` holding `texels` as the format stores them.
    std::unique_ptr<TestImage> imageOf(VkFormat format, VkImageUsageFlags usage,
                                       VkImageLayout layout, const std::vector<float>& texels) {
        auto image = std::make_unique<TestImage>(dev(), format, kScreen, usage, layout,
                                                 "test color " + rg::formatName(format));
        image->uploadBytes(pack(format, texels));
        return image;
    }
    // What `image` of `format` holds.
    std::vector<float> read(TestImage& image, VkFormat format) {
        return unpack(format, image.downloadBytes());
    }
    // A plugin on the test device told that dualSrcBlend is off: it blends in two draws.
    lightscatter::Plugin& twoDrawPlugin() {
        if (!twoDraws_) {
            withoutDualSource_ = dev().enabledFeatures();
            withoutDualSource_.features.dualSrcBlend = VK_FALSE;
            lightscatter::PluginCreateInfo info;
            info.context = contextOf(dev());
            info.context.enabledFeatures = &withoutDualSource_;
            twoDraws_ = std::make_unique<lightscatter::Plugin>(info);
        }
        return *twoDraws_;
    }

  private:
    VkPhysicalDeviceFeatures2 withoutDualSource_{};
    std::unique_ptr<lightscatter::Plugin> twoDraws_;
};

bool ranPassStartingWith(const lightscatter::FrameReport& r, const std::string& start) {
    return std::any_of(r.passNames.begin(), r.passNames.end(),
                       [&](const std::string& n) { return n.rfind(start, 0) == 0; });
}

// Every format, three methods that composite three ways (epipolar where it unwarps, brute force in
// the composite pass, froxels in their apply), with and without dual-source blending; the frame's
// pre-exposure high enough for the 8-bit and 10-bit formats to clamp some pixels.
TEST_F(CompositeGpu, EveryColorFormatCompositesAsTheStoragePathWithinItsPrecision) {
    ASSERT_TRUE(dev().enabledFeatures().features.dualSrcBlend)
        << "the test device has no dualSrcBlend: only the two-draw path would be tested";
    const std::vector<float> backdrop = background();
    for (const Method method : {Method::Epipolar, Method::BruteForce, Method::Froxels}) {
        TestFrame frame(dev(), sceneWith(spotOverGrille(), kScreen));
        for (const float exposure : {1.0f, 40.0f})
            for (const VkFormat format : kTargets) {
                auto target = imageOf(format, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, backdrop);
                const std::vector<float> before = read(*target, format);
                // The storage path's result from the same stored background.
                auto reference = imageOf(VK_FORMAT_R16G16B16A16_SFLOAT, VK_IMAGE_USAGE_STORAGE_BIT,
                                         VK_IMAGE_LAYOUT_GENERAL, before);
                auto desc = frame.description(method, Profile::Custom, smallSettings(kScreen));
                desc.preExposure = exposure;
                desc.color = reference->input();
                plugin().render(desc);
                const std::vector<float> expected = read(*reference, VK_FORMAT_R16G16B16A16_SFLOAT);
                for (const bool dual : {true, false}) {
                    SCOPED_TRACE(std::string(lightscatter::methodName(method)) + " into " +
                                 rg::formatName(format) + (dual ? ", dual-source" : ", two draws") +
                                 ", pre-exposure " + std::to_string(exposure));
                    if (!dual)
                        target = imageOf(format, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, backdrop);
                    desc.color = target->input();
                    lightscatter::Plugin& p = dual ? plugin() : twoDrawPlugin();
                    const lightscatter::FrameReport r = p.render(desc);
                    EXPECT_TRUE(
                        ranPassStartingWith(r, dual ? "composite into color (dual-source blend)"
                                                    : "composite into color (two blended draws)"));
                    const std::vector<float> got = read(*target, format);
                    size_t worse = 0, changed = 0;
                    double worst = 0;
                    for (size_t i = 0; i < got.size(); ++i) {
                        const int c = int(i % 4);
                        if (c == 3) {
                            EXPECT_EQ(got[i], before[i]) << "alpha changed at texel " << i / 4;
                            continue;
                        }
                        const Stored want = stored(format, c, expected[i]);
                        // The reference is float16, rounded twice (its background as stored,
                        // its result): its own error on top of the format's.
                        const double tolerance =
                            2.0 * want.step + std::ldexp(std::abs(expected[i]), -9);
                        const double error = std::abs(got[i] - want.value);
                        worst = std::max(worst, error / tolerance);
                        if (error > tolerance) ++worse;
                        // Where the composite moved the pixel well beyond the tolerance: an
                        // untouched or black image fails there.
                        if (std::abs(want.value - before[i]) > 4.0 * tolerance) ++changed;
                    }
                    EXPECT_EQ(worse, 0u) << "worst error " << worst << " of the tolerance";
                    EXPECT_GT(changed, got.size() / 8) << "the frame barely changed the color";
                }
            }
    }
}

// A storage color that also takes COLOR_ATTACHMENT: epipolar's unwarp blends into it (dual-source)
// rather than reading and writing it. The same bits as the storage path: the first light's
// extinction and a later light's add, with and without the fix-up, and the same Lin output.
TEST_F(CompositeGpu, TheUnwarpBlendsIntoAStorageColorWithTheSameBits) {
    ASSERT_TRUE(dev().enabledFeatures().features.dualSrcBlend)
        << "the test device has no dualSrcBlend: the unwarp would never blend";
    const std::vector<float> backdrop = background();
    lightscatter::Light second = spotOverGrille();
    second.position = {-1.5f, 5.0f, 0.8f};
    second.direction = {0.25f, -1.0f, -0.1f};
    second.intensity = {15.0f, 25.0f, 40.0f};
    TestFrame a(dev(), sceneWith(spotOverGrille(), kScreen));
    TestFrame b(dev(), sceneWith(second, kScreen));
    for (const VkFormat format : {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT})
        for (const bool fixup : {true, false})
            for (const size_t lights : {size_t{1}, size_t{2}}) {
                SCOPED_TRACE(rg::formatName(format) + (fixup ? ", fix-up, " : ", no fix-up, ") +
                             std::to_string(lights) + " light(s)");
                lightscatter::Settings settings = smallSettings(kScreen);
                settings.epipolar.fixup = fixup;
                auto desc = a.description(Method::Epipolar, Profile::Custom, settings);
                if (lights == 2) {
                    const auto db = b.description(Method::Epipolar, Profile::Custom, settings);
                    desc.lights = {{desc.light, desc.shadowMap, desc.lightColor},
                                   {db.light, db.shadowMap, db.lightColor}};
                    desc.light = {};
                    desc.shadowMap.reset();
                    desc.lightColor.reset();
                }
                std::vector<float> color[2], lin[2];
                std::string reason[2];
                for (const int blend : {0, 1}) {
                    VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT;
                    if (blend != 0) usage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
                    auto target = imageOf(format, usage, VK_IMAGE_LAYOUT_GENERAL, backdrop);
                    desc.color = target->input();
                    reason[blend] = plugin().render(desc).reason;
                    color[blend] = read(*target, format);
                    lin[blend] = a.inscatter();
                }
                const std::string blends = "the color takes dual-source blending";
                EXPECT_EQ(reason[0].find(blends), std::string::npos) << reason[0];
                EXPECT_NE(reason[1].find(blends), std::string::npos) << reason[1];
                ASSERT_EQ(color[0].size(), color[1].size());
                EXPECT_EQ(std::memcmp(color[0].data(), color[1].data(), color[0].size() * 4), 0)
                    << "the blended color differs from the read-modify-written one";
                EXPECT_EQ(lin[0], lin[1]);
                // The frame moved the color: an unwarp that left it alone would pass the above.
                const std::vector<float> before = unpack(format, pack(format, backdrop));
                size_t changed = 0;
                for (size_t i = 0; i < before.size(); ++i)
                    if (i % 4 != 3 && std::abs(color[1][i] - before[i]) > 1e-3f * before[i])
                        ++changed;
                EXPECT_GT(changed, before.size() / 8);
            }
}

// An engine that composites itself: no color, Lin and the transmittance out, from which it makes
// what the plugin would have made (color * T + Lin), checked against the storage path.
TEST_F(CompositeGpu, WithoutAColorTheOutputsComposeTheSameFrame) {
    const std::vector<float> backdrop = background();
    for (const Method method : {Method::Epipolar, Method::Analytic, Method::Froxels}) {
        SCOPED_TRACE(lightscatter::methodName(method));
        FrameSpec spec = sceneWith(spotOverGrille(), kScreen);
        spec.shadowed = method != Method::Analytic;
        TestFrame frame(dev(), spec);
        auto desc = frame.description(method, Profile::Custom, smallSettings(kScreen));
        auto reference = imageOf(VK_FORMAT_R32G32B32A32_SFLOAT, VK_IMAGE_USAGE_STORAGE_BIT,
                                 VK_IMAGE_LAYOUT_GENERAL, backdrop);
        desc.color = reference->input();
        plugin().render(desc);
        const std::vector<float> expected = reference->download(), lin = frame.inscatter();

        TestImage transmittance(dev(), VK_FORMAT_R32G32B32A32_SFLOAT, kScreen,
                                VK_IMAGE_USAGE_STORAGE_BIT, VK_IMAGE_LAYOUT_GENERAL,
                                "test transmittance");
        desc.color = {};
        desc.transmittanceOut = transmittance.input();
        plugin().render(desc);
        const std::vector<float> t = transmittance.download();
        EXPECT_EQ(frame.inscatter(), lin) << "Lin differs without a color";
        double worst = 0, darkest = 1;
        for (size_t i = 0; i < t.size(); ++i) {
            if (i % 4 == 3) {
                EXPECT_EQ(t[i], 1.0f);
                continue;
            }
            darkest = std::min(darkest, double(t[i]));
            const double composed = double(backdrop[i]) * t[i] + lin[i];
            worst = std::max(worst, std::abs(composed - expected[i]) /
                                        std::max(1e-3, std::abs(double(expected[i]))));
        }
        EXPECT_LT(worst, 1e-5);
        EXPECT_LT(darkest, 0.95) << "the fog extinguishes nothing: T of 1 would pass";
    }
}

}  // namespace
}  // namespace plugin_test
