#include "report.h"

#include <cstdio>
#include <sstream>

#include "format_info.h"

namespace rg {
namespace {

const char* passTypeName(PassType t) {
    switch (t) {
        case PassType::Graphics:
            return "graphics";
        case PassType::Compute:
            return "compute";
        case PassType::Transfer:
            return "transfer";
    }
    return "?";
}

std::string dotEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out;
}

std::string lifetimeText(const ResourcePlan& p) {
    if (!p.used) return "unused";
    return std::to_string(p.firstPass) + ".." + std::to_string(p.lastPass);
}

}  // namespace

std::string formatBytes(VkDeviceSize bytes) {
    char buf[64];
    const double b = static_cast<double>(bytes);
    if (bytes >= (VkDeviceSize{1} << 20))
        std::snprintf(buf, sizeof buf, "%.2f MiB", b / (1024.0 * 1024.0));
    else if (bytes >= 1024)
        std::snprintf(buf, sizeof buf, "%.1f KiB", b / 1024.0);
    else
        std::snprintf(buf, sizeof buf, "%llu B", static_cast<unsigned long long>(bytes));
    return buf;
}

nlohmann::json reportJson(const RenderGraph& graph, const CompiledGraph& compiled,
                          const FrameTimings* timings) {
    using nlohmann::json;
    json j;
    j["screen"] = {compiled.screen.width, compiled.screen.height};
    j["memorySizes"] = compiled.exactSizes ? "device" : "estimate";
    j["poisonTransients"] = compiled.poisonTransients;
    json passes = json::array();
    for (uint32_t pos = 0; pos < compiled.passes.size(); ++pos) {
        const PassPlan& plan = compiled.passes[pos];
        const PassDecl& decl = graph.passes()[plan.pass];
        json p;
        p["name"] = decl.name;
        p["type"] = passTypeName(decl.type);
        p["position"] = pos;
        p["barriers"] = plan.barriers.size();
        json uses = json::array();
        for (const auto& u : decl.uses) {
            json x;
            x["resource"] = graph.resource(u.resource).name;
            x["use"] = useKindName(u.kind);
            x["version"] = u.inVersion;
            if (u.outVersion != kInvalidIndex) x["produces"] = u.outVersion;
            uses.push_back(x);
        }
        p["uses"] = uses;
        if (timings && timings->valid && pos < timings->passes.size())
            p["milliseconds"] = timings->passes[pos].milliseconds;
        passes.push_back(p);
    }
    j["passes"] = passes;
    json culled = json::array();
    for (uint32_t c : compiled.culled) culled.push_back(graph.passes()[c].name);
    j["culled"] = culled;
    json resources = json::array();
    for (uint32_t id = 0; id < graph.resources().size(); ++id) {
        const ResourceDecl& r = graph.resource(id);
        const ResourcePlan& p = compiled.resources[id];
        json x;
        x["name"] = r.name;
        x["kind"] = r.buffer ? "buffer" : "image";
        x["imported"] = r.imported;
        x["used"] = p.used;
        if (!r.buffer) {
            x["format"] = formatName(r.image.format);
            x["extent"] = {p.extent.width, p.extent.height};
            x["mipLevels"] = r.image.mipLevels;
            x["arrayLayers"] = r.image.arrayLayers;
            if (r.image.depth > 1) x["depth"] = r.image.depth;
        }
        if (p.used) x["lifetime"] = {p.firstPass, p.lastPass};
        if (!r.imported && p.used) {
            x["bytes"] = p.memory.size;
            x["alignment"] = p.memory.alignment;
            x["block"] = p.block;
            x["offset"] = p.offset;
        }
        resources.push_back(x);
    }
    j["resources"] = resources;
    json blocks = json::array();
    for (const auto& b : compiled.blocks)
        blocks.push_back({{"memoryType", b.memoryType}, {"bytes", b.size}});
    j["memoryBlocks"] = blocks;
    j["totals"] = {{"unaliasedBytes", compiled.unaliasedBytes},
                   {"aliasedBytes", compiled.aliasedBytes}};
    if (timings && timings->valid) j["totals"]["milliseconds"] = timings->totalMilliseconds;
    return j;
}

