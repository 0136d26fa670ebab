#include "engine_renderer.h"

#include <cstring>
#include <functional>
#include <glm/gtc/packing.hpp>
#include <map>

#include "camera_math.h"
#include "fullscreen_vert.h"
#include "mesh_shadowed_frag.h"
#include "mesh_unshadowed_frag.h"
#include "mesh_vert.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/image_readback.h"
#include "rendergraph/pipeline.h"
#include "rendergraph/vk_error.h"
#include "scene/bounding_boxes.h"
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

rg::GraphicsPipelineDesc meshPipeline(rg::ShaderCode fragment,
                                      const rg::RenderingFormats& formats) {
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

// Every draw of the mesh with `p` bound; `bind` pushes a draw's descriptors first.
void drawMesh(VkCommandBuffer cmd, const GpuMesh& mesh, const rg::Pipeline& p,
              const glm::mat4& viewProj,
              const std::function<void(const GpuMesh::Draw&)>& bind = {}) {
    const VkDeviceSize zero = 0;
    const VkBuffer vertices = mesh.vertices();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &zero);
    vkCmdBindIndexBuffer(cmd, mesh.indices(), 0, VK_INDEX_TYPE_UINT32);
    for (const auto& d : mesh.draws()) {
        if (bind) bind(d);
        p.push(cmd, DrawPush{viewProj, d.baseColor});
        vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, 0, 0);
    }
}

}  // namespace

struct EngineRenderer::Pipelines {
    explicit Pipelines(const rg::Device& d) : samplers(d) {}
    rg::Samplers samplers;
    rg::Pipeline shadow, cubeShadow;
    // Each light's lighting (ambient in the first light's only: its pass adds it once), and the
    // shading pipelines by pass (the first light's or an added one), light type and shadowing.
    std::vector<Lighting> lighting;
    std::map<int, rg::Pipeline> shading;
    glm::mat4 viewProj{1.0f};
};

namespace {

// Runs `make`; a device that could not give what it asked for is reported with `cause`, the
// option or scene field behind it, in front.
template <class F>
auto because(const std::string& cause, F&& make) -> decltype(make()) {
    try {
        return make();
    } catch (const rg::OutOfDeviceMemory& e) {
        throw rg::OutOfDeviceMemory(cause + ": " + e.what());
    } catch (const rg::VulkanError& e) {
        throw rg::VulkanError(cause + ": " + e.what());
    }
}

}  // namespace

EngineRenderer::EngineRenderer(const rg::Device& device, SceneDesc scene, const MeshData& mesh,
                               VkExtent2D size, std::string sizeOrigin)
    : device_(device),
      scene_(std::move(scene)),
      bounds_(mesh.bounds),
      size_(size),
      sizeOrigin_(std::move(sizeOrigin)) {
    for (const Primitive& p : mesh.primitives) {
        Bounds b;
        for (uint32_t i = p.firstIndex; i < p.firstIndex + p.indexCount; ++i)
            b.add(mesh.vertices[mesh.indices[i]].position);
        partBounds_.push_back(b);
    }
    // Seed 004's occluders: the scene's oriented boxes, handed to the plugin with every frame.
    auto toPlugin = [](const OrientedBox& b) {
        lightscatter::OccluderBox o;
        o.center = {b.center.x, b.center.y, b.center.z};
        for (int i = 0; i < 3; ++i)
            o.axes[static_cast<size_t>(i)] = {b.axes[i].x, b.axes[i].y, b.axes[i].z};
        o.halfExtents = {b.halfExtents.x, b.halfExtents.y, b.halfExtents.z};
        return o;
    };
    // More parts than the beam tree takes are merged into a grid of boxes; the other methods
    // ignore occluders either way.
    std::vector<BoundingBoxes> boxes = boundingBoxes(mesh);
    if (boxes.size() > lightscatter::kMaxOccluders)
        boxes = gridBoxes(mesh, lightscatter::kMaxOccluders);
    for (const BoundingBoxes& b : boxes) {
        lightscatter::Occluder o;
        o.outer = toPlugin(b.outer);
        if (b.inner) o.inner = toPlugin(*b.inner);
        occluders_.push_back(o);
    }
    mesh_ = because(scene_.path + ": the scene's models",
                    [&] { return std::make_unique<GpuMesh>(device, mesh); });
    plugin_ = std::make_unique<lightscatter::Plugin>(lightscatter::VulkanContext{
        device.instance(), device.physical(), device.device(), device.queue(), device.queueFamily(),
        &device.enabledFeatures(), device.instanceApiVersion()});
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
    try {
        createTargets();
        buildGraph();
    } catch (...) {
        // No destructor runs for a constructor that throws: what it made so far goes here.
        vkDestroyFence(device.device(), fence_, nullptr);
        vkDestroyCommandPool(device.device(), pool_, nullptr);
        throw;
    }
}

