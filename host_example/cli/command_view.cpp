// lightscatter view SCENE.json [--method NAME] [--profile NAME] [--size WxH] [--frames N]
//   [--screenshot FILE.png] [--resize-at FRAME --resize-to WxH]
//   [--animate-light] [--resizes N] [--memory-log FILE.csv]   (the soak test's options)
// A GLFW window: WASD/QE move the camera, left-drag looks around, arrow keys move the selected
// light (L selects the next of a scene's "lights"), M
// cycles the methods, P cycles profiles, T toggles the min/max trees, N steps the planes method's
// scrolling noise (0, 0.25, 0.5, 1), Esc quits. The title shows the method, profile and noise, and
// the plugin's GPU time per pass. Resizing rebuilds the graphs. Every frame carries the seconds
// since the window opened, which scroll the noise.
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <unistd.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "command_options.h"
#include "commands.h"
#include "fullscreen_vert.h"
#include "image_io.h"
#include "output_set.h"
#include "panel_script.h"
#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/memory_counter.h"
#include "rendergraph/pipeline.h"
#include "rendergraph/vk_error.h"
#include "scene/medium_json.h"
#include "scene_inputs.h"
#include "settings_fields.h"
#include "settings_panel.h"
#include "swapchain.h"
#include "temp_files.h"
#include "tonemap_frag.h"
#include "ui_overlay.h"

