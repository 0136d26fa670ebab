#include "frame_reports.h"

#include <algorithm>

#include "rendergraph/format_info.h"

namespace lightscatter::detail {
namespace {

// What changed this frame without a rebuild (epipolar's cube faces reaching the view), per light
// that has a chain.
std::string frameNotes(const GraphConfig& c, const std::vector<ls::LightFrame>& values) {
    std::string notes;
    for (size_t i = 0; i < c.lights.size(); ++i) {
        if (!c.lights[i].touchesView) continue;
        const std::string note = c.lights[i].method->frameNote(values[i], c.lights[i].chain);
        if (note.empty()) continue;
        notes += c.lights.size() == 1 ? "; " + note : "; light " + std::to_string(i) + "'s " + note;
    }
    return notes;
}

}  // namespace

// The frame's method: that of every light with a chain, each named once in the engine's order
// ("none" without one). With one method for every light, the reason is Auto's for the first light
// that has a chain, or the frame's summary; with several, the summary, which names each light's.
void describeMethods(RecordedFrame& f, const GraphConfig& c, const std::string& summary,
                     const std::vector<MethodChoice>& choices,
                     const std::vector<Settings>& settings,
                     const std::vector<ls::LightFrame>& values, const std::vector<size_t>& given) {
    const size_t n = c.lights.size();
    f.lights.assign(n, FrameReport::Light{});
    std::vector<size_t> inGivenOrder(n);
    for (size_t i = 0; i < n; ++i) {
        const MethodChoice& choice = choices[i];
        const bool chain = c.lights[i].touchesView;
        FrameReport::Light& l = f.lights[given[i]];
        l.method = chain ? methodName(choice.method) : "none";
        l.reason = !choice.reason.empty() ? choice.reason
                   : chain                ? c.lights[i].method->summary(c.lights[i].chain)
                           : "the light reaches no view ray (or nothing scatters): no chain";
        l.notice = choice.notice;
        l.settings = settings[i];
        inGivenOrder[given[i]] = i;
    }
    std::vector<std::string> names;
    const MethodChoice* first = nullptr;
    for (size_t k = 0; k < n; ++k) {
        const size_t i = inGivenOrder[k];
        if (!c.lights[i].touchesView) continue;
        if (!first) first = &choices[i];
        if (std::find(names.begin(), names.end(), f.lights[k].method) == names.end())
            names.push_back(f.lights[k].method);
    }
    if (names.empty()) {
        f.method = "none";
        f.reason = choices[0].reason.empty() ? summary : choices[0].reason;
        f.notice = choices[0].notice;
    } else {
        for (size_t k = 0; k < names.size(); ++k) f.method += (k ? "+" : "") + names[k];
        f.reason = names.size() == 1 && n == 1 && !first->reason.empty() ? first->reason : summary;
        // The notices of the lights' methods, each once.
        for (const FrameReport::Light& l : f.lights)
            if (!l.notice.empty() && f.notice.find(l.notice) == std::string::npos)
                f.notice += (f.notice.empty() ? "" : "; ") + l.notice;
    }
    f.reason += frameNotes(c, values);
}

FrameReport reportOf(const RecordedFrame& f, const std::string& device, VkFormat depthStencil,
                     const StepCounters& steps) {
    const rg::FrameTimings t = f.graph->executor->readTimings(f.frame);
    FrameReport r;
    r.frame = f.frame;
    r.timed = t.valid;
    r.device = device;
    r.depthStencilFormat = rg::formatName(depthStencil);
    if (t.valid) {
        for (const auto& p : t.passes) r.passes.push_back({p.name, p.milliseconds, p.samples});
        r.totalMilliseconds = t.totalMilliseconds;
        if (f.stepCounter) r.steps = steps.read(f.frame, f.stepBytes, *f.stepCounter);
    }
    r.passNames = f.passNames;
    r.method = f.method;
    r.reason = f.reason;
    r.notice = f.notice;
    r.lights = f.lights;
    r.setupPasses = f.setupPasses;
    r.graphCompiled = f.graphCompiled;
    r.cpuWork = f.cpuWork;
    return r;
}

}  // namespace lightscatter::detail