EngineRenderer::~EngineRenderer() {
    vkDeviceWaitIdle(device_.device());
    executor_.reset();
    graph_.reset();
    pipelines_.reset();
    plugin_.reset();
    vkDestroyFence(device_.device(), fence_, nullptr);
    vkDestroyCommandPool(device_.device(), pool_, nullptr);
}

void EngineRenderer::createTargets() {
    // What the device cannot give is said in the terms of the option or field that asked for it.
    const std::string screen =
        sizeOrigin_ + " " + std::to_string(size_.width) + "x" + std::to_string(size_.height);
    because(screen, [&] { createScreenTargets(); });
    lights_.clear();
    lights_.resize(scene_.lightCount());
    for (size_t i = 0; i < lights_.size(); ++i) {
        const LightDesc& l = scene_.lightAt(i);
        const std::string which = i == 0 ? "" : " (light " + std::to_string(i) + ")";
        if (l.cookie) {
            const std::string field =
                scene_.path + ": " +
                (scene_.lightList ? "lights[" + std::to_string(i) + "]" : std::string("light")) +
                ".cookie";
            because(field, [&] {
                // sRGB: the file stores colors as images do, and the plugin samples the linear
                // transmittance of the glass (Vulkan decodes before it filters).
                lights_[i].cookie = std::make_unique<GpuImage>(
                    device_, VK_FORMAT_R8G8B8A8_SRGB, VkExtent2D{l.cookie->width, l.cookie->height},
                    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                    "host cookie" + which);
                uploadCookie(*l.cookie, *lights_[i].cookie);
            });
        }
        const uint32_t sm = l.shadowMapSize;
        if (sm == 0) continue;
        const std::string field =
            scene_.path + ": " +
            (scene_.lightList ? "lights[" + std::to_string(i) + "]" : std::string("light")) +
            ".shadowMapSize " + std::to_string(sm);
        because(field, [&] {
            if (l.type == lightscatter::LightType::Point)
                lights_[i].cubeShadow =
                    std::make_unique<CubeShadowMap>(device_, sm, "host cube shadow map" + which);
            else
                lights_[i].shadowMap = std::make_unique<GpuImage>(
                    device_, VK_FORMAT_D32_SFLOAT, VkExtent2D{sm, sm},
                    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                    "host shadow map" + which);
        });
    }
    layOutTargets();
}

