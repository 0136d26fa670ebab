#pragma once
// The froxel volumetric fog engines ship (Wronski 2014, Hillaire 2015), as nodes: each light's
// in-scattering injected into a view-frustum grid, one front-to-back integration along the grid's
// columns, and one pass that fetches the integrated grid at each pixel's depth and composites.
#include <vector>

#include "froxel_settings.h"
#include "lightscatter/methods/froxels.h"
#include "shared/chain_context.h"
#include "shared/composite_target.h"
#include "shared/frame_history.h"
#include "shared/scattering_params.h"

namespace ls {

// The grid's size on a screen: columns of `tile` x `tile` pixels (rounded up), `slices` deep.
struct FroxelGrid {
    bool operator==(const FroxelGrid&) const = default;
    uint32_t columns = 0, rows = 0, slices = 0, tile = 0;
    float farDistance = 0.0f;  // FroxelSettings::farDistance
};
FroxelGrid froxelGrid(VkExtent2D screen, const FroxelSettings& settings);
// The grid's settings as the nodes take them, from Settings::froxels.
FroxelSettings froxelSettings(const lightscatter::FroxelsSettings& s);

// The view-axis distances (metres) where the first slice starts, the camera's near plane, and where
// the last one ends: the far distance, or where no ray goes further (the medium's maxDistance, a
// finite far plane).
struct FroxelDepthRange {
    float nearZ = 0.0f, farZ = 0.0f;
};
FroxelDepthRange froxelDepthRange(float nearPlane, float farPlane, bool infiniteFar,
                                  float maxDistance, float farDistance);

// The in-scattering grid's and the integrated grid's formats: float32 for the in-scattering, whose
// per-metre values of a faint light fall under float16's normal range; float16 for the integrated
// Lin (stored at a scale, as the screen Lin is) and transmittance.
inline constexpr VkFormat kFroxelScatteringFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kFroxelIntegratedFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

// The per-pixel history's clock: the frame before's pixels (whose age steps the columns) and the
// frame before's camera and lights. Invalid `pixels`: no per-pixel history, the columns stay.
struct FroxelPixelClock {
    rg::ImageRef pixels;
    rg::HostDataRef<PreviousFrame> previous;
};
// Where the grid's columns are in a frame: `still` when the per-pixel history holds the frame
// before's pixels and neither the camera nor a light changed since; then the whole grid is offset
// by `shift` froxels (froxelGridShift of the history's age), else it stays (0). `stillBefore`: the
// frame before was still too (PreviousFrame::beforeMoved tells).
struct FroxelColumns {
    bool still = false;
    glm::vec2 shift{0.0f};
    bool stillBefore = false;
};
FroxelColumns froxelColumns(const rg::PassContext& ctx, const FroxelPixelClock& clock,
                            const FrameConstants& now);

struct FroxelInjectInputs {
    ChainContext chain;  // the light's constants and values
    LightImages light;   // its shadow map and light color, where it has them
    // The grid the frame's earlier lights wrote, or for the first light (`first`), which writes
    // every froxel, the new grid (froxelScatteringImage()).
    rg::ImageRef scattering;
    bool first = false;
    // The temporal mode's history (the frame before's grid): the jitter's step follows its age;
    // invalid: the froxels' centres.
    rg::ImageRef history;
    // The temporal mode's blue-noise tile (addFroxelBlueNoise), each froxel's own jitter.
    rg::ImageRef noise;
    FroxelPixelClock clock;  // the per-pixel history's: where the columns are this frame
};
// The temporal mode's history of the grid: float32 in-scattering, read and written by compute
// passes, kept read-only between frames.
rg::PersistentImageDesc froxelHistoryDesc(const FroxelGrid& grid);
// The in-scattering grid, declared (kFroxelScatteringFormat, the grid's size) for the first
// light's injection.
rg::ImageRef froxelScatteringImage(rg::RenderGraph& graph, const FroxelGrid& grid);
// In-scattering per froxel (kFroxelScatteringFormat, the grid's size): the light's added to the
// earlier lights'.
rg::ImageRef addFroxelInjection(rg::RenderGraph& graph, const FroxelInjectInputs& in,
                                const FroxelGrid& grid);

// The temporal mode's step of every froxel's jitter in the frame of `index` (the history's age):
// the R3 sequence (Roberts 2018, the golden ratio's generalisation to three dimensions) in
// [0, 1)^3, which each froxel adds to its own offsets from the blue-noise tile, so that its points
// over the frames are a low-discrepancy sequence of its own.
glm::vec3 froxelJitterStep(uint32_t index);

// The per-pixel history's offset of the whole grid in the frame of `index` (the history's age), in
// froxels, in [-0.5, 0.5)^2: the R2 sequence (the plastic number's), from 0 at the first frame, so
// that the columns' rays cover each froxel evenly over the frames.
glm::vec2 froxelGridShift(uint32_t index);
// The per-pixel history: float32 Lin and its weight at each pixel of the screen, read and written
// by the apply.
rg::PersistentImageDesc froxelPixelHistoryDesc(VkExtent2D screen);

struct FroxelTemporalInputs {
    ChainContext chain;                // the first light's: this frame's camera
    rg::ImageRef scattering;           // every light's, injected at this frame's jittered points
    rg::ImageRef history, historyOut;  // the frame before's grid, and this frame's
    rg::HostDataRef<PreviousFrame> previous;
    float weight = 0.9f;  // the history's
    // The per-pixel history's: its still frames keep the grid as the last frame that moved left it
    // (their samples lie on offset columns, which the apply gathers).
    FroxelPixelClock clock;
};
// The blend with the frame before's grid, reprojected and clipped to this frame's neighbourhood
// (temporal.comp), written into historyOut: the grid the integration reads (but for the per-pixel
// history's still frames: FroxelIntegrateInputs::samples) and the exported volume. Returns it.
rg::ImageRef addFroxelTemporalBlend(rg::RenderGraph& graph, const FroxelTemporalInputs& in,
                                    const FroxelGrid& grid);

struct FroxelIntegrateInputs {
    ChainContext chain;  // the first light's: the camera and the medium
    rg::ImageRef scattering;
    // Every light's values: the integrated grid is stored at the smallest of their Lin scales.
    std::vector<rg::HostDataRef<LightFrame>> lights;
    // The per-pixel history's apply: its clock (as FroxelInjectInputs') and this frame's samples,
    // before the temporal blend, which its still frames integrate instead of `scattering` along
    // their offset columns (the apply gathers them per pixel). Invalid: `scattering`, unmoved.
    FroxelPixelClock clock;
    rg::ImageRef samples;
    // The exported volume's own integration (its names), beside the apply's: with the per-pixel
    // history, the grid the blend keeps.
    bool volume = false;
    // Valid: the integration is needed only in this clock's still frames (the kept grid, which the
    // apply reads only there and no volume is exported), and a frame that moved records nothing.
    FroxelPixelClock onlyStill;
};
// Lin and the mean transmittance from the camera to each froxel's far end
// (kFroxelIntegratedFormat, the grid's size).
rg::ImageRef addFroxelIntegration(rg::RenderGraph& graph, const FroxelIntegrateInputs& in,
                                  const FroxelGrid& grid);

struct FroxelApplyInputs {
    ChainContext chain;  // the first light's
    rg::ImageRef integrated;
    std::vector<rg::HostDataRef<LightFrame>> lights;  // as the integration's
    CompositeTarget target;
    // The per-pixel history (apply.comp): its clock (the frame before's pixels) and this frame's
    // pixels; an invalid clock: none, the trilinear fetch alone.
    FroxelPixelClock clock;
    rg::ImageRef pixelsOut;
    // The grid the temporal blend keeps (as the last frame that moved left it), integrated: the
    // pixels hold what they gathered as detail against its fetch.
    rg::ImageRef kept;
};
// The engine's color (and Lin output) with the grid applied at each pixel's depth.
CompositeOutputs addFroxelApply(rg::RenderGraph& graph, const FroxelApplyInputs& in,
                                const FroxelGrid& grid);

struct FroxelExportInputs {
    ChainContext chain;  // the first light's
    rg::ImageRef integrated;
    std::vector<rg::HostDataRef<LightFrame>> lights;  // as the integration's
    rg::ImageRef volumeOut;  // the engine's 3D image (R16G16B16A16_SFLOAT, the grid's size)
};
// The integrated grid in the engine's image: Lin at its true scale in rgb, T in a.
rg::ImageRef addFroxelExport(rg::RenderGraph& graph, const FroxelExportInputs& in,
                             const FroxelGrid& grid);

}  // namespace ls
