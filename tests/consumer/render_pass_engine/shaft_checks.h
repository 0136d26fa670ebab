#pragma once
// The test's checks of the plugin build's last frame against the build without the plugin (its
// PPM): shafts came out where the beam is, the UI drawn after the plugin is untouched, and outside
// the beam the scene is darkened by the haze's extinction only, as little as it should be. Not part
// of the integration: the engine calls it from one line.
#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>

namespace shaft_checks {

inline float toLinear(uint8_t v) {
    const float c = float(v) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline float toSrgbByte(float linear) {
    const float c =
        linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return std::clamp(c, 0.0f, 1.0f) * 255.0f;
}

// A binary PPM (P6) of `extent`, as the engine writes it: RGB bytes.
inline std::vector<uint8_t> readPpm(const std::string& path, VkExtent2D extent) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    uint32_t width = 0, height = 0, maxValue = 0;
    in >> magic >> width >> height >> maxValue;
    in.get();
    std::vector<uint8_t> rgb(size_t{extent.width} * extent.height * 3);
    if (!in || magic != "P6" || width != extent.width || height != extent.height ||
        maxValue != 255 ||
        !in.read(reinterpret_cast<char*>(rgb.data()), std::streamsize(rgb.size())))
        return {};
    return rgb;
}

// `bgra`: the plugin build's last frame of `frame` (B8G8R8A8_SRGB bytes). Returns the number of
// failed checks.
inline int compare(const uint8_t* bgra, const std::string& baselinePath,
                   const lightscatter::FrameDescription& frame) {
    const VkExtent2D extent = frame.depth.extent;
    const auto projection = std::bit_cast<glm::mat4>(frame.camera.projection);
    const glm::mat4 viewProjection = projection * std::bit_cast<glm::mat4>(frame.camera.view);
    const auto lightPosition = std::bit_cast<glm::vec3>(frame.light.position);
    const auto lightDirection = glm::normalize(std::bit_cast<glm::vec3>(frame.light.direction));
    const lightscatter::Medium& medium = frame.medium;
    // The far plane of a [0, 1] depth perspective: m[3][2] / (m[2][2] + 1).
    const float farPlane = projection[3][2] / (projection[2][2] + 1.0f);
    int failures = 0;
    auto fail = [&](const std::string& what) {
        std::fprintf(stderr, "FAILED: %s\n", what.c_str());
        ++failures;
    };
    const std::vector<uint8_t> baseline = readPpm(baselinePath, extent);
    if (baseline.empty()) {
        fail("no baseline image (--baseline " + baselinePath + "): the build without the plugin " +
             "writes it");
        return failures;
    }
    // Channel c of pixel (x, y), as bytes: the plugin's build and the baseline.
    auto shafts = [&](uint32_t x, uint32_t y, int c) {
        return int(bgra[4 * (size_t{y} * extent.width + x) + size_t(2 - c)]);
    };
    auto base = [&](uint32_t x, uint32_t y, int c) {
        return int(baseline[3 * (size_t{y} * extent.width + x) + size_t(c)]);
    };

    // Shafts: points on the spot's axis, 2 to 3.5 m below the light (above the grille), seen in
    // front of the back wall, each gained more than a few 8-bit steps (about 35 to 65 here; shafts
    // mirrored by a projection with y up gain 2 to 10 there).
    int probes = 0;
    for (float t : {2.0f, 2.5f, 3.0f, 3.5f}) {
        const glm::vec4 clip = viewProjection * glm::vec4(lightPosition + t * lightDirection, 1.0f);
        const float px = (clip.x / clip.w * 0.5f + 0.5f) * float(extent.width);
        const float py = (clip.y / clip.w * 0.5f + 0.5f) * float(extent.height);
        if (px < 0 || py < 0 || px >= float(extent.width) || py >= float(extent.height)) continue;
        const auto x = uint32_t(px), y = uint32_t(py);
        int gain = -255;
        for (int c = 0; c < 3; ++c) gain = std::max(gain, shafts(x, y, c) - base(x, y, c));
        std::printf("beam at (%u, %u), %.1f m from the light: %+d steps\n", x, y, double(t), gain);
        ++probes;
        if (gain <= 12)
            fail("no shaft where the beam is, " + std::to_string(t) + " m from the light: " +
                 std::to_string(gain) + " 8-bit steps gained (more than 12 expected)");
    }
    if (probes != 4) fail("the beam's points are off the screen");

    // The UI panel (shaders/ui.vert: x 8..88, y 9..31 at 320x180), drawn after the plugin, is
    // exactly the baseline's.
    int uiDiffers = 0;
    for (uint32_t y = 11; y < 30; ++y)
        for (uint32_t x = 10; x < 86; ++x)
            for (int c = 0; c < 3; ++c) uiDiffers += shafts(x, y, c) != base(x, y, c);
    if (uiDiffers) fail("the UI panel differs from the baseline's: the fog covered the UI");

    // Extinction: wherever the plugin's build is darker than the baseline (outside the beam), by
    // at most the transmittance over the farthest distance, exp(-betaT far) (one 8-bit step of
    // rounding allowed), and on average only slightly.
    float betaT = 0.0f;
    for (int c = 0; c < 3; ++c)
        betaT = std::max(betaT, medium.betaR[c] + medium.betaM[c] + medium.sigmaA[c]);
    const float minTransmittance = std::exp(-betaT * farPlane);
    double ratioSum = 0.0;
    int darkened = 0, tooDark = 0, brightened = 0;
    float minRatio = 1.0f;
    for (uint32_t y = 0; y < extent.height; ++y)
        for (uint32_t x = 0; x < extent.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const int s = shafts(x, y, c), b = base(x, y, c);
                if (s > b) ++brightened;
                if (s >= b || b < 40) continue;  // dark pixels: 8 bits say too little
                const float ratio = toLinear(uint8_t(s)) / toLinear(uint8_t(b));
                ratioSum += ratio;
                ++darkened;
                minRatio = std::min(minRatio, ratio);
                if (float(s) < toSrgbByte(toLinear(uint8_t(b)) * minTransmittance) - 1.0f)
                    ++tooDark;
            }
    const double meanRatio = darkened ? ratioSum / darkened : 1.0;
    std::printf(
        "%d channel values brighter, %d darker (mean %.3f, least %.3f of the baseline; "
        "exp(-betaT far) = %.3f)\n",
        brightened, darkened, meanRatio, double(minRatio), double(minTransmittance));
    if (tooDark)
        fail(std::to_string(tooDark) + " channel values darker than the extinction allows");
    if (meanRatio < 0.85)
        fail("the scene outside the beam lost " + std::to_string(100.0 * (1.0 - meanRatio)) +
             "% on average: more than a light haze's extinction");
    return failures;
}

}  // namespace shaft_checks
