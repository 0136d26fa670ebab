#pragma once
// The constants only epipolar's passes read (shaders/epipolar/epipolar_constants.glsl, std140),
// kept out of the frame constants every method reads. The fields are written once, in
// shaders/epipolar/epipolar_constants_fields.h, for this struct and the shaders' uniform block.
// The method keeps a light's constants of the frame being recorded in its LightData
// (EpipolarFrame), which its chain uploads (addUploadEpipolarConstants).
#include <array>
#include <glm/glm.hpp>

#include "lightscatter/methods/epipolar.h"
#include "rendergraph/binding_table.h"
#include "screen_share.h"
#include "shared/chain_context.h"
#include "shared/light_setup.h"
#include "shared/refusals.h"
#include "shared/scattering_params.h"

namespace ls {

struct EpipolarConstants {
#define LS_VEC4 glm::vec4
#include "shaders/epipolar/epipolar_constants_fields.h"
#undef LS_VEC4
};
// Only vec4 members, as frame_constants.h's: std140 packs them as C++ does.
static_assert(sizeof(EpipolarConstants) == 7 * 16, "std140 layout of epipolar_constants.glsl");

// The phases of the march's order (marchTexel in shaders/epipolar/epipolar_constants.glsl): the
// initial step where the samples per line are a multiple of it (the slices are of 4); 1 (each
// sample in its own texel) otherwise.
uint32_t marchPhases(const lightscatter::EpipolarSettings& s);
// How many phase blocks a row of the march's textures holds: 2^ceil(log2(phases) / 2), so that
// the textures stay about as square as the samples'.
uint32_t marchBlocksPerRow(uint32_t phases);
// Whether the first march takes the samples of the march order's tiles (those off the initial
// grid past a line's first phase: marched only where the refinement put them, on both sides of a
// depth break) from a list the refinement compacts, 16 to a tile, rather than where their tiles
// keep them: wherever there are tiles (slices a multiple of 16, two or more samples a phase) and
// no second march follows (the refinement on in-scattering marks samples where the tiles keep
// them). In their tiles a break's samples left most of each 4 x 4 block of fragments idle.
bool marchesFromList(const lightscatter::EpipolarSettings& s, bool inscatterRefinement);

// The light's own block (no cube face) for its settings and shadow map.
// A point or spot light in a non-uniform medium has no closed-form unshadowed Lin per pixel to take
// a shadowed fraction of (the sun's stays exact: E P (1 - T(S)) / betaT whatever the density), so
// its samples carry Lin itself (interpolatesLin). Lin interpolated along an epipolar line smears
// what the fraction kept; and across a fog volume's silhouette, which is not radial from the light
// as a shaft's edges are, neither Lin nor the fraction is smooth (a ray through a lit box takes
// most of its light from the box). A point light's cube map casts shadows across its lines that no
// depth break marks: a cage's bars around a light on screen stripe the floor and the cage's far
// side, which the initial step interpolated over (scenes/hard/point_in_small_cage at 320x180:
// 1.56x brute force's error, 1.36x refined). Such frames (refinesByDefault), where the settings
// do not refine on in-scattering, refine at this threshold: samples are marched rather than
// interpolated where what they carry changes.
inline constexpr float kDefaultInscatterRefinement = 0.1f;
float inscatterRefinementOf(const lightscatter::EpipolarSettings& s, bool refinesByDefault);
// Whether a light's epipolar samples carry Lin whatever the settings say.
inline bool interpolatesLin(const LightSetup& s) {
    return s.medium.nonUniform() && s.light.kind != LightType::Directional;
}
inline bool refinesByDefault(const LightSetup& s) {
    return interpolatesLin(s) || !s.medium.volumes.empty() || cubeShadowed(s);
}

// `s` with the light's own sizes; `bounds`: lineBounds() of its screen rectangle.
EpipolarConstants makeEpipolarConstants(const lightscatter::EpipolarSettings& s,
                                        uint32_t shadowMapSize, bool interpolatesLin,
                                        bool refinesByDefault, const glm::vec4& bounds);

// EpipolarConstants::cubeFaces.x without a cube: every face's bit.
inline constexpr uint32_t kAllCubeFaces = 63;

// A light's epipolar values of one frame (EpipolarMethod::prepare): its constants, and for a cube
// shadow map which faces reach the view (constants.cubeFaces holds them too). The passes that read
// the cube read every face in one dispatch or draw and skip the faces out of view, so a face moving
// into view rebuilds nothing.
struct EpipolarFrame final : LightData {
    EpipolarConstants constants;
    LineSizes sizes;      // the light's slices and samples per slice (screen_share.h)
    LineSizes rectSizes;  // its rectangle's (sizes.slices: the window's of these)
    LineWindow window;    // the slices of the rectangle's border its lines take
    LineSizes full;       // the settings' (the whole screen's)
    VkRect2D rect{};      // the light's screen rectangle
    std::array<bool, 6> faceInView{};
    bool inView(int face) const { return faceInView[face]; }
    uint32_t facesInView() const;  // a bit per face, as EpipolarConstants::cubeFaces.x
};
const EpipolarFrame& epipolarFrameOf(const LightFrame& frame);

// Epipolar's constants as a chain's passes read them.
struct EpipolarContext {
    rg::BufferRef constants;  // uploaded by an earlier pass
};

// A binding table whose first rows are the frame constants and epipolar's (LS_BINDING_FRAME,
// LS_BINDING_EPIPOLAR).
// stages: those that read them (0: the pass's shader; a graphics pass's fragment shader).
rg::BindingTable epipolarTable(rg::PassBuilder& pass, const ChainContext& chain,
                               const EpipolarContext& epipolar, VkPipelineStageFlags2 stages = 0);
// A later light's unwarp and fix-up read both in their wedge's vertex shader too, and the first
// marking and march in the vertex shader of their cover (march_cover.vert), the march list too.
inline constexpr VkPipelineStageFlags2 kVertexAndFragmentStages =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;

}  // namespace ls
