#pragma once
// The pipelines and samplers of one device, shared by every plugin on it (views of one engine, or
// plugins on several threads).
#include <lightscatter/lightscatter.h>
#include "rendergraph/device.h"
#include "shared/shared_state.h"

namespace lightscatter::detail {

// The engine's device as the runtime takes it, from a creation checked before anything is made
// from it (InvalidInput for a missing handle, a Vulkan version below 1.3 or a missing feature, or
// framesInFlight out of its range).
rg::ExternalDevice externalDevice(const PluginCreateInfo& info);

// The device's shared state, made for the first plugin on it and kept while one lives, with what
// `info`'s context says of the device's optional features. Plugins that load Vulkan differently,
// allocate differently, or are told of other optional features keep theirs apart.
ls::Shared sharedFor(const PluginCreateInfo& info);

}  // namespace lightscatter::detail
