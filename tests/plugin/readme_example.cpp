// The integration example of docs/integration.md. integration_doc_sync_test.cpp checks that the
// page quotes this file's marked block verbatim; readme_example_gpu_test.cpp and the consumer
// projects (tests/consumer/) run it.
#include "readme_example.h"

#include <memory>

uint64_t recordLightShafts(Engine& engine) {
    // [integration-example]
    // Once: the plugin works on the engine's own device and queue (the engine resets it before
    // destroying them). The engine keeps two frames in flight: when it records a frame, the one
    // two frames back has completed (its fence). The plugin never waits for the GPU.
    if (!engine.lightShafts) {
        lightscatter::PluginCreateInfo info;
        info.context = engine.context;
        info.framesInFlight = 2;
        engine.lightShafts = std::make_unique<lightscatter::Plugin>(info);
    }

    // Every frame: the engine's images, where they stand and where to leave them.
    lightscatter::FrameDescription frame;
    frame.depth = {engine.depth, VK_FORMAT_D32_SFLOAT, engine.extent, VK_IMAGE_USAGE_SAMPLED_BIT,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    frame.depth.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    frame.color = {engine.hdrColor, VK_FORMAT_R16G16B16A16_SFLOAT, engine.extent,
                   VK_IMAGE_USAGE_STORAGE_BIT, VK_IMAGE_LAYOUT_GENERAL};
    frame.color.finalLayout = VK_IMAGE_LAYOUT_GENERAL;

    // The near and far planes are read from the projection.
    frame.camera.view = engine.view;
    frame.camera.projection = engine.projection;

    // The lights, each with its own shadow map (or none). One light may go in frame.light and
    // frame.shadowMap instead.
    lightscatter::LightInput spot;
    spot.light.type = lightscatter::LightType::Spot;
    spot.light.position = {0.0f, 6.0f, 0.0f};
    spot.light.direction = {0.0f, -1.0f, 0.0f};
    spot.light.intensity = {40.0f, 38.0f, 35.0f};  // W/sr
    spot.light.innerConeAngleDegrees = 25.0f;      // full intensity within 25 degrees of its axis,
    spot.light.outerConeAngleDegrees = 30.0f;      // none beyond 30 (KHR_lights_punctual's falloff)
    spot.light.shadowViewProjection = engine.lightViewProjection;
    spot.light.shadowMapSize = 1024;
    const VkExtent2D mapExtent{spot.light.shadowMapSize, spot.light.shadowMapSize};
    spot.shadowMap = lightscatter::ImageInput{engine.shadowMap, VK_FORMAT_D32_SFLOAT, mapExtent,
                                              VK_IMAGE_USAGE_SAMPLED_BIT,
                                              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    spot.shadowMap->finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    // Optional: this light's own settings; without them it takes frame.profile.
    spot.settings = lightscatter::profileSettings(lightscatter::Profile::Balanced);
    lightscatter::LightInput sun;  // no shadow map: its closed form
    sun.light.type = lightscatter::LightType::Directional;
    sun.light.direction = {0.3f, -1.0f, 0.2f};
    sun.light.intensity = {0.5f, 0.5f, 0.45f};  // W/m^2
    frame.lights = {spot, sun};

    frame.medium.betaM = {0.03f, 0.03f, 0.03f};  // 1/m
    frame.method = lightscatter::Method::Epipolar;
    frame.profile = lightscatter::Profile::HighPerformance;

    // Throws lightscatter::InvalidInput, naming the field, before recording anything.
    const uint64_t frameNumber = engine.lightShafts->record(engine.commandBuffer, frame);
    // Once the engine's fence says this command buffer has run, report(frameNumber) gives the GPU
    // time of each of its passes.
    // [integration-example]
    return frameNumber;
}
