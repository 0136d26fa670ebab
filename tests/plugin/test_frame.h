#pragma once
// One frame of a synthetic scene on the test device: depth and shadow map ray-cast on the CPU and
// uploaded, a constant engine color, and an R32G32B32A32 image receiving Lin.
#include <memory>
#include <string_view>
#include <vector>

#include "gpu_images.h"
#include "synthetic_scene.h"

namespace plugin_test {

struct FrameSpec {
    Scene scene = grilleScene();
    View view;
    lightscatter::Light light;
    lightscatter::Medium medium;
    VkExtent2D screen{48, 32};
    float shadowNear = 0.5f, shadowFar = 30.0f;  // spot shadow frustum
    glm::vec3 sceneCenter{0.0f, 1.0f, 0.0f};     // directional shadow box
    float sceneRadius = 12.0f;
    float background = 0.25f;  // the engine's color before compositing
    bool shadowed = true;
    std::vector<float> depthOverride;  // replaces the ray-cast depth when not empty
    bool coloredLight = false;         // stained glass: light-space color texture
    // A square light-color image (cookie) of RGBA float texels, row 0 at the top of the light's
    // view, projected with the light's shadowViewProjection, which is then set for a spot or
    // directional light without a shadow map too. Empty: none (or coloredLight's stripes).
    std::vector<float> cookie;
    bool depthAttachment = true;  // the depth image allows a depth attachment
    std::vector<float> noise;     // 16x16 RGBA noise texels for planes; empty: none
};

class TestFrame {
  public:
    TestFrame(const rg::Device& device, FrameSpec spec);
    lightscatter::FrameDescription description(lightscatter::Method method,
                                               lightscatter::Profile profile,
                                               const lightscatter::Settings& settings) const;
    std::vector<float> inscatter() { return out_->download(); }  // RGBA per pixel
    std::vector<float> color() { return color_->download(); }
    void resetColor();
    // Destroys the engine's color image and makes it again, the same (an engine's resize back to
    // the same size); returns the new handle.
    VkImage recreateColor();
    VkImage colorImage() const { return color_->image(); }
    const FrameSpec& spec() const { return spec_; }
    const lightscatter::Light& light() const { return light_; }

  private:
    const rg::Device& device_;
    FrameSpec spec_;
    lightscatter::Light light_;
    std::unique_ptr<TestImage> depth_, color_, shadow_, out_, lightColor_, noise_;
};

// Default spot light over the grille, and a directional light through it.
lightscatter::Light spotOverGrille();
lightscatter::Light sunThroughGrille();
lightscatter::Medium fog();
// The spot over the grille without a shadow map, 48x32: every ray's Lin is the model's unshadowed
// integral (model_conversion.h's float64Unshadowed).
FrameSpec flatSpot();
View defaultView(VkExtent2D screen);
// The grille scene in fog under `light` (shadowed), seen from the default view.
FrameSpec sceneWith(lightscatter::Light light, VkExtent2D screen = {64, 48});

// Test-sized settings (the profiles are far too large for lavapipe): about one slice per pixel of
// the screen's perimeter and one sample per pixel along the longest line, so that the epipolar
// error measured is the method's, not that of a deliberately sparse sampling.
lightscatter::Settings smallSettings(VkExtent2D screen = {48, 32});

// Relative error statistics of `a` against `b` (RGB of RGBA arrays), over pixels where b matters.
struct ErrorStats {
    double meanRelative = 0;  // mean |a - b| / max(b), per channel, over every pixel
    double maxRelative = 0;   // max |a - b| / max(b)
    double rmsRelative = 0;
    double peak = 0;  // max(b)
    size_t nonFinite = 0;
};
ErrorStats compare(const std::vector<float>& a, const std::vector<float>& b);

// A method's bound on ErrorStats::meanRelative in a test that renders one frame with several.
struct MethodBound {
    lightscatter::Method method;
    double meanRelative;
};

// Whether the frame ran a pass of exactly this name.
bool ranPass(const lightscatter::FrameReport& r, std::string_view name);

}  // namespace plugin_test
