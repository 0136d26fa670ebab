#include "engine_renderer.h"

#include <cstring>
#include <functional>
#include <map>
#include <glm/gtc/packing.hpp>

#include "camera_math.h"
#include "scene/bounding_boxes.h"
#include "fullscreen_vert.h"
#include "mesh_shadowed_frag.h"
#include "mesh_unshadowed_frag.h"
#include "mesh_vert.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/pipeline.h"
#include "rendergraph/report.h"
#include "rendergraph/vk_error.h"
#include "scene_to_plugin.h"
#include "shadow_frag.h"

namespace host {
namespace {

// mesh.frag's uniform block (std140).
struct Lighting {
    glm::mat4 lightViewProj;
    glm::vec4 lightPos, lightDir, lightIntensity, betaT, ambient, shadowInfo;
};

struct DrawPush {
    glm::mat4 viewProj;
    glm::vec4 baseColor;
};

rg::GraphicsPipelineDesc meshPipeline(rg::ShaderCode fragment, const rg::RenderingFormats& formats) {
    rg::GraphicsPipelineDesc d;
    d.vertex = rg::spirv(ls_spirv::mesh_vert);
    d.fragment = fragment;
    d.formats = formats;
    d.pushConstantBytes = sizeof(DrawPush);
    d.vertexBindings = {{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    d.vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
                          {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
                          {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, uv)}};
    d.depthTest = true;
    d.depthWrite = true;
    return d;
}

}  // namespace

struct EngineRenderer::Pipelines {
    explicit Pipelines(const rg::Device& d) : samplers(d) {}
    rg::Samplers samplers;
    rg::Pipeline shadow, forward, cubeShadow;
    Lighting lighting{};
    // The lights after the first: each one's lighting (no ambient: the first light's pass adds it)
    // and additive forward pipelines by light type and shadowing.
    std::vector<Lighting> moreLighting;
    std::map<int, rg::Pipeline> additive;
    glm::mat4 viewProj{1.0f};
};

EngineRenderer::EngineRenderer(const rg::Device& device, SceneDesc scene, const MeshData& mesh,
                               VkExtent2D size)
    : device_(device), scene_(std::move(scene)), bounds_(mesh.bounds), size_(size) {
    for (const Primitive& p : mesh.primitives) {
        Bounds b;
        for (uint32_t i = p.firstIndex; i < p.firstIndex + p.indexCount; ++i) b.add(mesh.vertices[mesh.indices[i]].position);
        partBounds_.push_back(b);
    }
    // Seed 004's occluders: the scene's oriented boxes, handed to the plugin with every frame.
    auto toPlugin = [](const OrientedBox& b) {
        lightscatter::OccluderBox o;
        o.center = {b.center.x, b.center.y, b.center.z};
        for (int i = 0; i < 3; ++i) o.axes[static_cast<size_t>(i)] = {b.axes[i].x, b.axes[i].y, b.axes[i].z};
        o.halfExtents = {b.halfExtents.x, b.halfExtents.y, b.halfExtents.z};
        return o;
    };
    for (const BoundingBoxes& b : boundingBoxes(mesh)) {
        lightscatter::Occluder o;
        o.outer = toPlugin(b.outer);
        if (b.inner) o.inner = toPlugin(*b.inner);
        occluders_.push_back(o);
    }
    mesh_ = std::make_unique<GpuMesh>(device, mesh);
    plugin_ = std::make_unique<lightscatter::Plugin>(lightscatter::VulkanContext{
        device.instance(), device.physical(), device.device(), device.queue(), device.queueFamily(),
        &device.enabledFeatures()});
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = device.queueFamily();
    RG_VK(vkCreateCommandPool(device.device(), &pool, nullptr, &pool_));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool_;
    alloc.commandBufferCount = 1;
    RG_VK(vkAllocateCommandBuffers(device.device(), &alloc, &cmd_));
    device.setName(cmd_, VK_OBJECT_TYPE_COMMAND_BUFFER, "host frame");
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    RG_VK(vkCreateFence(device.device(), &fence, nullptr, &fence_));
    createTargets();
    buildGraph();
}

EngineRenderer::~EngineRenderer() {
    vkDeviceWaitIdle(device_.device());
    executor_.reset();
    graph_.reset();
    pipelines_.reset();
    plugin_.reset();
    destroyCubeViews();
    vkDestroyFence(device_.device(), fence_, nullptr);
    vkDestroyCommandPool(device_.device(), pool_, nullptr);
}

void EngineRenderer::createTargets() {
    const uint32_t sm = scene_.light.shadowMapSize;
    depth_ = std::make_unique<GpuImage>(device_, VK_FORMAT_D32_SFLOAT, size_,
                                        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                        "host depth");
    color_ = std::make_unique<GpuImage>(device_, VK_FORMAT_R16G16B16A16_SFLOAT, size_,
                                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                        "host hdr color");
    inscatter_ = std::make_unique<GpuImage>(device_, VK_FORMAT_R32G32B32A32_SFLOAT, size_,
                                            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                            "host in-scattering");
    const VkDeviceSize pixels = size_t{size_.width} * size_.height;
    colorReadback_ = std::make_unique<rg::HostBuffer>(device_, pixels * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                      "color readback");
    linReadback_ = std::make_unique<rg::HostBuffer>(device_, pixels * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                    "in-scattering readback");
    shadowMap_.reset();
    destroyCubeViews();
    cubeShadow_.reset();
    if (sm > 0 && scene_.light.type == LightKind::Point) {
        cubeShadow_ = std::make_unique<GpuImage>(
            device_, VK_FORMAT_D32_SFLOAT, VkExtent2D{sm, sm},
            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "host cube shadow map", 6,
            VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT);
        static const char* kFaces[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
        for (uint32_t i = 0; i < 6; ++i) {
            VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
            info.image = cubeShadow_->image();
            info.viewType = VK_IMAGE_VIEW_TYPE_2D;
            info.format = VK_FORMAT_D32_SFLOAT;
            info.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, i, 1};
            RG_VK(vkCreateImageView(device_.device(), &info, nullptr, &cubeFaceViews_[i]));
            device_.setName(cubeFaceViews_[i], VK_OBJECT_TYPE_IMAGE_VIEW,
                            std::string("host cube shadow map face ") + kFaces[i]);
        }
    }
    if (sm > 0 && scene_.light.type != LightKind::Point)
        shadowMap_ = std::make_unique<GpuImage>(device_, VK_FORMAT_D32_SFLOAT, VkExtent2D{sm, sm},
                                                VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                                    VK_IMAGE_USAGE_SAMPLED_BIT,
                                                "host shadow map");
    moreShadowMaps_.clear();
    for (size_t i = 0; i < scene_.moreLights.size(); ++i) {
        const LightDesc& l = scene_.moreLights[i];
        if (l.shadowMapSize > 0 && l.type != LightKind::Point)
            moreShadowMaps_.push_back(std::make_unique<GpuImage>(
                device_, VK_FORMAT_D32_SFLOAT, VkExtent2D{l.shadowMapSize, l.shadowMapSize},
                VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                "host shadow map (light " + std::to_string(i + 1) + ")"));
        else
            moreShadowMaps_.push_back(nullptr);
    }
    // The Lin output stays in GENERAL from frame to frame, as the plugin expects it.
    device_.submitAndWait([&](VkCommandBuffer cmd) {
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        b.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
        b.newLayout = VK_IMAGE_LAYOUT_GENERAL;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = inscatter_->image();
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.imageMemoryBarrierCount = 1;
        dep.pImageMemoryBarriers = &b;
        vkCmdPipelineBarrier2(cmd, &dep);
    });
}

void EngineRenderer::destroyCubeViews() {
    for (VkImageView& v : cubeFaceViews_) {
        if (v) vkDestroyImageView(device_.device(), v, nullptr);
        v = VK_NULL_HANDLE;
    }
}

void EngineRenderer::recordCubeShadow(VkCommandBuffer cmd) {
    if (!pipelines_->cubeShadow) {
        rg::RenderingFormats formats;
        formats.depth = VK_FORMAT_D32_SFLOAT;
        auto d = meshPipeline(rg::spirv(ls_spirv::shadow_frag), formats);
        d.depthBias = true;
        d.cullMode = VK_CULL_MODE_NONE;
        pipelines_->cubeShadow = rg::Pipeline::graphics(device_, "host cube shadow map", d);
    }
    device_.beginLabel(cmd, "host cube shadow map");
    // The previous frame's plugin read the faces last (its final barrier made that visible to the
    // fragment tests); they are redrawn from scratch.
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    b.srcAccessMask = VK_ACCESS_2_NONE;
    b.dstStageMask = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    b.dstAccessMask = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    b.newLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = cubeShadow_->image();
    b.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 6};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);