// Once, when the targets are made: the copy is waited for, and the image stays in
// SHADER_READ_ONLY_OPTIMAL for every frame after (the plugin only samples it).
void EngineRenderer::uploadCookie(const Texture& texture, GpuImage& image) const {
    const VkDeviceSize bytes = texture.rgba.size();
    rg::HostBuffer staging(device_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "cookie upload");
    std::memcpy(staging.data(), texture.rgba.data(), bytes);
    device_.submitAndWait([&](VkCommandBuffer cmd) {
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
        b.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = image.image();
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.imageMemoryBarrierCount = 1;
        dep.pImageMemoryBarriers = &b;
        vkCmdPipelineBarrier2(cmd, &dep);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {texture.width, texture.height, 1};
        vkCmdCopyBufferToImage(cmd, staging.buffer(), image.image(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        b.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
        b.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        b.dstStageMask = VK_PIPELINE_STAGE_2_NONE;
        b.dstAccessMask = VK_ACCESS_2_NONE;
        b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        b.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        vkCmdPipelineBarrier2(cmd, &dep);
    });
}

void EngineRenderer::createScreenTargets() {
    depth_ = std::make_unique<GpuImage>(
        device_, VK_FORMAT_D32_SFLOAT, size_,
        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "host depth");
    color_ = std::make_unique<GpuImage>(
        device_, VK_FORMAT_R16G16B16A16_SFLOAT, size_,
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
        "host hdr color");
    inscatter_ = std::make_unique<GpuImage>(
        device_, VK_FORMAT_R32G32B32A32_SFLOAT, size_,
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "host in-scattering");
    const VkDeviceSize pixels = size_t{size_.width} * size_.height;
    colorReadback_ = std::make_unique<rg::HostBuffer>(
        device_, pixels * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "color readback");
    linReadback_ = std::make_unique<rg::HostBuffer>(
        device_, pixels * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "in-scattering readback");
}

namespace {

// A new storage image into GENERAL, where the host keeps its outputs from frame to frame.
void layOutAsGeneral(const rg::Device& device, VkImage image) {
    device.submitAndWait([&](VkCommandBuffer cmd) {
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        b.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
        b.newLayout = VK_IMAGE_LAYOUT_GENERAL;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = image;
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.imageMemoryBarrierCount = 1;
        dep.pImageMemoryBarriers = &b;
        vkCmdPipelineBarrier2(cmd, &dep);
    });
}

}  // namespace

void EngineRenderer::layOutTargets() {
    // The Lin output stays in GENERAL from frame to frame, as the plugin expects it.
    layOutAsGeneral(device_, inscatter_->image());
}

void EngineRenderer::recordCubeShadows(VkCommandBuffer cmd) {
    for (size_t i = 0; i < lights_.size(); ++i) {
        if (!lights_[i].cubeShadow) continue;
        if (!pipelines_->cubeShadow) {
            rg::RenderingFormats formats;
            formats.depth = VK_FORMAT_D32_SFLOAT;
            auto d = meshPipeline(rg::spirv(ls_spirv::shadow_frag), formats);
            d.depthBias = true;
            d.cullMode = VK_CULL_MODE_NONE;
            pipelines_->cubeShadow = rg::Pipeline::graphics(device_, "host cube shadow map", d);
        }
        const rg::Pipeline& pipeline = pipelines_->cubeShadow;
        const GpuMesh& mesh = *mesh_;
        lights_[i].cubeShadow->record(cmd, cubeFaceViewProjections(scene_.lightAt(i), bounds_),
                                      [&](VkCommandBuffer c, const glm::mat4& face) {
                                          pipeline.bind(c);
                                          vkCmdSetDepthBias(c, 1.0f, 0.0f, 1.5f);
                                          drawMesh(c, mesh, pipeline, face);
                                      });
    }
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
    depthRef_ =
        g.importImage("host depth", imported(*depth_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
    auto pipes = pipelines_;
    const GpuMesh* mesh = mesh_.get();
    pipes->lighting.resize(scene_.lightCount());
    // Each light: its lighting uploaded, its shadow map drawn where it has a 2D one, then its
    // direct light shaded. The first light's pass clears the color to the sky, writes depth and
    // adds the ambient; each later one adds its light onto that color, depth tested against the
    // same depth.
    for (size_t i = 0; i < scene_.lightCount(); ++i) {
        const bool first = i == 0;
        const std::string which = first ? "" : " (light " + std::to_string(i) + ")";
        rg::BufferRef lighting = g.createBuffer("host lighting" + which, {sizeof(Lighting)});
        {
            auto pass = g.addPass("upload lighting" + which, rg::PassType::Transfer);
            lighting = pass.transferDst(lighting);
            pass.execute([pipes, lighting, i](rg::PassContext& ctx) {
                vkCmdUpdateBuffer(ctx.cmd(), ctx.buffer(lighting), 0, sizeof(Lighting),
                                  &pipes->lighting[i]);
            });
        }
        const bool shadowed = lights_[i].shadowMap != nullptr;
        rg::ImageRef shadow;
        if (shadowed) {
            shadow = g.importImage(
                "host shadow map" + which,
                imported(*lights_[i].shadowMap, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
            auto pass = g.addPass("shadow map" + which, rg::PassType::Graphics);
            shadow = pass.depthWrite(shadow, rg::LoadOp::Clear, 1.0f);
            pass.execute([pipes, mesh, i](rg::PassContext& ctx) {
                if (!pipes->shadow) {
                    auto d = meshPipeline(rg::spirv(ls_spirv::shadow_frag), ctx.renderingFormats());
                    d.depthBias = true;
                    d.cullMode = VK_CULL_MODE_NONE;
                    pipes->shadow = rg::Pipeline::graphics(ctx.device(), "host shadow map", d);
                }
                pipes->shadow.bind(ctx.cmd());
                vkCmdSetDepthBias(ctx.cmd(), 1.0f, 0.0f, 1.5f);
                drawMesh(ctx.cmd(), *mesh, pipes->shadow, pipes->lighting[i].lightViewProj);
            });
        }
        auto pass = g.addPass("forward shading" + which, rg::PassType::Graphics);
        pass.uniformBuffer(lighting);
        if (shadowed) pass.sampled(shadow, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
        const bool reversed = scene_.camera.reversedZ;
        if (first) {
            const glm::vec3 sky = scene_.skyColor;
            colorRef_ =
                pass.colorAttachment(colorRef_, rg::LoadOp::Clear, {{sky.r, sky.g, sky.b, 1.0f}});
            depthRef_ = pass.depthWrite(depthRef_, rg::LoadOp::Clear, reversed ? 0.0f : 1.0f);
        } else {
            colorRef_ = pass.colorAttachment(colorRef_, rg::LoadOp::Load);
            pass.depthTest(depthRef_);
        }
        const lightscatter::LightType kind = scene_.lightAt(i).type;
        const int32_t lightType = kind == lightscatter::LightType::Directional ? 0
                                  : kind == lightscatter::LightType::Spot      ? 1
                                                                               : 2;
        pass.execute([pipes, mesh, lighting, shadow, shadowed, reversed, lightType,
                      first](rg::PassContext& ctx) {
            const int key = (first ? 8 : 0) + lightType * 2 + (shadowed ? 1 : 0);
            auto it = pipes->shading.find(key);
            if (it == pipes->shading.end()) {
                auto d = meshPipeline(shadowed ? rg::spirv(ls_spirv::mesh_shadowed_frag)
                                               : rg::spirv(ls_spirv::mesh_unshadowed_frag),
                                      ctx.renderingFormats());
                d.bindings = {
                    {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT},
                    {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};
                if (shadowed)
                    d.bindings.push_back({2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                          VK_SHADER_STAGE_FRAGMENT_BIT});
                d.depthCompare =
                    reversed ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS_OR_EQUAL;
                if (!first) {
                    d.depthWrite = false;
                    d.blend = rg::BlendMode::Additive;
                }
                d.specialization.set(0, lightType);
                it = pipes->shading
                         .emplace(key,
                                  rg::Pipeline::graphics(
                                      ctx.device(),
                                      first ? "host forward shading" : "host additive shading", d))
                         .first;
            }
            const rg::Pipeline& p = it->second;
            p.bind(ctx.cmd());
            drawMesh(ctx.cmd(), *mesh, p, pipes->viewProj, [&](const GpuMesh::Draw& draw) {
                rg::DescriptorPush set;
                set.uniform(0, ctx.buffer(lighting))
                    .sampled(1, draw.texture, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                             pipes->samplers.linear());
                if (shadowed)
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

namespace {

lightscatter::ImageInput imageInput(const GpuImage& img, VkImageLayout layout) {
    lightscatter::ImageInput in;
    in.image = img.image();
    in.format = img.format();
    in.extent = img.extent();
    in.usage = img.usage();
    in.layout = layout;
    in.finalLayout = layout;
    return in;
}

}  // namespace

lightscatter::LightInput EngineRenderer::pluginLight(size_t i, float aspect) const {
    const LightDesc& l = scene_.lightAt(i);
    const LightTargets& t = lights_[i];
    lightscatter::LightInput in;
    if (t.shadowMap) {
        in.light = toPluginLight(
            l, shadowViewProjection(l, bounds_, partBounds_, scene_.camera, aspect), true);
        in.shadowMap = imageInput(*t.shadowMap, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    } else if (t.cubeShadow) {
        in.light = toPluginLight(l, glm::mat4(1.0f), true);
        const std::array<glm::mat4, 6> faces = cubeFaceViewProjections(l, bounds_);
        for (size_t f = 0; f < 6; ++f)
            in.light.cubeFaceViewProjections[f] = toPluginMatrix(faces[f]);
        // Left by the six face passes; left for the next frame's, which redraw it.
        in.shadowMap = imageInput(t.cubeShadow->image(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
        in.shadowMap->arrayLayers = 6;
        in.shadowMap->stages = VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
        in.shadowMap->access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        in.shadowMap->finalStages = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                    VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
        in.shadowMap->finalAccess = VK_ACCESS_2_NONE;
    } else {
        in.light = toPluginLight(l, glm::mat4(1.0f), false);
        // A cookie without a shadow map is cast with the matrix the map would have had.
        if (t.cookie)
            in.light.shadowViewProjection = toPluginMatrix(
                shadowViewProjection(l, bounds_, partBounds_, scene_.camera, aspect));
    }
    if (t.cookie) {
        // Uploaded and waited for before the first frame: the engine neither wrote it since nor
        // uses it after, so there is nothing to wait for or to hand it back to.
        in.lightColor = imageInput(*t.cookie, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        in.lightColor->stages = in.lightColor->finalStages = VK_PIPELINE_STAGE_2_NONE;
        in.lightColor->access = in.lightColor->finalAccess = VK_ACCESS_2_NONE;
    }
    return in;
}

lightscatter::FrameDescription EngineRenderer::describe(const RenderOptions& options,
                                                        VkPipelineStageFlags2 finalStages,
                                                        VkAccessFlags2 finalAccess) const {
    lightscatter::FrameDescription f;
    f.occluders = occluders_;
    f.depth = imageInput(*depth_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    f.color = imageInput(*color_, VK_IMAGE_LAYOUT_GENERAL);
    f.color.finalStages = finalStages;
    f.color.finalAccess = finalAccess;
    if (options.linOut) {
        f.inscatterOut = imageInput(*inscatter_, VK_IMAGE_LAYOUT_GENERAL);
        f.inscatterOut->finalStages = finalStages;
        f.inscatterOut->finalAccess = finalAccess;
    }
    const float aspect = static_cast<float>(size_.width) / static_cast<float>(size_.height);
    f.camera = toPluginCamera(scene_.camera, cameraView(scene_.camera),
                              cameraProjection(scene_.camera, aspect));
    // One light is the plugin's single light, several (or a scene's "lights" of one) its list, so
    // that a refusal names the light as the scene does.
    if (lights_.size() == 1 && !scene_.lightList) {
        lightscatter::LightInput only = pluginLight(0, aspect);
        f.light = only.light;
        f.shadowMap = only.shadowMap;
        f.lightColor = only.lightColor;
    } else {
        for (size_t i = 0; i < lights_.size(); ++i) f.lights.push_back(pluginLight(i, aspect));
    }
    f.medium = toPluginMedium(scene_.medium);
    f.method = options.method;
    f.profile = options.profile;
    f.custom = options.custom;
    f.timeSeconds = options.timeSeconds;
    f.debug.countSteps = options.countSteps;
    f.resetHistory = options.resetHistory;
    if (options.exportVolume && volume_) {
        f.volumeOut = imageInput(*volume_, VK_IMAGE_LAYOUT_GENERAL);
        f.volumeOut->depth = volume_->depth();
        f.volumeOut->finalStages = finalStages;
        f.volumeOut->finalAccess = finalAccess;
    }
    return f;
}

void EngineRenderer::record(VkCommandBuffer cmd, const RenderOptions& options,
                            VkPipelineStageFlags2 finalStages, VkAccessFlags2 finalAccess,
                            VkImageLayout finalLayout) {
    // The plugin checks the description first: nothing is recorded when it is refused.
    lightscatter::FrameDescription frame = describe(options, finalStages, finalAccess);
    frame.color.finalLayout = finalLayout;
    if (frame.inscatterOut) frame.inscatterOut->finalLayout = finalLayout;
    if (frame.volumeOut) frame.volumeOut->finalLayout = finalLayout;
    const float aspect = static_cast<float>(size_.width) / static_cast<float>(size_.height);
    pipelines_->viewProj = cameraProjection(scene_.camera, aspect) * cameraView(scene_.camera);
    pipelines_->lighting.resize(lights_.size());
    const glm::vec3 betaT = scene_.medium.betaR + scene_.medium.betaM + scene_.medium.sigmaA;
    for (size_t i = 0; i < lights_.size(); ++i) {
        const LightDesc& light = scene_.lightAt(i);
        Lighting& l = pipelines_->lighting[i];
        l.lightViewProj = lights_[i].shadowMap ? shadowViewProjection(light, bounds_, partBounds_,
                                                                      scene_.camera, aspect)
                                               : glm::mat4(1.0f);
        l.lightPos = glm::vec4(light.position, 0.0f);
        l.lightDir = glm::vec4(glm::normalize(light.direction),
                               std::cos(glm::radians(light.outerConeAngleDegrees)));
        l.lightIntensity = glm::vec4(light.intensity, light.range);
        l.betaT = glm::vec4(betaT, light.radius);
        l.ambient = glm::vec4(i == 0 ? scene_.ambient : glm::vec3(0.0f), 0.0f);  // added once
        l.shadowInfo = glm::vec4(static_cast<float>(light.shadowMapSize), 0.0f, 0.0f, 0.0f);
    }
    recordCubeShadows(cmd);
    executor_->record(cmd);
    try {
        plugin_->record(cmd, frame);
    } catch (const lightscatter::InvalidInput& e) {
        // The frame is the scene's: say what is wrong in SCENE.json's terms, not the API's.
        throw SceneError(pluginRefusalInSceneTerms(e.what(), scene_.path));
    } catch (const lightscatter::DeviceError& e) {
        // The plugin's memory grows with the screen and the profile's slices and samples.
        std::string why = e.what();
        if (why.rfind("lightscatter: ", 0) == 0) why.erase(0, 14);
        throw std::runtime_error("the plugin's frame at " + sizeOrigin_ + " " +
                                 std::to_string(size_.width) + "x" + std::to_string(size_.height) +
                                 " with profile " + lightscatter::profileName(options.profile) +
                                 ": " + why);
    }
}

void EngineRenderer::check(const RenderOptions& options) const {
    try {
        plugin_->check(
            describe(options, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT));
    } catch (const lightscatter::InvalidInput& e) {
        throw SceneError(pluginRefusalInSceneTerms(e.what(), scene_.path));
    }
}

FrameOutput EngineRenderer::timings() {
    FrameOutput out;
    out.engine = executor_->readTimings();
    out.plugin = plugin_->report();
    return out;
}

void EngineRenderer::prepareVolume(const RenderOptions& options) {
    lightscatter::FroxelVolume v;
    try {
        v = lightscatter::froxelVolume(
            describe(options, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE));
    } catch (const lightscatter::InvalidInput&) {
        return;  // record() refuses the same frame, in the scene's terms
    }
    if (volume_ && volume_->extent().width == v.width && volume_->extent().height == v.height &&
        volume_->depth() == v.depth)
        return;
    volume_.reset();
    volumeReadback_.reset();
    volume_ = std::make_unique<GpuImage>(
        device_, VK_FORMAT_R16G16B16A16_SFLOAT, VkExtent2D{v.width, v.height},
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "host froxel volume", 1, 0,
        v.depth);
    volumeReadback_ = std::make_unique<rg::HostBuffer>(
        device_, VkDeviceSize{v.width} * v.height * v.depth * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
        "froxel volume readback");
    layOutAsGeneral(device_, volume_->image());
}

FrameOutput EngineRenderer::render(const RenderOptions& options) {
    const VkDeviceSize pixels = size_t{size_.width} * size_.height;
    if (options.exportVolume) prepareVolume(options);
    const bool volume = options.exportVolume && volume_;
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
    // The plugin leaves its images in TRANSFER_SRC_OPTIMAL for the copies; they go back to
    // GENERAL, where the next frame expects them.
    auto transition = [&](VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 dst,
                          VkAccessFlags2 dstAccess) {
        VkImageMemoryBarrier2 b[3] = {{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2},
                                      {VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2},
                                      {VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2}};
        VkImage images[3] = {color_->image()};
        uint32_t count = 1;
        if (options.linOut) images[count++] = inscatter_->image();
        if (volume) images[count++] = volume_->image();
        for (uint32_t i = 0; i < count; ++i) {
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
        d.imageMemoryBarrierCount = count;
        d.pImageMemoryBarriers = b;
        vkCmdPipelineBarrier2(cmd_, &d);
    };
    rg::recordReadback(device_, cmd_, color_->image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, size_,
                       colorBuffer.buffer());
    if (options.linOut)
        rg::recordReadback(device_, cmd_, inscatter_->image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           size_, linBuffer.buffer());
    if (volume)
        rg::recordReadback(device_, cmd_, volume_->image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           volume_->extent(), volumeReadback_->buffer(), VK_IMAGE_ASPECT_COLOR_BIT,
                           1, volume_->depth());
    transition(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
               VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
               VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
    RG_VK(vkEndCommandBuffer(cmd_));
    device_.submitAndWait(cmd_, fence_);

    FrameOutput out = timings();
    out.color.resize(pixels * 4);
    const auto* halves = static_cast<const uint16_t*>(colorBuffer.data());
    for (size_t i = 0; i < out.color.size(); ++i) out.color[i] = glm::unpackHalf1x16(halves[i]);
    if (options.linOut) {
        out.inscatter.resize(pixels * 4);
        std::memcpy(out.inscatter.data(), linBuffer.data(), pixels * 16);
    }
    if (volume) {
        out.volumeLayout = lightscatter::froxelVolume(
            describe(options, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE));
        out.volume.resize(size_t{volume_->extent().width} * volume_->extent().height *
                          volume_->depth() * 4);
        const auto* texels = static_cast<const uint16_t*>(volumeReadback_->data());
        for (size_t i = 0; i < out.volume.size(); ++i)
            out.volume[i] = glm::unpackHalf1x16(texels[i]);
    }
    return out;
}

}  // namespace host
