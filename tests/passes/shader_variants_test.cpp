// No GPU: each build of a shader a node asks for is built, and each build is one a node asks for
// (the builds are listed once, in shaders/CMakeLists.txt; the nodes ask by defines).
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "apply_comp_variants.h"
#include "beam_tree_hybrid/beam_tree_shaders.h"
#include "composite_apply_comp_variants.h"
#include "composite_blend_frag_variants.h"
#include "composite_comp_variants.h"
#include "cone_march/cone_march_shader.h"
#include "cone_march_frag_variants.h"
#include "epipolar/epipolar_shaders.h"
#include "froxels/froxel_shaders.h"
#include "inject_comp_variants.h"
#include "integrate_comp_variants.h"
#include "min_max_trees_comp_variants.h"
#include "pixel_march_frag_variants.h"
#include "planes/plane_shaders.h"
#include "planes_frag_variants.h"
#include "ray_march_frag_variants.h"
#include "shared/shared_shaders.h"
#include "slice_uv_frame_comp_variants.h"
#include "transmittance_export_comp_variants.h"
#include "unshadowed_frag_variants.h"
#include "unwarp_frag_variants.h"

namespace ls {
namespace {

using Reached = std::set<const uint32_t*>;

void reach(Reached& reached, const rg::ShaderCode& code) {
    ASSERT_NE(code.words, nullptr);
    ASSERT_GT(code.bytes, 0u);
    reached.insert(code.words);
}

// Every build of the source is one the nodes asked for.
void expectAllReached(const ls_spirv::ShaderVariants& shader, const Reached& reached) {
    for (const ls_spirv::Variant& v : shader.variants())
        EXPECT_TRUE(reached.count(v.words.data()))
            << shader.source() << "'s build \"" << v.name << "\" is built but no node asks for it";
}

// The lights a spec can describe: a cube map only for a point light.
template <typename F>
void forEachSpec(F&& f) {
    for (LightType light : {LightType::Directional, LightType::Spot, LightType::Point})
        for (bool color : {false, true})
            for (bool cube : {false, true}) {
                if (cube && light != LightType::Point) continue;
                ScatterSpec spec;
                spec.light = light;
                spec.lightColor = color;
                spec.cubeShadow = cube;
                f(spec);
            }
}

// Every target a compositing shader may write (cmake/CompositeTargets.cmake).
template <typename F>
void forEachTarget(F&& f) {
    for (VkFormat color : {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT})
        for (bool out : {false, true})
            for (bool split : {false, true}) f(CompositeVariant{color, out, split});
}

TEST(ShaderVariants, EpipolarNodesAskForBuiltVariants) {
    Reached rayMarch, pixelMarch, unwarp, minMax, uvFrame;
    forEachSpec([&](const ScatterSpec& spec) {
        for (bool trees : {false, true})
            for (bool count : {false, true}) reach(rayMarch, rayMarchShader(spec, trees, count));
        reach(pixelMarch, pixelMarchShader(spec));
        // An unshadowed light marched for its light color (no cube map: it has no shadow map).
        if (spec.lightColor && !spec.cubeShadow) reach(pixelMarch, pixelMarchShader(spec, false));
        forEachTarget([&](const CompositeVariant& t) { reach(pixelMarch, fixupShader(spec, t)); });
    });
    for (bool table : {false, true})
        forEachTarget([&](const CompositeVariant& t) {
            for (bool blend : {false, true})
                if (!(blend && t.split)) reach(unwarp, unwarpShader(table, t, blend));
        });
    for (bool cube : {false, true}) {
        reach(minMax, minMaxTreesShader(cube));
        reach(uvFrame, sliceUvFrameShader(cube));
    }
    expectAllReached(ls_spirv::ray_march_frag_variants, rayMarch);
    expectAllReached(ls_spirv::pixel_march_frag_variants, pixelMarch);
    expectAllReached(ls_spirv::unwarp_frag_variants, unwarp);
    expectAllReached(ls_spirv::min_max_trees_comp_variants, minMax);
    expectAllReached(ls_spirv::slice_uv_frame_comp_variants, uvFrame);
}

TEST(ShaderVariants, ScreenLinNodesAskForBuiltVariants) {
    Reached composite, unshadowed, coneMarch, planes;
    for (bool addOnly : {false, true})
        for (bool lin : {false, true})
            forEachTarget([&](const CompositeVariant& t) {
                reach(composite, compositeShader(addOnly, lin, t));
            });
    forEachSpec([&](const ScatterSpec& spec) { reach(unshadowed, unshadowedShader(spec)); });
    for (bool shadow : {false, true})
        for (bool color : {false, true})
            for (bool cube : {false, true}) {
                reach(coneMarch, coneMarchShader(shadow, color, cube));
                for (bool slab : {false, true})
                    reach(planes, beamTreePlanesShader(shadow, color, cube, slab));
                for (bool noise : {false, true})
                    reach(planes, planesShader(shadow, color, noise, cube));
            }
    expectAllReached(ls_spirv::composite_comp_variants, composite);
    expectAllReached(ls_spirv::unshadowed_frag_variants, unshadowed);
    expectAllReached(ls_spirv::cone_march_frag_variants, coneMarch);
    expectAllReached(ls_spirv::planes_frag_variants, planes);
}

TEST(ShaderVariants, SplitCompositeNodesAskForBuiltVariants) {
    Reached blend, apply, exportT;
    for (bool dual : {false, true}) reach(blend, compositeBlendShader(dual));
    for (VkFormat f : {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT}) {
        reach(apply, compositeApplyShader(f));
        reach(exportT, transmittanceExportShader(f));
    }
    expectAllReached(ls_spirv::composite_blend_frag_variants, blend);
    expectAllReached(ls_spirv::composite_apply_comp_variants, apply);
    expectAllReached(ls_spirv::transmittance_export_comp_variants, exportT);
}

TEST(ShaderVariants, FroxelNodesAskForBuiltVariants) {
    Reached inject, integrate, apply;
    for (bool shadow : {false, true})
        for (bool color : {false, true})
            for (bool cube : {false, true})
                for (bool slab : {false, true})
                    for (bool noise : {false, true})
                        reach(inject, froxelInjectShader(shadow, color, cube, slab, noise));
    forEachTarget([&](const CompositeVariant& t) {
        for (const bool pixels : {false, true}) reach(apply, froxelApplyShader(t, pixels));
    });
    for (const bool samples : {false, true}) reach(integrate, froxelIntegrateShader(samples));
    expectAllReached(ls_spirv::inject_comp_variants, inject);
    expectAllReached(ls_spirv::integrate_comp_variants, integrate);
    expectAllReached(ls_spirv::apply_comp_variants, apply);
}

TEST(ShaderVariants, CountingStepsIsAnotherBuild) {
    const ScatterSpec spec;
    EXPECT_NE(rayMarchShader(spec, true, false).words, rayMarchShader(spec, true, true).words);
}

std::string pickError(const ls_spirv::ShaderVariants& shader,
                      std::initializer_list<ls_spirv::Define> defines) {
    try {
        shader.pick(defines);
    } catch (const std::logic_error& e) {
        return e.what();
    }
    return "";
}

TEST(ShaderVariants, BuildNotMadeIsOneClearError) {
    // The per-pixel march is not built without a shadow map and without a light color (an
    // unshadowed light without one takes the closed form).
    EXPECT_EQ(
        pickError(ls_spirv::pixel_march_frag_variants, {{"LS_NEEDS_TABLE", 1},
                                                        {"LS_LIGHT_COLOR", 0},
                                                        {"LS_CUBE_SHADOW", 0},
                                                        {"LS_NO_SHADOW_MAP", 1},
                                                        {"LS_COMPOSITE", 0},
                                                        {"LS_COLOR_RGBA32F", 0},
                                                        {"LS_WITH_OUTPUT", 0},
                                                        {"LS_SPLIT", 0}}),
        "shader pixel_march.frag with [LS_NEEDS_TABLE=1,LS_LIGHT_COLOR=0,LS_CUBE_SHADOW=0,"
        "LS_NO_SHADOW_MAP=1,LS_COMPOSITE=0,LS_COLOR_RGBA32F=0,LS_WITH_OUTPUT=0,LS_SPLIT=0]: no "
        "build has these defines (add it to shaders/CMakeLists.txt)");
    EXPECT_EQ(pickError(ls_spirv::cone_march_frag_variants, {{"LS_SHADOW_MAP", 1}}),
              "shader cone_march.frag with [LS_SHADOW_MAP=1]: the define LS_LIGHT_COLOR is not "
              "given");
    EXPECT_EQ(pickError(ls_spirv::cone_march_frag_variants,
                        {{"LS_SHADOW_MAP", 1}, {"LS_LIGHT_COLOR", 0}, {"LS_NOISE", 0}}),
              "shader cone_march.frag with [LS_SHADOW_MAP=1,LS_LIGHT_COLOR=0,LS_NOISE=0]: no build "
              "of it has the define LS_NOISE");
    EXPECT_EQ(pickError(ls_spirv::cone_march_frag_variants,
                        {{"LS_SHADOW_MAP", 1}, {"LS_CUBE_SHADOW", 0}, {"LS_LIGHT_COLOR", 1}}),
              "");
}

}  // namespace
}  // namespace ls
