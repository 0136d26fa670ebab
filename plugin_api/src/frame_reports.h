#pragma once
// What a recorded frame's report says besides its timestamps: the method of each light and of the
// frame, why, and what each method assumes; kept until the frame's times are read.
#include <memory>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "graph_cache.h"
#include "method_choice.h"
#include "step_counters.h"

namespace lightscatter::detail {

struct RecordedFrame {
    uint64_t frame = 0;
    std::shared_ptr<Running> graph;  // the graph it was recorded with
    std::string method, reason, notice;
    std::vector<FrameReport::Light> lights;  // in the engine's order
    std::vector<std::string> passNames;
    std::vector<std::string> setupPasses;
    std::vector<PassTime> cpuWork;
    // The method whose chains added into its step counter, and how many bytes of it; null: none.
    const ls::MethodUnit* stepCounter = nullptr;
    uint64_t stepBytes = 0;
    bool graphCompiled = false;
};

// The frame's and each light's methods, reasons and notices into `f`. Each light's `choices`,
// `settings` and `values` in the order of the frame's lights (their ids); `given` each one's place
// in the engine's list, which FrameReport::lights follows.
void describeMethods(RecordedFrame& f, const GraphConfig& c, const std::string& summary,
                     const std::vector<MethodChoice>& choices,
                     const std::vector<Settings>& settings,
                     const std::vector<ls::LightFrame>& values, const std::vector<size_t>& given);

// The report of a recorded frame, with its times once the GPU has finished it.
FrameReport reportOf(const RecordedFrame& f, const std::string& device, VkFormat depthStencil,
                     const StepCounters& steps);

}  // namespace lightscatter::detail