namespace host {
namespace {

struct GlfwSession {
    GlfwSession() {
        if (!glfwInit())
            throw std::runtime_error(
                "view: cannot open a window: GLFW found no display (set DISPLAY, "
                "or run under xvfb-run -a)");
    }
    ~GlfwSession() { glfwTerminate(); }
};

struct Window {
    GLFWwindow* handle;
    Window(VkExtent2D size, const std::string& title) {
        glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
        handle = glfwCreateWindow(static_cast<int>(size.width), static_cast<int>(size.height),
                                  title.c_str(), nullptr, nullptr);
        if (!handle) throw std::runtime_error("view: cannot create a window");
    }
    ~Window() { glfwDestroyWindow(handle); }
};

struct Surface {
    VkInstance instance;
    VkSurfaceKHR handle = VK_NULL_HANDLE;
    Surface(VkInstance i, GLFWwindow* w) : instance(i) {
        RG_VK(glfwCreateWindowSurface(i, w, nullptr, &handle));
    }
    ~Surface() { vkDestroySurfaceKHR(instance, handle, nullptr); }
};

// Tone maps the engine's HDR color into a swapchain image (and reads that image back when asked).
class Display {
  public:
    // `pipeline` outlives displays: a resize builds a new display but keeps the pipeline.
    // `overlay`: the interface draws over the image after this graph (UiOverlay), so the graph
    // leaves it a color attachment, and the screenshot, in a graph of its own, comes after both.
    Display(const rg::Device& device, const GpuImage& hdr, const Swapchain& swapchain,
            float exposure, bool screenshot, std::shared_ptr<rg::Pipeline> pipeline, bool overlay)
        : device_(device), samplers_(device), exposure_(exposure), pipeline_(std::move(pipeline)) {
        graph_.setScreenExtent(swapchain.extent());
        shotGraph_.setScreenExtent(swapchain.extent());
        rg::ImportedImage h;
        h.image = hdr.image();
        h.format = hdr.format();
        h.extent = hdr.extent();
        h.usage = hdr.usage();
        h.initialLayout = VK_IMAGE_LAYOUT_GENERAL;
        h.initialStages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        h.initialAccess = VK_ACCESS_2_MEMORY_WRITE_BIT;
        h.finalLayout = VK_IMAGE_LAYOUT_GENERAL;
        hdr_ = graph_.importImage("host hdr color", h);
        rg::ImportedImage s;
        s.image = swapchain.image(0);
        s.format = swapchain.format();
        s.extent = swapchain.extent();
        s.usage = swapchain.usage();
        s.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        s.initialStages = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;  // the acquire's wait
        s.initialAccess = VK_ACCESS_2_NONE;
        s.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
        s.finalStages = VK_PIPELINE_STAGE_2_NONE;
        s.finalAccess = VK_ACCESS_2_NONE;
        if (overlay) {
            s.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
            s.finalStages = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
            s.finalAccess = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
        }
        target_ = graph_.importImage("swapchain image", s);
        swapchainDesc_ = s;

        auto pass = graph_.addPass("tone map to window", rg::PassType::Graphics);
        pass.sampled(hdr_);
        target_ = pass.colorAttachment(target_, rg::LoadOp::DontCare);
        const rg::ImageRef src = hdr_;
        pass.execute([this, src](rg::PassContext& ctx) {
            if (!*pipeline_) {
                rg::GraphicsPipelineDesc d;
                d.vertex = rg::spirv(ls_spirv::fullscreen_vert);
                d.fragment = rg::spirv(ls_spirv::tonemap_frag);
                d.formats = ctx.renderingFormats();
                d.bindings = {
                    {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};
                d.pushConstantBytes = 4;
                *pipeline_ = rg::Pipeline::graphics(ctx.device(), "tone map to window", d);
            }
            pipeline_->bind(ctx.cmd());
            rg::DescriptorPush()
                .sampled(0, ctx.view(src), ctx.layout(src), samplers_.nearest())
                .push(ctx.device(), ctx.cmd(), *pipeline_);
            pipeline_->push(ctx.cmd(), exposure_);
            vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
        });
        const rg::VulkanDeviceCaps caps(device);
        if (screenshot) {
            const VkExtent2D e = swapchain.extent();
            readback_ =
                std::make_unique<rg::HostBuffer>(device, VkDeviceSize{4} * e.width * e.height,
                                                 VK_BUFFER_USAGE_TRANSFER_DST_BIT, "screenshot");
            if (overlay) {
                // After the interface: the image as its render pass left it.
                rg::ImportedImage after = s;
                after.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
                after.initialStages = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
                after.initialAccess = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
                after.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
                after.finalStages = VK_PIPELINE_STAGE_2_NONE;
                after.finalAccess = VK_ACCESS_2_NONE;
                shotTarget_ = shotGraph_.importImage("swapchain image", after);
                shotDesc_ = after;
                addScreenshot(shotGraph_, shotTarget_, e);
                shotExecutor_ = std::make_unique<rg::GraphExecutor>(device, shotGraph_,
                                                                    rg::compile(shotGraph_, caps));
            } else {
                addScreenshot(graph_, target_, e);
            }
        }
        executor_ = std::make_unique<rg::GraphExecutor>(device, graph_, rg::compile(graph_, caps));
    }
    ~Display() {
        shotExecutor_.reset();
        executor_.reset();
    }

    void record(VkCommandBuffer cmd, VkImage swapchainImage) {
        swapchainDesc_.image = swapchainImage;
        graph_.updateImport(target_, swapchainDesc_);
        executor_->record(cmd);
    }
    // After the interface: the screenshot's copy (and the image's way to presentation).
    void recordAfterOverlay(VkCommandBuffer cmd, VkImage swapchainImage) {
        if (!shotExecutor_) return;
        shotDesc_.image = swapchainImage;
        shotGraph_.updateImport(shotTarget_, shotDesc_);
        shotExecutor_->record(cmd);
    }
    // The interface leaves the image for the screenshot graph rather than for presentation.
    bool keepsForScreenshot() const { return shotExecutor_ != nullptr; }
    // RGBA8 of the last recorded frame (after the engine waited for it); BGRA swapchains swizzled.
    std::vector<uint8_t> screenshot(VkFormat format) const {
        std::vector<uint8_t> px(readback_->size());
        std::memcpy(px.data(), readback_->data(), px.size());
        if (format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_B8G8R8A8_UNORM)
            for (size_t i = 0; i + 3 < px.size(); i += 4) std::swap(px[i], px[i + 2]);
        return px;
    }

  private:
    void addScreenshot(rg::RenderGraph& graph, rg::ImageRef image, VkExtent2D e) {
        rg::BufferRef buf = graph.importBuffer("screenshot", readback_->asReadback());
        auto copy = graph.addPass("screenshot", rg::PassType::Transfer);
        copy.transferSrc(image);
        buf = copy.transferDst(buf);
        copy.execute([image, buf, e](rg::PassContext& ctx) {
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {e.width, e.height, 1};
            vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(image), ctx.layout(image), ctx.buffer(buf),
                                   1, &region);
        });
    }

