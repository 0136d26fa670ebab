// Ordering: who produces each version, which passes are needed, and a topological order in which
// every reader follows the writer of the version it names and precedes the next writer.
#include <algorithm>
#include <functional>
#include <map>
#include <queue>
#include <set>
#include <string>

#include "compile.h"

namespace rg::detail {
namespace {

using VersionKey = std::pair<uint32_t, uint32_t>;  // resource, version

struct VersionInfo {
    uint32_t producer = kInvalidIndex;
    std::vector<uint32_t> readers;  // passes that read or overwrite this version
    std::vector<uint32_t> writers;  // passes that consume this version to make the next
};

std::vector<uint32_t> findCycle(const std::vector<std::set<uint32_t>>& succ,
                                const std::vector<bool>& remaining) {
    const size_t n = succ.size();
    std::vector<int> colour(n, 0);  // 0 unvisited, 1 on stack, 2 done
    std::vector<uint32_t> stack;
    std::vector<uint32_t> cycle;
    std::function<bool(uint32_t)> dfs = [&](uint32_t v) {
        colour[v] = 1;
        stack.push_back(v);
        for (uint32_t w : succ[v]) {
            if (!remaining[w]) continue;
            if (colour[w] == 1) {
                auto it = std::find(stack.begin(), stack.end(), w);
                cycle.assign(it, stack.end());
                cycle.push_back(w);
                return true;
            }
            if (colour[w] == 0 && dfs(w)) return true;
        }
        stack.pop_back();
        colour[v] = 2;
        return false;
    };
    for (uint32_t v = 0; v < n; ++v)
        if (remaining[v] && colour[v] == 0 && dfs(v)) break;
    return cycle;
}

}  // namespace

Schedule schedule(const RenderGraph& graph) {
    const auto& passes = graph.passes();
    const uint32_t n = static_cast<uint32_t>(passes.size());
    std::map<VersionKey, VersionInfo> versions;

    for (uint32_t p = 0; p < n; ++p) {
        std::set<VersionKey> producedHere, consumedHere;
        for (const auto& u : passes[p].uses) {
            VersionInfo& in = versions[{u.resource, u.inVersion}];
            if (std::find(in.readers.begin(), in.readers.end(), p) == in.readers.end())
                in.readers.push_back(p);
            if (isWrite(u.kind) && consumedHere.insert({u.resource, u.inVersion}).second)
                in.writers.push_back(p);
            if (u.outVersion != kInvalidIndex &&
                producedHere.insert({u.resource, u.outVersion}).second)
                versions[{u.resource, u.outVersion}].producer = p;
        }
    }

    // A version may be overwritten by one pass only; a second writer of the same version has no
    // order with the first.
    for (const auto& [key, info] : versions) {
        if (info.writers.size() > 1) {
            const auto& r = graph.resource(key.first);
            throw GraphError(Rule::UnorderedWriters,
                             "passes " + quote(passes[info.writers[0]].name) + " and " +
                                 quote(passes[info.writers[1]].name) + " both write " +
                                 quote(r.name) + " starting from version " +
                                 std::to_string(key.second) +
                                 ", so nothing orders them; chain the second write on the version "
                                 "the first one returns");
        }
    }

    // Reading contents nobody wrote.
    for (uint32_t p = 0; p < n; ++p) {
        for (const auto& u : passes[p].uses) {
            const auto& r = graph.resource(u.resource);
            if (!u.readsContents() || r.imported) continue;
            if (u.inVersion == 0)
                throw GraphError(Rule::NeverWritten,
                                 "pass " + quote(passes[p].name) + " reads " + quote(r.name) +
                                     " (" + useKindName(u.kind) +
                                     ") but no pass writes it before; write it first, or clear it "
                                     "as an attachment");
        }
    }

    // Liveness: roots are side effects, writes to imports and producers of outputs' last versions.
    std::vector<bool> live(n, false);
    std::vector<uint32_t> work;
    auto markLive = [&](uint32_t p) {
        if (p != kInvalidIndex && !live[p]) {
            live[p] = true;
            work.push_back(p);
        }
    };
    for (uint32_t p = 0; p < n; ++p) {
        if (passes[p].sideEffect) markLive(p);
        for (const auto& u : passes[p].uses)
            if (isWrite(u.kind) && graph.resource(u.resource).imported) markLive(p);
    }
    for (uint32_t id = 0; id < graph.resources().size(); ++id) {
        const auto& r = graph.resource(id);
        if (r.output && r.versionCount > 1) markLive(versions[{id, r.versionCount - 1}].producer);
    }
    while (!work.empty()) {
        const uint32_t p = work.back();
        work.pop_back();
        for (const auto& u : passes[p].uses)
            if (u.readsContents()) markLive(versions[{u.resource, u.inVersion}].producer);
    }

    // Edges among live passes, walking each resource's chain of versions: every user of a version
    // follows the last live writer before it, and the next live writer follows every user since.
    // Culled writers are skipped so that a reader is still ordered before a later live overwrite.
    std::vector<std::set<uint32_t>> succ(n);
    std::vector<uint32_t> indegree(n, 0);
    auto edge = [&](uint32_t a, uint32_t b) {
        if (a == kInvalidIndex || a == b || !live[a] || !live[b]) return;
        if (succ[a].insert(b).second) ++indegree[b];
    };
    for (uint32_t id = 0; id < graph.resources().size(); ++id) {
        uint32_t lastWriter = kInvalidIndex;
        std::vector<uint32_t> pending;
        for (uint32_t v = 0; v < graph.resource(id).versionCount; ++v) {
            auto it = versions.find({id, v});
            if (it == versions.end()) continue;
            const VersionInfo& info = it->second;
            const uint32_t writer = info.writers.empty() ? kInvalidIndex : info.writers[0];
            for (uint32_t r : info.readers) {
                if (r == writer || !live[r]) continue;
                edge(lastWriter, r);
                pending.push_back(r);
            }
            if (writer != kInvalidIndex && live[writer]) {
                edge(lastWriter, writer);
                for (uint32_t r : pending) edge(r, writer);
                pending.clear();
                lastWriter = writer;
            }
        }
    }

    // Kahn's algorithm; among ready passes the earliest declared goes first, so the order is
    // stable.
    Schedule s;
    std::priority_queue<uint32_t, std::vector<uint32_t>, std::greater<>> ready;
    for (uint32_t p = 0; p < n; ++p)
        if (live[p] && indegree[p] == 0) ready.push(p);
    while (!ready.empty()) {
        const uint32_t p = ready.top();
        ready.pop();
        s.order.push_back(p);
        for (uint32_t q : succ[p])
            if (--indegree[q] == 0) ready.push(q);
    }
    const size_t liveCount = static_cast<size_t>(std::count(live.begin(), live.end(), true));
    if (s.order.size() != liveCount) {
        std::vector<bool> remaining(n, false);
        for (uint32_t p = 0; p < n; ++p) remaining[p] = live[p] && indegree[p] > 0;
        const auto cycle = findCycle(succ, remaining);
        std::string path;
        for (uint32_t p : cycle) path += (path.empty() ? "" : " -> ") + quote(passes[p].name);
        throw GraphError(Rule::Cycle, "passes depend on each other in a cycle: " + path);
    }
    for (uint32_t p = 0; p < n; ++p)
        if (!live[p]) s.culled.push_back(p);
    return s;
}

}  // namespace rg::detail
