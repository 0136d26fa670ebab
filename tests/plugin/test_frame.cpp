#include "test_frame.h"

#include <algorithm>
#include <cmath>

namespace plugin_test {

TestFrame::TestFrame(const rg::Device& device, FrameSpec spec)
    : device_(device), spec_(std::move(spec)) {
    light_ = spec_.light;
    const VkExtent2D s = spec_.screen;
    const VkImageUsageFlags depthUsage =
        VK_IMAGE_USAGE_SAMPLED_BIT |
        (spec_.depthAttachment ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : 0);
    depth_ = std::make_unique<TestImage>(device, VK_FORMAT_D32_SFLOAT, s, depthUsage,
                                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "test depth");
    if (!spec_.noise.empty()) {
        noise_ = std::make_unique<TestImage>(
            device, VK_FORMAT_R32G32B32A32_SFLOAT, VkExtent2D{16, 16}, VK_IMAGE_USAGE_SAMPLED_BIT,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "test noise");
        noise_->upload(spec_.noise);
    }
    depth_->upload(spec_.depthOverride.empty()
                       ? renderDepth(spec_.scene, spec_.view, s.width, s.height)
                       : spec_.depthOverride);
    color_ = std::make_unique<TestImage>(device, VK_FORMAT_R32G32B32A32_SFLOAT, s,
                                         VK_IMAGE_USAGE_STORAGE_BIT, VK_IMAGE_LAYOUT_GENERAL,
                                         "test color");
    resetColor();
    out_ = std::make_unique<TestImage>(device, VK_FORMAT_R32G32B32A32_SFLOAT, s,
                                       VK_IMAGE_USAGE_STORAGE_BIT, VK_IMAGE_LAYOUT_GENERAL,
                                       "test in-scattering");
    const bool projected =
        light_.type != lightscatter::LightType::Point && (spec_.shadowed || !spec_.cookie.empty());
    const glm::mat4 m = !projected ? glm::mat4(1.0f)
                        : light_.type == lightscatter::LightType::Spot
                            ? spotShadowMatrix(light_, spec_.shadowNear, spec_.shadowFar)
                            : directionalShadowMatrix(
                                  {light_.direction[0], light_.direction[1], light_.direction[2]},
                                  spec_.sceneCenter, spec_.sceneRadius);
    if (projected) light_.shadowViewProjection = toMat4(m);
    if (!spec_.cookie.empty()) {
        const auto c = static_cast<uint32_t>(
            std::lround(std::sqrt(static_cast<double>(spec_.cookie.size()) / 4.0)));
        lightColor_ = std::make_unique<TestImage>(
            device, VK_FORMAT_R32G32B32A32_SFLOAT, VkExtent2D{c, c}, VK_IMAGE_USAGE_SAMPLED_BIT,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "test cookie");
        lightColor_->upload(spec_.cookie);
    }
    if (spec_.shadowed && light_.type != lightscatter::LightType::Point) {
        if (light_.shadowMapSize == 0) light_.shadowMapSize = 128;
        const uint32_t n = light_.shadowMapSize;
        shadow_ = std::make_unique<TestImage>(
            device, VK_FORMAT_D32_SFLOAT, VkExtent2D{n, n}, VK_IMAGE_USAGE_SAMPLED_BIT,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "test shadow map");
        shadow_->upload(renderShadowMap(spec_.scene, m, n, light_.shadowReversedZ));
        if (spec_.coloredLight && spec_.cookie.empty()) {
            // Stripes of red, green and blue glass across the light's view.
            const uint32_t c = 32;
            lightColor_ = std::make_unique<TestImage>(
                device, VK_FORMAT_R32G32B32A32_SFLOAT, VkExtent2D{c, c}, VK_IMAGE_USAGE_SAMPLED_BIT,
                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "test light color");
            std::vector<float> texels(size_t{c} * c * 4, 1.0f);
            for (uint32_t y = 0; y < c; ++y)
                for (uint32_t x = 0; x < c; ++x) {
                    float* t = &texels[(size_t{y} * c + x) * 4];
                    const uint32_t band = (x / 8) % 3;
                    for (uint32_t k = 0; k < 3; ++k) t[k] = k == band ? 1.0f : 0.15f;
                }
            lightColor_->upload(texels);
        }
    } else {
        light_.shadowMapSize = 0;
    }
}

VkImage TestFrame::recreateColor() {
    color_.reset();
    color_ = std::make_unique<TestImage>(device_, VK_FORMAT_R32G32B32A32_SFLOAT, spec_.screen,
                                         VK_IMAGE_USAGE_STORAGE_BIT, VK_IMAGE_LAYOUT_GENERAL,
                                         "test color");
    resetColor();
    return color_->image();
}

void TestFrame::resetColor() {
    std::vector<float> c(size_t{spec_.screen.width} * spec_.screen.height * 4, spec_.background);
    color_->upload(c);
}

lightscatter::FrameDescription TestFrame::description(
    lightscatter::Method method, lightscatter::Profile profile,
    const lightscatter::Settings& settings) const {
    lightscatter::FrameDescription f;
    f.depth = depth_->input();
    f.color = color_->input();
    f.inscatterOut = out_->input();
    if (shadow_) f.shadowMap = shadow_->input();
    if (lightColor_) f.lightColor = lightColor_->input();
    if (noise_) f.noise = noise_->input();
    f.camera = spec_.view.camera();
    f.light = light_;
    f.medium = spec_.medium;
    f.method = method;
    f.profile = profile;
    f.custom = settings;
    return f;
}

FrameSpec sceneWith(lightscatter::Light light, VkExtent2D screen) {
    FrameSpec s;
    s.screen = screen;
    s.view = defaultView(s.screen);
    s.light = light;
    s.medium = fog();
    return s;
}

FrameSpec flatSpot() {
    FrameSpec s = sceneWith(spotOverGrille(), {48, 32});
    s.shadowed = false;
    return s;
}

lightscatter::Light spotOverGrille() {
    lightscatter::Light l;
    l.type = lightscatter::LightType::Spot;
    l.position = {0.3f, 6.0f, 0.2f};
    l.direction = {0.0f, -1.0f, 0.0f};
    l.intensity = {40.0f, 38.0f, 35.0f};
    l.innerConeAngleDegrees = l.outerConeAngleDegrees = 30.0f;
    l.range = 20.0f;
    l.shadowMapSize = 128;
    return l;
}

lightscatter::Light sunThroughGrille() {
    lightscatter::Light l;
    l.type = lightscatter::LightType::Directional;
    l.direction = {0.35f, -1.0f, -0.25f};
    l.intensity = {3.0f, 3.0f, 2.8f};
    l.shadowMapSize = 128;
    return l;
}

lightscatter::Medium fog() {
    lightscatter::Medium m;
    m.betaR = {0.002f, 0.004f, 0.008f};
    m.betaM = {0.03f, 0.03f, 0.03f};
    m.g = 0.6f;
    m.maxDistance = 60.0f;
    return m;
}

View defaultView(VkExtent2D screen) {
    return lookAt({0.0f, 2.5f, 9.0f}, {0.0f, 1.5f, 0.0f}, 60.0f,
                  static_cast<float>(screen.width) / static_cast<float>(screen.height), 0.1f,
                  50.0f);
}

lightscatter::Settings smallSettings(VkExtent2D screen) {
    lightscatter::Settings s;
    s.epipolar.slices = (2 * (screen.width + screen.height) + 3) / 4 * 4;
    s.epipolar.samplesPerSlice =
        std::max(std::max(screen.width, screen.height) + screen.height / 2, 16u);
    s.epipolar.initialSampleStep = 8;
    s.shadowMapSize = 128;
    return s;
}

ErrorStats compare(const std::vector<float>& a, const std::vector<float>& b) {
    ErrorStats e;
    for (size_t i = 0; i < b.size(); ++i)
        if (i % 4 != 3) e.peak = std::max(e.peak, static_cast<double>(std::fabs(b[i])));
    const double scale = e.peak > 0 ? e.peak : 1.0;
    size_t n = 0;
    double sum = 0, sum2 = 0;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
        if (i % 4 == 3) continue;
        if (!std::isfinite(a[i])) {
            ++e.nonFinite;
            continue;
        }
        const double d = std::fabs(static_cast<double>(a[i]) - b[i]) / scale;
        sum += d;
        sum2 += d * d;
        e.maxRelative = std::max(e.maxRelative, d);
        ++n;
    }
    if (n) {
        e.meanRelative = sum / static_cast<double>(n);
        e.rmsRelative = std::sqrt(sum2 / static_cast<double>(n));
    }
    return e;
}

bool ranPass(const lightscatter::FrameReport& r, std::string_view name) {
    return std::find(r.passNames.begin(), r.passNames.end(), name) != r.passNames.end();
}

}  // namespace plugin_test