    const rg::Device& device_;
    rg::Samplers samplers_;
    float exposure_;
    rg::RenderGraph graph_, shotGraph_;
    rg::ImageRef hdr_, target_, shotTarget_;
    rg::ImportedImage swapchainDesc_, shotDesc_;
    std::shared_ptr<rg::Pipeline> pipeline_;
    std::unique_ptr<rg::HostBuffer> readback_;
    std::unique_ptr<rg::GraphExecutor> executor_, shotExecutor_;
};

struct Controls {
    bool dragging = false;
    double lastX = 0, lastY = 0;
};

// `keys` and `mouse`: whether the interface left them to the camera.
void moveCamera(GLFWwindow* w, CameraDesc& cam, float speed, float dt, Controls& c, bool keys,
                bool mouse) {
    glm::vec3 forward = glm::normalize(cam.target - cam.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, cam.up));
    glm::vec3 move(0.0f);
    auto held = [&](int key) { return keys && glfwGetKey(w, key) == GLFW_PRESS; };
    if (held(GLFW_KEY_W)) move += forward;
    if (held(GLFW_KEY_S)) move -= forward;
    if (held(GLFW_KEY_D)) move += right;
    if (held(GLFW_KEY_A)) move -= right;
    if (held(GLFW_KEY_E)) move += cam.up;
    if (held(GLFW_KEY_Q)) move -= cam.up;
    const glm::vec3 delta = move * speed * dt;
    cam.position += delta;
    cam.target += delta;
    double x, y;
    glfwGetCursorPos(w, &x, &y);
    const bool down = mouse && glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    if (down && c.dragging) {
        const float yaw = static_cast<float>(x - c.lastX) * -0.004f;
        const float pitch = static_cast<float>(y - c.lastY) * -0.004f;
        glm::mat4 r = glm::rotate(glm::mat4(1.0f), yaw, cam.up);
        r = glm::rotate(r, pitch, right);
        forward = glm::vec3(r * glm::vec4(forward, 0.0f));
        if (std::fabs(glm::dot(glm::normalize(forward), cam.up)) < 0.995f)
            cam.target = cam.position + forward * glm::length(cam.target - cam.position);
    }
    c.dragging = down;
    c.lastX = x;
    c.lastY = y;
}

void moveLight(GLFWwindow* w, LightDesc& light, float speed, float dt, bool keys) {
    if (!keys) return;
    glm::vec2 m(0.0f);
    if (glfwGetKey(w, GLFW_KEY_LEFT) == GLFW_PRESS) m.x -= 1;
    if (glfwGetKey(w, GLFW_KEY_RIGHT) == GLFW_PRESS) m.x += 1;
    if (glfwGetKey(w, GLFW_KEY_UP) == GLFW_PRESS) m.y += 1;
    if (glfwGetKey(w, GLFW_KEY_DOWN) == GLFW_PRESS) m.y -= 1;
    if (m == glm::vec2(0.0f)) return;
    if (light.type == lightscatter::LightType::Directional) {  // turn the sun
        glm::mat4 r = glm::rotate(glm::mat4(1.0f), m.x * dt * 0.6f, glm::vec3(0, 1, 0));
        r = glm::rotate(r, m.y * dt * 0.3f, glm::vec3(1, 0, 0));
        light.direction = glm::normalize(glm::vec3(r * glm::vec4(light.direction, 0.0f)));
    } else {
        light.position += glm::vec3(m.x, 0.0f, -m.y) * speed * dt;
    }
}

// Moves the light on a slow circle (a point or spot light's position, a sun's direction), so that
// long runs exercise changing frame constants, shadow maps and light-volume tests.
void animateLight(LightDesc& light, const LightDesc& start, int frame) {
    const float angle = static_cast<float>(frame) * 0.01f;
    const glm::mat4 r = glm::rotate(glm::mat4(1.0f), angle, glm::vec3(0, 1, 0));
    if (light.type == lightscatter::LightType::Directional) {
        light.direction = glm::normalize(glm::vec3(r * glm::vec4(start.direction, 0.0f)));
    } else {
        light.position = start.position + glm::vec3(std::cos(angle), 0.0f, std::sin(angle)) * 0.5f;
        light.direction = glm::normalize(glm::vec3(r * glm::vec4(start.direction, 0.0f)));
    }
}

// The size the window takes at the k-th of a soak's resizes: 60%, 80% and 100% of the start, in
// turn, so that three resizes have shown every size and memory has its high-water mark.
VkExtent2D soakSize(VkExtent2D base, int k) {
    const float f = 0.6f + 0.2f * static_cast<float>(k % 3);
    return {std::max(16u, static_cast<uint32_t>(static_cast<float>(base.width) * f)),
            std::max(16u, static_cast<uint32_t>(static_cast<float>(base.height) * f))};
}

// Whether a method takes the light as the scene has it: its type, its shadow map, its cookie.
bool takesLight(const lightscatter::MethodInfo& m, const LightDesc& l) {
    using lightscatter::LightType;
    if (!(l.type == LightType::Directional ? m.directional
          : l.type == LightType::Spot      ? m.spot
                                           : m.point))
        return false;
    const bool shadowed = l.shadowMapSize > 0;
    if (shadowed && !(l.type == LightType::Point ? m.cubeShadow : m.shadowMap)) return false;
    return !l.cookie || (shadowed ? m.lightColor : m.unshadowedLightColor);
}

// The title's word on the noise: nothing when it is off.
std::string noiseTitle(float amplitude, lightscatter::Method method) {
    if (amplitude <= 0.0f) return "";
    char buf[64];
    std::snprintf(buf, sizeof buf, " / noise %g%s", static_cast<double>(amplitude),
                  honours(method, &lightscatter::MethodInfo::noise) ? "" : " (off: not honoured)");
    return buf;
}

// Resident set size of this process, in KiB (Linux).
long residentKiB() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

}  // namespace