std::string reportText(const RenderGraph& graph, const CompiledGraph& compiled,
                       const FrameTimings* timings) {
    std::ostringstream o;
    char line[256];
    o << "Passes (execution order)\n";
    for (uint32_t pos = 0; pos < compiled.passes.size(); ++pos) {
        const PassDecl& decl = graph.passes()[compiled.passes[pos].pass];
        std::snprintf(line, sizeof line, "  %2u  %-36s %-9s %2zu barriers", pos, decl.name.c_str(),
                      passTypeName(decl.type), compiled.passes[pos].barriers.size());
        o << line;
        if (timings && timings->valid && pos < timings->passes.size()) {
            std::snprintf(line, sizeof line, "  %10.4f ms", timings->passes[pos].milliseconds);
            o << line;
        }
        o << "\n";
    }
    for (uint32_t c : compiled.culled) o << "  --  " << graph.passes()[c].name << " (culled)\n";
    o << "Resources\n";
    for (uint32_t id = 0; id < graph.resources().size(); ++id) {
        const ResourceDecl& r = graph.resource(id);
        const ResourcePlan& p = compiled.resources[id];
        std::string shape = r.buffer ? "buffer"
                                     : formatName(r.image.format) + " " +
                                           std::to_string(p.extent.width) + "x" +
                                           std::to_string(p.extent.height);
        std::string where =
            r.imported ? "imported"
            : !p.used  ? "not allocated"
                       : "block " + std::to_string(p.block) + " @ " + std::to_string(p.offset);
        std::snprintf(line, sizeof line, "  %-32s %-30s %12s  passes %-8s %s", r.name.c_str(),
                      shape.c_str(),
                      (r.imported || !p.used) ? "-" : formatBytes(p.memory.size).c_str(),
                      lifetimeText(p).c_str(), where.c_str());
        o << line << "\n";
    }
    o << "Memory ("
      << (compiled.exactSizes ? "sizes from the device" : "estimated sizes, no device")
      << "): " << formatBytes(compiled.unaliasedBytes) << " without aliasing, "
      << formatBytes(compiled.aliasedBytes) << " with aliasing in " << compiled.blocks.size()
      << " block(s)\n";
    if (timings && timings->valid) {
        std::snprintf(line, sizeof line, "GPU time: %.4f ms\n", timings->totalMilliseconds);
        o << line;
    }
    return o.str();
}

std::string reportDot(const RenderGraph& graph, const CompiledGraph& compiled) {
    std::ostringstream o;
    o << "digraph rendergraph {\n  rankdir=LR;\n  node [fontname=\"Helvetica\"];\n";
    std::vector<int> position(graph.passes().size(), -1);
    for (uint32_t pos = 0; pos < compiled.passes.size(); ++pos)
        position[compiled.passes[pos].pass] = static_cast<int>(pos);
    for (uint32_t p = 0; p < graph.passes().size(); ++p) {
        const PassDecl& d = graph.passes()[p];
        o << "  p" << p << " [shape=box, label=\"" << dotEscape(d.name);
        if (position[p] >= 0)
            o << "\\n#" << position[p] << " " << passTypeName(d.type) << "\"";
        else
            o << "\\n(culled)\", style=dashed, color=gray, fontcolor=gray";
        o << "];\n";
    }
    for (uint32_t id = 0; id < graph.resources().size(); ++id) {
        const ResourceDecl& r = graph.resource(id);
        const ResourcePlan& plan = compiled.resources[id];
        o << "  r" << id << " [shape=" << (r.imported ? "doubleoctagon" : "ellipse") << ", label=\""
          << dotEscape(r.name);
        if (!r.buffer) o << "\\n" << formatName(r.image.format);
        if (plan.used && !r.imported) o << "\\n" << formatBytes(plan.memory.size);
        o << "\"" << (plan.used ? "" : ", style=dashed, color=gray, fontcolor=gray") << "];\n";
    }
    for (uint32_t p = 0; p < graph.passes().size(); ++p) {
        for (const auto& u : graph.passes()[p].uses) {
            if (u.resource >= graph.resources().size()) continue;
            if (u.readsContents())
                o << "  r" << u.resource << " -> p" << p << " [label=\"" << useKindName(u.kind)
                  << " v" << u.inVersion << "\"];\n";
            if (u.outVersion != kInvalidIndex)
                o << "  p" << p << " -> r" << u.resource << " [label=\"" << useKindName(u.kind)
                  << " v" << u.outVersion << "\", color=firebrick];\n";
        }
    }
    o << "}\n";
    return o.str();
}

}  // namespace rg