    const std::array<glm::mat4, 6> faces = cubeFaceViewProjections(scene_.light, bounds_);
    const VkExtent2D extent = cubeShadow_->extent();
    const VkDeviceSize zero = 0;
    const VkBuffer vertices = mesh_->vertices();
    for (size_t i = 0; i < 6; ++i) {
        VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        depth.imageView = cubeFaceViews_[i];
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depth.clearValue.depthStencil = {1.0f, 0};
        VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
        info.renderArea = {{0, 0}, extent};
        info.layerCount = 1;
        info.pDepthAttachment = &depth;
        vkCmdBeginRendering(cmd, &info);
        const VkViewport viewport{0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height),
                                  0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, extent};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        pipelines_->cubeShadow.bind(cmd);
        vkCmdSetDepthBias(cmd, 1.0f, 0.0f, 1.5f);
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &zero);
        vkCmdBindIndexBuffer(cmd, mesh_->indices(), 0, VK_INDEX_TYPE_UINT32);
        for (const auto& d : mesh_->draws()) {
            pipelines_->cubeShadow.push(cmd, DrawPush{faces[i], d.baseColor});
            vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, 0, 0);
        }
        vkCmdEndRendering(cmd);
    }
    device_.endLabel(cmd);
}

void EngineRenderer::buildGraph() {
    executor_.reset();
    // Pipelines depend on formats, not on the size: a resize keeps them (recompiling them at every
    // resize cost lavapipe memory that it never gave back).
    if (!pipelines_) pipelines_ = std::make_shared<Pipelines>(device_);
    graph_ = std::make_unique<rg::RenderGraph>();
    rg::RenderGraph& g = *graph_;
    g.setScreenExtent(size_);
    auto imported = [&](const GpuImage& img, VkImageLayout finalLayout) {
        rg::ImportedImage d;
        d.image = img.image();
        d.format = img.format();
        d.extent = img.extent();
        d.usage = img.usage();
        d.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // redrawn every frame
        d.initialStages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        d.initialAccess = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
        d.finalLayout = finalLayout;
        return d;
    };
    colorRef_ = g.importImage("host hdr color", imported(*color_, VK_IMAGE_LAYOUT_GENERAL));
    depthRef_ = g.importImage("host depth", imported(*depth_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
    const bool shadowed = shadowMap_ != nullptr;
    if (shadowed)
        shadowRef_ = g.importImage("host shadow map", imported(*shadowMap_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));

    auto pipes = pipelines_;
    const GpuMesh* mesh = mesh_.get();
    rg::BufferRef lighting = g.createBuffer("host lighting", {sizeof(Lighting)});
    {
        auto pass = g.addPass("upload lighting", rg::PassType::Transfer);
        lighting = pass.transferDst(lighting);
        pass.execute([pipes, lighting](rg::PassContext& ctx) {
            vkCmdUpdateBuffer(ctx.cmd(), ctx.buffer(lighting), 0, sizeof(Lighting), &pipes->lighting);
        });
    }
    auto drawAll = [mesh](VkCommandBuffer cmd, const rg::Pipeline& p, const glm::mat4& viewProj,
                          const std::function<void(const GpuMesh::Draw&)>& bind) {
        const VkDeviceSize zero = 0;
        const VkBuffer vertices = mesh->vertices();
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &zero);
        vkCmdBindIndexBuffer(cmd, mesh->indices(), 0, VK_INDEX_TYPE_UINT32);
        for (const auto& d : mesh->draws()) {
            if (bind) bind(d);
            p.push(cmd, DrawPush{viewProj, d.baseColor});
            vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, 0, 0);
        }
    };
    if (shadowed) {
        auto pass = g.addPass("shadow map", rg::PassType::Graphics);
        shadowRef_ = pass.depthWrite(shadowRef_, rg::LoadOp::Clear, 1.0f);
        pass.execute([pipes, drawAll](rg::PassContext& ctx) {
            if (!pipes->shadow) {
                auto d = meshPipeline(rg::spirv(ls_spirv::shadow_frag), ctx.renderingFormats());
                d.depthBias = true;
                d.cullMode = VK_CULL_MODE_NONE;
                pipes->shadow = rg::Pipeline::graphics(ctx.device(), "host shadow map", d);
            }
            pipes->shadow.bind(ctx.cmd());
            vkCmdSetDepthBias(ctx.cmd(), 1.0f, 0.0f, 1.5f);
            drawAll(ctx.cmd(), pipes->shadow, pipes->lighting.lightViewProj, {});
        });
    }
    {
        auto pass = g.addPass("forward shading", rg::PassType::Graphics);
        pass.uniformBuffer(lighting);
        if (shadowed) pass.sampled(shadowRef_, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
        const glm::vec3 sky = scene_.skyColor;
        colorRef_ = pass.colorAttachment(colorRef_, rg::LoadOp::Clear, {{sky.r, sky.g, sky.b, 1.0f}});
        const bool reversed = scene_.camera.reversedZ;
        depthRef_ = pass.depthWrite(depthRef_, rg::LoadOp::Clear, reversed ? 0.0f : 1.0f);
        const rg::ImageRef shadow = shadowRef_;
        const int32_t lightType = scene_.light.type == LightKind::Directional ? 0
                                  : scene_.light.type == LightKind::Spot      ? 1
                                                                              : 2;
        pass.execute([pipes, drawAll, lighting, shadow, shadowed, reversed, lightType](rg::PassContext& ctx) {
            if (!pipes->forward) {
                auto d = meshPipeline(shadowed ? rg::spirv(ls_spirv::mesh_shadowed_frag)
                                               : rg::spirv(ls_spirv::mesh_unshadowed_frag),
                                      ctx.renderingFormats());
                d.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT},
                              {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};
                if (shadowed)
                    d.bindings.push_back({2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT});
                d.depthCompare = reversed ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS_OR_EQUAL;
                d.specialization.set(0, lightType);
                pipes->forward = rg::Pipeline::graphics(ctx.device(), "host forward shading", d);
            }
            pipes->forward.bind(ctx.cmd());
            drawAll(ctx.cmd(), pipes->forward, pipes->viewProj, [&](const GpuMesh::Draw& draw) {
                rg::DescriptorPush set;
                set.uniform(0, ctx.buffer(lighting))
                    .sampled(1, draw.texture, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, pipes->samplers.linear());
                if (shadowed)
                    set.sampled(2, ctx.view(shadow, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(shadow),
                                pipes->samplers.nearest());
                set.push(ctx.device(), ctx.cmd(), pipes->forward);
            });
        });
    }
    // The lights after the first: a shadow pass each where it has a map, then its direct light
    // added onto the shaded color (same geometry, depth tested against the first pass's depth).
    pipes->moreLighting.resize(scene_.moreLights.size());
    moreShadowRefs_.assign(scene_.moreLights.size(), rg::ImageRef{});
    for (size_t i = 0; i < scene_.moreLights.size(); ++i) {
        const std::string which = " (light " + std::to_string(i + 1) + ")";
        const bool lit = moreShadowMaps_[i] != nullptr;
        rg::BufferRef buffer = g.createBuffer("host lighting" + which, {sizeof(Lighting)});
        {
            auto pass = g.addPass("upload lighting" + which, rg::PassType::Transfer);
            buffer = pass.transferDst(buffer);
            pass.execute([pipes, buffer, i](rg::PassContext& ctx) {
                vkCmdUpdateBuffer(ctx.cmd(), ctx.buffer(buffer), 0, sizeof(Lighting), &pipes->moreLighting[i]);
            });
        }
        rg::ImageRef shadow;
        if (lit) {
            shadow = g.importImage("host shadow map" + which,
                                   imported(*moreShadowMaps_[i], VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
            auto pass = g.addPass("shadow map" + which, rg::PassType::Graphics);
            shadow = pass.depthWrite(shadow, rg::LoadOp::Clear, 1.0f);
            pass.execute([pipes, drawAll, i](rg::PassContext& ctx) {
                if (!pipes->shadow) {
                    auto d = meshPipeline(rg::spirv(ls_spirv::shadow_frag), ctx.renderingFormats());
                    d.depthBias = true;
                    d.cullMode = VK_CULL_MODE_NONE;
                    pipes->shadow = rg::Pipeline::graphics(ctx.device(), "host shadow map", d);
                }
                pipes->shadow.bind(ctx.cmd());
                vkCmdSetDepthBias(ctx.cmd(), 1.0f, 0.0f, 1.5f);
                drawAll(ctx.cmd(), pipes->shadow, pipes->moreLighting[i].lightViewProj, {});
            });
            moreShadowRefs_[i] = shadow;
        }
        auto pass = g.addPass("forward shading" + which, rg::PassType::Graphics);
        pass.uniformBuffer(buffer);
        if (lit) pass.sampled(shadow, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
        colorRef_ = pass.colorAttachment(colorRef_, rg::LoadOp::Load);
        pass.depthTest(depthRef_);
        const bool reversed = scene_.camera.reversedZ;
        const LightKind kind = scene_.moreLights[i].type;
        const int32_t lightType = kind == LightKind::Directional ? 0 : kind == LightKind::Spot ? 1 : 2;
        pass.execute([pipes, drawAll, buffer, shadow, lit, reversed, lightType](rg::PassContext& ctx) {
            const int key = lightType * 2 + (lit ? 1 : 0);
            auto it = pipes->additive.find(key);
            if (it == pipes->additive.end()) {
                auto d = meshPipeline(lit ? rg::spirv(ls_spirv::mesh_shadowed_frag)
                                          : rg::spirv(ls_spirv::mesh_unshadowed_frag),
                                      ctx.renderingFormats());
                d.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT},
                              {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};
                if (lit) d.bindings.push_back({2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT});
                d.depthWrite = false;
                d.depthCompare = reversed ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS_OR_EQUAL;
                d.blend = rg::BlendMode::Additive;
                d.specialization.set(0, lightType);
                it = pipes->additive.emplace(key, rg::Pipeline::graphics(ctx.device(), "host additive shading", d)).first;
            }
            const rg::Pipeline& p = it->second;
            p.bind(ctx.cmd());
            drawAll(ctx.cmd(), p, pipes->viewProj, [&](const GpuMesh::Draw& draw) {
                rg::DescriptorPush set;
                set.uniform(0, ctx.buffer(buffer))
                    .sampled(1, draw.texture, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, pipes->samplers.linear());
                if (lit)
                    set.sampled(2, ctx.view(shadow, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(shadow),
                                pipes->samplers.nearest());
                set.push(ctx.device(), ctx.cmd(), p);
            });
        });
    }
    const rg::VulkanDeviceCaps caps(device_);
    executor_ = std::make_unique<rg::GraphExecutor>(device_, g, rg::compile(g, caps));
}

void EngineRenderer::resize(VkExtent2D size) {
    vkDeviceWaitIdle(device_.device());
    size_ = size;
    createTargets();
    buildGraph();
}

lightscatter::FrameDescription EngineRenderer::describe(const RenderOptions& options,
                                                        VkPipelineStageFlags2 finalStages,
                                                        VkAccessFlags2 finalAccess) const {
    lightscatter::FrameDescription f;
    f.occluders = occluders_;
    auto input = [](const GpuImage& img, VkImageLayout layout) {
        lightscatter::ImageInput in;
        in.image = img.image();
        in.format = img.format();
        in.extent = img.extent();
        in.usage = img.usage();
        in.layout = layout;
        in.finalLayout = layout;
        return in;
    };
    f.depth = input(*depth_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    f.color = input(*color_, VK_IMAGE_LAYOUT_GENERAL);
    f.color.finalStages = finalStages;
    f.color.finalAccess = finalAccess;
    f.inscatterOut = input(*inscatter_, VK_IMAGE_LAYOUT_GENERAL);
    f.inscatterOut->finalStages = finalStages;
    f.inscatterOut->finalAccess = finalAccess;
    if (shadowMap_) f.shadowMap = input(*shadowMap_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    if (cubeShadow_) {
        // Left by the six face passes; left for the next frame's, which redraw it.
        f.shadowMap = input(*cubeShadow_, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
        f.shadowMap->arrayLayers = 6;
        f.shadowMap->stages = VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
        f.shadowMap->access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        f.shadowMap->finalStages =
            VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
        f.shadowMap->finalAccess = VK_ACCESS_2_NONE;
    }
    const float aspect = static_cast<float>(size_.width) / static_cast<float>(size_.height);
    f.camera = toPluginCamera(scene_.camera, cameraView(scene_.camera), cameraProjection(scene_.camera, aspect));
    f.light = toPluginLight(scene_.light, shadowMap_ ? shadowViewProjection(scene_.light, bounds_, partBounds_, scene_.camera, aspect) : glm::mat4(1.0f),
                            shadowMap_ != nullptr);
    if (cubeShadow_) {
        f.light = toPluginLight(scene_.light, glm::mat4(1.0f), true);
        const std::array<glm::mat4, 6> faces = cubeFaceViewProjections(scene_.light, bounds_);
        for (size_t i = 0; i < 6; ++i) f.light.cubeFaceViewProjections[i] = toPluginMatrix(faces[i]);
    }
    if (!scene_.moreLights.empty()) {
        // Several lights: the first one's fields move into the list, the others follow.
        f.lights.push_back({f.light, f.shadowMap, std::nullopt});
        f.light = {};
        f.shadowMap.reset();
        for (size_t i = 0; i < scene_.moreLights.size(); ++i) {
            const LightDesc& l = scene_.moreLights[i];
            lightscatter::LightInput in;
            const bool lit = moreShadowMaps_[i] != nullptr;
            in.light = toPluginLight(l, lit ? shadowViewProjection(l, bounds_, partBounds_, scene_.camera, aspect) : glm::mat4(1.0f),
                                     lit);
            if (lit) in.shadowMap = input(*moreShadowMaps_[i], VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
            f.lights.push_back(in);
        }
    }
    f.medium = toPluginMedium(scene_.medium);
    f.method = options.method;
    f.profile = options.profile;
    f.custom = options.custom;
    f.timeSeconds = options.timeSeconds;
    return f;
}

void EngineRenderer::record(VkCommandBuffer cmd, const RenderOptions& options,
                            VkPipelineStageFlags2 finalStages, VkAccessFlags2 finalAccess,
                            VkImageLayout finalLayout) {
    // The plugin checks the description first: nothing is recorded when it is refused.
    lightscatter::FrameDescription frame = describe(options, finalStages, finalAccess);
    frame.color.finalLayout = finalLayout;
    frame.inscatterOut->finalLayout = finalLayout;
    const float aspect = static_cast<float>(size_.width) / static_cast<float>(size_.height);
    pipelines_->viewProj = cameraProjection(scene_.camera, aspect) * cameraView(scene_.camera);
    Lighting& l = pipelines_->lighting;
    const LightDesc& light = scene_.light;
    l.lightViewProj = shadowMap_ ? shadowViewProjection(light, bounds_, partBounds_, scene_.camera, aspect) : glm::mat4(1.0f);
    l.lightPos = glm::vec4(light.position, 0.0f);
    l.lightDir = glm::vec4(glm::normalize(light.direction), std::cos(glm::radians(light.halfAngleDegrees)));
    l.lightIntensity = glm::vec4(light.intensity, light.range);
    l.betaT = glm::vec4(scene_.medium.betaR + scene_.medium.betaM + scene_.medium.sigmaA, light.radius);
    l.ambient = glm::vec4(scene_.ambient, 0.0f);
    l.shadowInfo = glm::vec4(static_cast<float>(light.shadowMapSize), 0.0f, 0.0f, 0.0f);
    pipelines_->moreLighting.resize(scene_.moreLights.size());
    for (size_t i = 0; i < scene_.moreLights.size(); ++i) {
        const LightDesc& m = scene_.moreLights[i];
        Lighting& e = pipelines_->moreLighting[i];
        e = l;
        e.lightViewProj = moreShadowMaps_[i] ? shadowViewProjection(m, bounds_, partBounds_, scene_.camera, aspect)
                                             : glm::mat4(1.0f);
        e.lightPos = glm::vec4(m.position, 0.0f);
        e.lightDir = glm::vec4(glm::normalize(m.direction), std::cos(glm::radians(m.halfAngleDegrees)));
        e.lightIntensity = glm::vec4(m.intensity, m.range);
        e.betaT.w = m.radius;
        e.ambient = glm::vec4(0.0f);  // added once, by the first light's pass
        e.shadowInfo = glm::vec4(static_cast<float>(m.shadowMapSize), 0.0f, 0.0f, 0.0f);
    }
    if (cubeShadow_) recordCubeShadow(cmd);
    executor_->record(cmd);
    try {
        plugin_->record(cmd, frame);
    } catch (const lightscatter::InvalidInput& e) {
        // The frame is the scene's: say what is wrong in SCENE.json's terms, not the API's.
        throw SceneError(pluginRefusalInSceneTerms(e.what(), scene_.path));
    }
}

FrameOutput EngineRenderer::timings() {
    FrameOutput out;
    out.engine = executor_->readTimings();
    out.plugin = plugin_->report();
    return out;
}

FrameOutput EngineRenderer::render(const RenderOptions& options) {
    const VkDeviceSize pixels = size_t{size_.width} * size_.height;
    const rg::HostBuffer& colorBuffer = *colorReadback_;
    const rg::HostBuffer& linBuffer = *linReadback_;
    RG_VK(vkResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    RG_VK(vkBeginCommandBuffer(cmd_, &begin));
    try {
        record(cmd_, options, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    } catch (...) {
        vkEndCommandBuffer(cmd_);
        throw;
    }
    // The plugin leaves both images in TRANSFER_SRC_OPTIMAL for the copies; they go back to GENERAL,
    // where the next frame expects them.
    auto transition = [&](VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 dst, VkAccessFlags2 dstAccess) {
        VkImageMemoryBarrier2 b[2] = {{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2}, {VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2}};
        const VkImage images[2] = {color_->image(), inscatter_->image()};
        for (int i = 0; i < 2; ++i) {
            b[i].srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
            b[i].srcAccessMask = 0;
            b[i].dstStageMask = dst;
            b[i].dstAccessMask = dstAccess;
            b[i].oldLayout = from;
            b[i].newLayout = to;
            b[i].srcQueueFamilyIndex = b[i].dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            b[i].image = images[i];
            b[i].subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        }
        VkDependencyInfo d{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        d.imageMemoryBarrierCount = 2;
        d.pImageMemoryBarriers = b;
        vkCmdPipelineBarrier2(cmd_, &d);
    };
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {size_.width, size_.height, 1};
    vkCmdCopyImageToBuffer(cmd_, color_->image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, colorBuffer.buffer(), 1, &region);
    vkCmdCopyImageToBuffer(cmd_, inscatter_->image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, linBuffer.buffer(), 1,
                           &region);
    transition(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
               VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
    VkMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    toHost.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &toHost;
    vkCmdPipelineBarrier2(cmd_, &dep);
    RG_VK(vkEndCommandBuffer(cmd_));
    device_.submitAndWait(cmd_, fence_);

    FrameOutput out = timings();
    out.color.resize(pixels * 4);
    const auto* halves = static_cast<const uint16_t*>(colorBuffer.data());
    for (size_t i = 0; i < out.color.size(); ++i) out.color[i] = glm::unpackHalf1x16(halves[i]);
    out.inscatter.resize(pixels * 4);
    std::memcpy(out.inscatter.data(), linBuffer.data(), pixels * 16);
    return out;
}

std::string EngineRenderer::engineGraphDot() const { return rg::reportDot(*graph_, executor_->compiled()); }

}  // namespace host