int runView(Args& args) {
    const std::string screenshotPath = args.take("--screenshot", "");
    SceneOptions o = takeSceneOptions(args, "960x540");
    o.render.linOut = false;  // a window shows the color alone
    const std::string framesText = args.take("--frames", "");
    const std::string resizeAt = args.take("--resize-at", "");
    const std::string resizeTo = args.take("--resize-to", "");
    const bool animate = args.flag("--animate-light");
    const std::string resizesText = args.take("--resizes", "");
    const std::string memoryLogPath = args.take("--memory-log", "");
    const bool noPanel = args.flag("--no-panel");
    const std::string scriptPath = args.take("--panel-script", "");
    const std::string reportLogPath = args.take("--report-log", "");
    const std::string scenePath = args.positional("SCENE.json");
    args.finish();
    const int frameLimit = framesText.empty() ? 0 : parseCount(framesText, "--frames");
    const int resizeFrame = resizeAt.empty() ? -1 : parseCount(resizeAt, "--resize-at");
    const VkExtent2D resizeSize =
        resizeTo.empty() ? VkExtent2D{0, 0} : parseSize(resizeTo, "--resize-to");
    if ((resizeFrame > 0) != (resizeSize.width > 0))
        throw std::runtime_error("view: --resize-at and --resize-to go together");
    if (!screenshotPath.empty() && frameLimit == 0)
        throw std::runtime_error(
            "view: --screenshot needs --frames (the screenshot is of the last frame)");
    if (!scriptPath.empty() && (noPanel || frameLimit == 0))
        throw std::runtime_error(
            "view: --panel-script drives the panel: it needs --frames and no --no-panel");
    const int resizes = resizesText.empty() ? 0 : parseCount(resizesText, "--resizes");
    if (resizes > 0 && frameLimit <= resizes)
        throw std::runtime_error(
            "view: --resizes needs --frames, larger than the number of resizes");

    const SceneDesc scene = loadSceneFile(scenePath);
    const MeshData mesh = loadSceneMeshes(scene);
    for (const auto& w : mesh.warnings) std::cerr << "lightscatter: warning: " << w << "\n";
    const VkExtent2D size = sceneSize(o, {960, 540});
    // The screenshot and the memory log are checked before the window opens and written together
    // when the window closes, like render's outputs: all or nothing.
    OutputSet outputs;
    addSceneInputs(outputs, scenePath, scene, mesh, "the scene");
    if (!o.settingsPath.empty()) outputs.addInput("the settings file", o.settingsPath);
    if (!scriptPath.empty()) outputs.addInput("the panel script", scriptPath);
    if (!screenshotPath.empty()) outputs.add("--screenshot", screenshotPath);
    if (!memoryLogPath.empty()) outputs.add("--memory-log", memoryLogPath);
    if (!reportLogPath.empty()) outputs.add("--report-log", reportLogPath);
    const PanelScript script = scriptPath.empty() ? PanelScript() : PanelScript(scriptPath);
    // A script's saves follow the outputs' rules, checked now: a save that could not happen (after
    // the last frame, into a missing folder, onto a directory) or that would replace an input or
    // another output used to pass without a word, or replace the scene.
    for (const auto& [step, path] : script.saves()) {
        const std::string what =
            "--panel-script " + scriptPath + ": step " + std::to_string(step) + " saves";
        if (static_cast<long>(step) >= frameLimit)
            throw std::runtime_error(what + " " + path + ", but --frames " +
                                     std::to_string(frameLimit) + " ends before step " +
                                     std::to_string(step) + " is made");
        outputs.check(what, path);
        checkSettingsSaveTarget(path);
        TempFile probe(path, what);  // its folder exists and takes a file
    }
    nlohmann::json reportLog = nlohmann::json::array();
    std::string memoryLog = "frame,rss_kib,device_bytes\n";

    GlfwSession glfw;
    if (!glfwVulkanSupported()) throw std::runtime_error("view: GLFW finds no Vulkan loader");
    uint32_t extCount = 0;
    const char** exts = glfwGetRequiredInstanceExtensions(&extCount);
    for (uint32_t i = 0; i < extCount; ++i) o.device.instanceExtensions.emplace_back(exts[i]);
    o.device.swapchain = true;
    Window window(size, "lightscatter");
    rg::Device device(o.device);
    Surface surface(device.instance(), window.handle);
    Swapchain swapchain(device, surface.handle, size);
    EngineRenderer renderer(device, scene, mesh, swapchain.extent());
    std::unique_ptr<UiOverlay> ui;
    if (!noPanel) ui = std::make_unique<UiOverlay>(device, window.handle, swapchain);
    SettingsPanel panel;
    panel.setSaveCheck(
        [&outputs](const std::string& path) { outputs.check("save settings", path); });
    bool panelVisible = true;
    std::unique_ptr<Display> display;
    const auto displayPipeline = std::make_shared<rg::Pipeline>();
    auto rebuildDisplay = [&](bool screenshot) {
        display.reset();
        display = std::make_unique<Display>(device, renderer.color(), swapchain, scene.exposure,
                                            screenshot, displayPipeline, ui != nullptr);
        if (ui) ui->swapchainChanged(swapchain);
    };
    rebuildDisplay(false);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = device.queueFamily();
    VkCommandPool pool;
    RG_VK(vkCreateCommandPool(device.device(), &poolInfo, nullptr, &pool));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd;
    RG_VK(vkAllocateCommandBuffers(device.device(), &alloc, &cmd));
    VkSemaphoreCreateInfo semInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore acquired;
    RG_VK(vkCreateSemaphore(device.device(), &semInfo, nullptr, &acquired));
    std::vector<VkSemaphore> finished(swapchain.imageCount());
    for (auto& s : finished) RG_VK(vkCreateSemaphore(device.device(), &semInfo, nullptr, &s));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    VkFence fence;
    RG_VK(vkCreateFence(device.device(), &fenceInfo, nullptr, &fence));

    RenderOptions options = o.render;
    Controls controls;
    const float speed =
        std::max(glm::length(renderer.bounds().max - renderer.bounds().min) * 0.15f, 1.0f);
    const std::array profiles{
        lightscatter::Profile::HighQuality,     lightscatter::Profile::Balanced,
        lightscatter::Profile::HighPerformance, lightscatter::Profile::LowHighQuality,
        lightscatter::Profile::LowBalanced,     lightscatter::Profile::LowHighPerformance};
    // N steps the noise's amplitude through these; it starts at the --settings file's.
    constexpr std::array kNoiseSteps{0.0f, 0.25f, 0.5f, 1.0f};
    bool keyM = false, keyP = false, keyT = false, keyN = false, keyL = false, keyF1 = false;
    // What the plugin accepted last: an edit it refuses is undone to this (the camera excepted).
    RenderOptions good = options;
    std::vector<LightDesc> goodLights;
    for (size_t i = 0; i < renderer.scene().lightCount(); ++i)
        goodLights.push_back(renderer.scene().lightAt(i));
    MediumDesc goodMedium = renderer.scene().medium;
    lightscatter::FrameReport lastReport;
    std::vector<std::pair<long, std::string>> frameSteps{{-1, ""}};  // by the plugin's frame
    std::vector<nlohmann::json> frameMedia{nullptr};  // the medium each frame ran with
    auto logReport = [&](const lightscatter::FrameReport& r) {
        lastReport = r;
        if (reportLogPath.empty() || r.frame == 0 || r.frame >= frameSteps.size()) return;
        nlohmann::json e = {{"frame", r.frame},
                            {"step", frameSteps[r.frame].first},
                            {"refused", frameSteps[r.frame].second},
                            {"method", r.method},
                            {"reason", r.reason},
                            {"medium", frameMedia[r.frame]}};
        e["lights"] = nlohmann::json::array();
        for (const auto& l : r.lights) {
            nlohmann::json fields = nlohmann::json::object();
            for (const SettingField& f : settingFields()) fields[f.name] = fieldJson(l.settings, f);
            e["lights"].push_back({{"method", l.method}, {"settings", fields}});
        }
        reportLog.push_back(e);
    };
    size_t selectedLight = 0;  // the light the arrow keys move; L selects the next
    const auto start = std::chrono::steady_clock::now();
    auto last = start;
    double titleClock = 0.0;
    int frame = 0;
    bool firstWait = true;
    int exitCode = 0;
    std::string screenshotNote;  // set once the screenshot is written
    while (!glfwWindowShouldClose(window.handle)) {
        glfwPollEvents();
        if (glfwGetKey(window.handle, GLFW_KEY_ESCAPE) == GLFW_PRESS) break;
        const auto now = std::chrono::steady_clock::now();
        const float dt = std::min(std::chrono::duration<float>(now - last).count(), 0.1f);
        last = now;
        const bool keys = !(ui && ui->wantsKeyboard()), mouse = !(ui && ui->wantsMouse());
        moveCamera(window.handle, renderer.scene().camera, speed, dt, controls, keys, mouse);
        moveLight(window.handle, renderer.scene().lightAt(selectedLight), speed, dt, keys);
        if (animate) animateLight(renderer.scene().light, scene.light, frame);
        if (resizes > 0 && frame > 0 && frame % (frameLimit / (resizes + 1)) == 0 &&
            frame / (frameLimit / (resizes + 1)) <= resizes) {
            const VkExtent2D to = soakSize(size, frame / (frameLimit / (resizes + 1)));
            glfwSetWindowSize(window.handle, static_cast<int>(to.width),
                              static_cast<int>(to.height));
        }
        auto pressed = [&](int key, bool& held) {
            const bool down = keys && glfwGetKey(window.handle, key) == GLFW_PRESS;
            const bool edge = down && !held;
            held = down;
            return edge;
        };
        if (pressed(GLFW_KEY_F1, keyF1)) panelVisible = !panelVisible;
        if (pressed(GLFW_KEY_L, keyL))
            selectedLight = (selectedLight + 1) % renderer.scene().lightCount();
        if (pressed(GLFW_KEY_M, keyM)) {
            // Auto, then every method that takes the scene's light (methodInfo()).
            std::vector<lightscatter::Method> methods{lightscatter::Method::Auto};
            for (const lightscatter::MethodInfo& m : lightscatter::methodInfo())
                if (takesLight(m, renderer.scene().light)) methods.push_back(m.method);
            auto it = std::find(methods.begin(), methods.end(), options.method);
            options.method =
                it == methods.end() || it + 1 == methods.end() ? methods[0] : *(it + 1);
        }
        if (pressed(GLFW_KEY_P, keyP)) {
            auto it = std::find(profiles.begin(), profiles.end(), options.profile);
            options.profile =
                it == profiles.end() || it + 1 == profiles.end() ? profiles[0] : *(it + 1);
        }
        if (pressed(GLFW_KEY_T, keyT))
            options.custom.epipolar.minMaxTrees = !options.custom.epipolar.minMaxTrees;
        if (pressed(GLFW_KEY_N, keyN)) {
            const float noise = options.custom.noiseAmplitude;
            const auto next = std::upper_bound(kNoiseSteps.begin(), kNoiseSteps.end(), noise);
            options.custom.noiseAmplitude = next == kNoiseSteps.end() ? kNoiseSteps[0] : *next;
        }
        options.timeSeconds = std::chrono::duration<double>(now - start).count();
        if (frame == resizeFrame)
            glfwSetWindowSize(window.handle, static_cast<int>(resizeSize.width),
                              static_cast<int>(resizeSize.height));

        RG_VK(vkWaitForFences(device.device(), 1, &fence, VK_TRUE, UINT64_MAX));
        if (!firstWait) {
            const FrameOutput t = renderer.timings();
            logReport(t.plugin);
            titleClock += dt;
            if (titleClock > 0.5 || frameLimit) {
                titleClock = 0.0;
                std::string title =
                    std::string("lightscatter - ") + lightscatter::methodName(options.method) +
                    (options.method == lightscatter::Method::Auto ? " (" + t.plugin.method + ")"
                                                                  : "") +
                    " / " + lightscatter::profileName(options.profile) +
                    noiseTitle(options.custom.noiseAmplitude, options.method) + " - " +
                    std::to_string(t.plugin.totalMilliseconds).substr(0, 6) + " ms";
                std::vector<lightscatter::PassTime> top = t.plugin.passes;
                std::sort(top.begin(), top.end(),
                          [](auto& a, auto& b) { return a.milliseconds > b.milliseconds; });
                for (size_t i = 0; i < top.size() && i < 3; ++i)
                    title += " | " + top[i].name + " " +
                             std::to_string(top[i].milliseconds).substr(0, 5);
                if (device.isCpu()) title += " (CPU timings)";
                glfwSetWindowTitle(window.handle, title.c_str());
            }
        }
        int fbw = 0, fbh = 0;
        glfwGetFramebufferSize(window.handle, &fbw, &fbh);
        if (fbw == 0 || fbh == 0) continue;  // minimised
        const bool lastFrame = frameLimit && frame + 1 == frameLimit;
        const VkExtent2D fb{static_cast<uint32_t>(fbw), static_cast<uint32_t>(fbh)};
        if (fb.width != swapchain.extent().width || fb.height != swapchain.extent().height) {
            swapchain.recreate(fb);
            renderer.resize(swapchain.extent());
            rebuildDisplay(lastFrame && !screenshotPath.empty());
            firstWait = true;
        } else if (lastFrame && !screenshotPath.empty()) {
            vkDeviceWaitIdle(device.device());
            rebuildDisplay(true);
        }
        uint32_t index = 0;
        const VkResult acq = vkAcquireNextImageKHR(device.device(), swapchain.handle(), UINT64_MAX,
                                                   acquired, VK_NULL_HANDLE, &index);
        if (acq == VK_ERROR_OUT_OF_DATE_KHR) {
            swapchain.recreate(fb);
            renderer.resize(swapchain.extent());
            rebuildDisplay(lastFrame && !screenshotPath.empty());
            continue;
        }
        if (acq != VK_SUBOPTIMAL_KHR) rg::check(acq, "vkAcquireNextImageKHR");
        // The panel's edits, then the script's step, then the plugin's word on them: what it
        // refuses is shown in the panel and undone, and the frame runs as the last one accepted.
        if (ui) {
            ui->beginFrame();
            if (panelVisible) {
                PanelStatus status;
                status.report = lastReport.frame ? &lastReport : nullptr;
                status.cpuDevice = device.isCpu();
                status.deviceBytes = rg::deviceMemoryInUse();
                if (options.custom.noiseAmplitude > 0.0f &&
                    !honours(options.method, &lightscatter::MethodInfo::noise))
                    status.note =
                        "the noise: " + methodsHonouring(&lightscatter::MethodInfo::noise, true) +
                        " only (this method runs without)";
                if (options.custom.lightModel == lightscatter::LightModel::Simplified &&
                    !honours(options.method, &lightscatter::MethodInfo::simplifiedModel))
                    status.note +=
                        std::string(status.note.empty() ? "" : "; ") + "the simplified model: " +
                        methodsHonouring(&lightscatter::MethodInfo::simplifiedModel, true) +
                        " only (this method runs the full one)";
                panel.draw(options, renderer.scene(), status);
            }
        }
        const long step = static_cast<size_t>(frame) < script.size() ? frame : -1;
        script.apply(static_cast<size_t>(frame), panel, options, renderer.scene());
        auto structure = [&] {
            std::vector<std::pair<lightscatter::LightType, uint32_t>> v;
            for (size_t i = 0; i < renderer.scene().lightCount(); ++i)
                v.emplace_back(renderer.scene().lightAt(i).type,
                               renderer.scene().lightAt(i).shadowMapSize);
            return v;
        };
        auto rebuildTargets = [&] {
            vkDeviceWaitIdle(device.device());
            renderer.resize(swapchain.extent());
            rebuildDisplay(lastFrame && !screenshotPath.empty());
        };
        if (panel.rebuildTargets()) rebuildTargets();
        // What runs of the options (options_as_run.h).
        RenderOptions run = asRun(options);
        std::string refusal;
        try {
            renderer.check(run);
            good = options;
            for (size_t i = 0; i < goodLights.size(); ++i)
                goodLights[i] = renderer.scene().lightAt(i);
            goodMedium = renderer.scene().medium;
            panel.refused("");
        } catch (const std::exception& e) {
            refusal = e.what();
            panel.refused(refusal);
            const auto before = structure();
            options = good;
            for (size_t i = 0; i < goodLights.size(); ++i)
                renderer.scene().lightAt(i) = goodLights[i];
            renderer.scene().medium = goodMedium;
            if (structure() != before) rebuildTargets();
            run = asRun(options);
            run.timeSeconds = std::chrono::duration<double>(now - start).count();
        }
        frameSteps.emplace_back(step, refusal);
        frameMedia.push_back(mediumJson(renderer.scene().medium));
        RG_VK(vkResetFences(device.device(), 1, &fence));
        RG_VK(vkResetCommandBuffer(cmd, 0));
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        RG_VK(vkBeginCommandBuffer(cmd, &begin));
        renderer.record(cmd, run, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                        VK_ACCESS_2_MEMORY_READ_BIT);
        display->record(cmd, swapchain.image(index));
        if (ui) {
            ui->record(cmd, index, display->keepsForScreenshot());
            display->recordAfterOverlay(cmd, swapchain.image(index));
        }
        RG_VK(vkEndCommandBuffer(cmd));
        VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
        wait.semaphore = acquired;
        wait.stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
        signal.semaphore = finished[index];
        signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        VkCommandBufferSubmitInfo cb{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
        cb.commandBuffer = cmd;
        VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
        submit.waitSemaphoreInfoCount = 1;
        submit.pWaitSemaphoreInfos = &wait;
        submit.commandBufferInfoCount = 1;
        submit.pCommandBufferInfos = &cb;
        submit.signalSemaphoreInfoCount = 1;
        submit.pSignalSemaphoreInfos = &signal;
        RG_VK(vkQueueSubmit2(device.queue(), 1, &submit, fence));
        VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
        present.waitSemaphoreCount = 1;
        present.pWaitSemaphores = &finished[index];
        const VkSwapchainKHR sc = swapchain.handle();
        present.swapchainCount = 1;
        present.pSwapchains = &sc;
        present.pImageIndices = &index;
        const VkResult pr = vkQueuePresentKHR(device.queue(), &present);
        if (pr != VK_ERROR_OUT_OF_DATE_KHR && pr != VK_SUBOPTIMAL_KHR)
            rg::check(pr, "vkQueuePresentKHR");
        firstWait = false;
        ++frame;
        if (!memoryLogPath.empty() && (frame % 100 == 0 || lastFrame))
            memoryLog += std::to_string(frame) + "," + std::to_string(residentKiB()) + "," +
                         std::to_string(rg::deviceMemoryInUse()) + "\n";
        if (lastFrame) {
            RG_VK(vkWaitForFences(device.device(), 1, &fence, VK_TRUE, UINT64_MAX));
            logReport(renderer.timings().plugin);
            if (!screenshotPath.empty()) {
                const VkExtent2D e = swapchain.extent();
                const std::vector<uint8_t> pixels = display->screenshot(swapchain.format());
                outputs.write(screenshotPath, encodePng(e.width, e.height, pixels), "PNG");
                screenshotNote = " (" + std::to_string(e.width) + "x" + std::to_string(e.height) +
                                 ", after " + std::to_string(frame) + " frames)";
            }
            break;
        }
    }
    vkDeviceWaitIdle(device.device());
    if (device.messageCount() > 0) {
        std::cerr << "lightscatter: the validation layer reported " << device.messageCount()
                  << " message(s)\n";
        exitCode = 3;
    }
    display.reset();
    ui.reset();
    vkDestroyFence(device.device(), fence, nullptr);
    for (auto s : finished) vkDestroySemaphore(device.device(), s, nullptr);
    vkDestroySemaphore(device.device(), acquired, nullptr);
    vkDestroyCommandPool(device.device(), pool, nullptr);
    if (!screenshotPath.empty() && screenshotNote.empty())
        throw std::runtime_error("view: --screenshot " + screenshotPath +
                                 ": the window was closed after " + std::to_string(frame) + " of " +
                                 std::to_string(frameLimit) + " frames; nothing was written");
    if (!memoryLogPath.empty()) outputs.writeText(memoryLogPath, memoryLog);
    if (!reportLogPath.empty()) outputs.writeText(reportLogPath, reportLog.dump(1) + "\n");
    outputs.commit();
    if (!screenshotPath.empty()) std::cout << "wrote " << screenshotPath << screenshotNote << "\n";
    return exitCode;
}

}  // namespace host
