// Synchronization: each pass's combined use of each resource (layout, stages, access), the
// attachments of graphics passes, and the synchronization2 barriers between passes.
#include <algorithm>
#include <map>

#include "block_occupants.h"
#include "compile.h"
#include "format_info.h"
#include "import_barriers.h"

namespace rg::detail {
namespace {

constexpr VkAccessFlags2 kWriteAccess =
    VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
constexpr VkPipelineStageFlags2 kFragmentTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;

VkPipelineStageFlags2 shaderStages(const ResourceUse& u, PassType type) {
    if (u.shaderStages) return u.shaderStages;
    return type == PassType::Graphics ? VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT
                                      : VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
}

void stagesAndAccess(const ResourceUse& u, PassType type, VkPipelineStageFlags2& stages,
                     VkAccessFlags2& access) {
    switch (u.kind) {
        case UseKind::Sampled:
            stages = shaderStages(u, type);
            access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
            break;
        case UseKind::StorageRead:
        case UseKind::StorageBufferRead:
            stages = shaderStages(u, type);
            access = VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
            break;
        case UseKind::StorageWrite:
        case UseKind::StorageBufferWrite:
            stages = shaderStages(u, type);
            access = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
            break;
        case UseKind::StorageReadWrite:
        case UseKind::StorageBufferReadWrite:
            stages = shaderStages(u, type);
            access = VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
            break;
        case UseKind::UniformBuffer:
            stages = shaderStages(u, type);
            access = VK_ACCESS_2_UNIFORM_READ_BIT;
            break;
        case UseKind::ColorAttachment:
            stages = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
            access = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
                     (u.load == LoadOp::Load ? VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT : 0);
            break;
        case UseKind::DepthTest:
        case UseKind::StencilTest:
            stages = kFragmentTests;
            access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
            break;
        case UseKind::DepthWrite:
        case UseKind::StencilWrite:
            stages = kFragmentTests;
            access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                     VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
            break;
        case UseKind::TransferSrc:
            stages = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
            access = VK_ACCESS_2_TRANSFER_READ_BIT;
            break;
        case UseKind::TransferDst:
            stages = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
            access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
            break;
    }
}

// One layout for the whole image in one pass, from the combination of its uses there.
VkImageLayout layoutFor(const std::vector<const ResourceUse*>& uses, VkFormat format) {
    bool depthWrite = false, stencilWrite = false, depthRead = false, stencilRead = false;
    for (const ResourceUse* u : uses) {
        switch (u->kind) {
            case UseKind::StorageRead:
            case UseKind::StorageWrite:
            case UseKind::StorageReadWrite:
                return VK_IMAGE_LAYOUT_GENERAL;
            case UseKind::ColorAttachment:
                return VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
            case UseKind::TransferSrc:
                return VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
            case UseKind::TransferDst:
                return VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            case UseKind::DepthWrite:
                depthWrite = true;
                break;
            case UseKind::StencilWrite:
                stencilWrite = true;
                break;
            case UseKind::DepthTest:
                depthRead = true;
                break;
            case UseKind::StencilTest:
                stencilRead = true;
                break;
            case UseKind::Sampled: {
                const VkImageAspectFlags a = u->aspect ? u->aspect : fullAspect(format);
                depthRead |= (a & VK_IMAGE_ASPECT_DEPTH_BIT) != 0;
                stencilRead |= (a & VK_IMAGE_ASPECT_STENCIL_BIT) != 0;
                break;
            }
            default:
                break;
        }
    }
    const bool attachment = std::any_of(uses.begin(), uses.end(),
                                        [](const ResourceUse* u) { return isAttachment(u->kind); });
    // Only sampled: the layout any sampled image may take, whatever else its usage allows (an
    // engine's shadow map need not be a depth-stencil attachment of ours).
    if (!attachment) return VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    if (depthWrite && !stencilWrite && stencilRead)
        return VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL;
    if (stencilWrite && !depthWrite && depthRead)
        return VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL;
    if (depthWrite || stencilWrite) return VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    return VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
}

VkAttachmentLoadOp loadOp(LoadOp op) {
    switch (op) {
        case LoadOp::Load:
            return VK_ATTACHMENT_LOAD_OP_LOAD;
        case LoadOp::Clear:
            return VK_ATTACHMENT_LOAD_OP_CLEAR;
        case LoadOp::DontCare:
            return VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    }
    return VK_ATTACHMENT_LOAD_OP_LOAD;
}

AttachmentPlan attachment(const ResourceUse& u, VkImageLayout layout) {
    AttachmentPlan a;
    a.resource = u.resource;
    a.layout = layout;
    a.clear = u.clear;
    if (isWrite(u.kind)) {
        a.load = loadOp(u.load);
        a.store = VK_ATTACHMENT_STORE_OP_STORE;
    } else {  // test only: read the contents, write nothing back
        a.load = VK_ATTACHMENT_LOAD_OP_LOAD;
        a.store = VK_ATTACHMENT_STORE_OP_NONE;
    }
    return a;
}

// What the last passes did to a resource, for the next barrier.
struct SyncState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 writeStages = 0;  // the last write (or layout transition)
    VkAccessFlags2 writeAccess = 0;
    VkPipelineStageFlags2 readStages = 0;                                   // reads since then
    std::vector<std::pair<VkPipelineStageFlags2, VkAccessFlags2>> visible;  // made visible to
    bool touched = false;
};

bool alreadyVisible(const SyncState& s, VkPipelineStageFlags2 stages, VkAccessFlags2 access) {
    for (const auto& [st, ac] : s.visible)
        if ((stages & ~st) == 0 && (access & ~ac) == 0) return true;
    return false;
}

}  // namespace

void deriveSync(const RenderGraph& graph, CompiledGraph& out) {
    const auto& decls = graph.resources();
    std::vector<SyncState> state(decls.size());
    for (uint32_t id = 0; id < decls.size(); ++id) {
        const auto& r = decls[id];
        if (!r.imported) continue;
        auto& s = state[id];
        const ImportEnd start = importStart(r);
        s.layout = start.layout;
        s.writeStages = start.stages;
        s.writeAccess = start.access & kWriteAccess;
        s.touched = true;
    }

    for (auto& plan : out.passes) {
        const PassDecl& pass = graph.passes()[plan.pass];
        if (pass.type == PassType::Graphics) plan.renderExtent = pass.renderArea;  // no attachment
        std::map<uint32_t, std::vector<const ResourceUse*>> byResource;
        for (const auto& u : pass.uses) byResource[u.resource].push_back(&u);

        for (const auto& [id, uses] : byResource) {
            const auto& r = decls[id];
            PassResourceState ps;
            ps.resource = id;
            ps.buffer = r.buffer;
            for (const ResourceUse* u : uses) {
                VkPipelineStageFlags2 st = 0;
                VkAccessFlags2 ac = 0;
                stagesAndAccess(*u, pass.type, st, ac);
                ps.stages |= st;
                ps.access |= ac;
                ps.writes |= isWrite(u->kind);
            }
            if (!r.buffer) ps.layout = layoutFor(uses, r.image.format);
            plan.states.push_back(ps);

            if (!r.buffer && pass.type == PassType::Graphics) {
                for (const ResourceUse* u : uses) {
                    switch (u->kind) {
                        case UseKind::ColorAttachment:
                            plan.colors.push_back(attachment(*u, ps.layout));
                            break;
                        case UseKind::DepthTest:
                        case UseKind::DepthWrite:
                            plan.depth = attachment(*u, ps.layout);
                            break;
                        case UseKind::StencilTest:
                        case UseKind::StencilWrite:
                            plan.stencil = attachment(*u, ps.layout);
                            break;
                        default:
                            break;
                    }
                    if (isAttachment(u->kind)) plan.renderExtent = out.resources[id].extent;
                }
            }

            // The barrier this pass needs before touching the resource.
            SyncState& s = state[id];
            BarrierPlan b;
            b.resource = id;
            b.buffer = r.buffer;
            b.dstStages = ps.stages;
            b.dstAccess = ps.access;
            b.oldLayout = s.layout;
            b.newLayout = r.buffer ? VK_IMAGE_LAYOUT_UNDEFINED : ps.layout;
            const bool layoutChange = !r.buffer && s.layout != ps.layout;
            bool emit = false;
            if (!s.touched) {
                // First use of a transient in the frame: contents discarded. The source scope is
                // filled in once every resource's last use is known (see below).
                b.firstUse = true;
                b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
                emit = true;
            } else if (ps.writes || layoutChange) {
                b.srcStages = s.writeStages | s.readStages;
                b.srcAccess = s.writeAccess;
                emit = b.srcStages != 0 || layoutChange;
            } else if (!alreadyVisible(s, ps.stages, ps.access) && s.writeStages != 0) {
                b.srcStages = s.writeStages;
                b.srcAccess = s.writeAccess;
                emit = true;
            }
            if (emit) {
                if (b.srcStages == 0) b.srcStages = VK_PIPELINE_STAGE_2_NONE;
                plan.barriers.push_back(b);
            }

            if (ps.writes || layoutChange || !s.touched) {
                s.writeStages = ps.stages;
                s.writeAccess = ps.writes ? (ps.access & kWriteAccess) : 0;
                s.readStages = ps.writes ? 0 : ps.stages;
                // A write is visible to nobody until a barrier makes it so, not even to later
                // accesses of the same stage; a transition for reading is visible to that read.
                s.visible.clear();
                if (!ps.writes) s.visible.emplace_back(ps.stages, ps.access);
            } else {
                s.readStages |= ps.stages;
                if (emit) s.visible.emplace_back(ps.stages, ps.access);
            }
            s.layout = r.buffer ? VK_IMAGE_LAYOUT_UNDEFINED : ps.layout;
            s.touched = true;
        }
    }

    const VkExtent2D screen = graph.screenExtent();
    for (auto& plan : out.passes)
        plan.screenSized = screen.width != 0 && plan.renderExtent.width == screen.width &&
                           plan.renderExtent.height == screen.height;

    // First uses wait for whatever last touched the same memory: the resource itself in the
    // previous frame, and every resource it shares memory with (earlier in this frame, or later in
    // the previous one). A barrier's first scope covers all earlier submissions on the queue, so
    // this also orders frame N+1 after frame N.
    std::vector<std::vector<BlockOccupants::Occupant>> inBlock(out.blocks.size());
    for (uint32_t id = 0; id < decls.size(); ++id) {
        const ResourcePlan& p = out.resources[id];
        if (!p.used || decls[id].imported || p.block == kInvalidIndex || p.memory.size == 0)
            continue;
        inBlock.at(p.block).push_back({p.offset, p.offset + p.memory.size,
                                       state[id].writeStages | state[id].readStages,
                                       state[id].writeAccess});
    }
    std::vector<BlockOccupants> occupants;
    occupants.reserve(inBlock.size());
    for (const auto& list : inBlock) occupants.emplace_back(list);
    for (auto& plan : out.passes) {
        for (auto& b : plan.barriers) {
            if (!b.firstUse) continue;
            const SyncState& own = state[b.resource];
            b.srcStages |= own.writeStages | own.readStages;
            b.srcAccess |= own.writeAccess;
            const ResourcePlan& p = out.resources[b.resource];
            if (p.block == kInvalidIndex || p.memory.size == 0) continue;
            const BlockOccupants& o = occupants.at(p.block);
            const auto [stages, access] = o.meeting(p.offset, p.offset + p.memory.size);
            b.srcStages |= stages;
            b.srcAccess |= access;
            if (o.count(p.offset, p.offset + p.memory.size) > 1) b.aliased = true;
        }
    }

    // Hand imports back in the state the engine asked for.
    for (uint32_t id = 0; id < decls.size(); ++id) {
        const auto& r = decls[id];
        if (!r.imported) continue;
        const SyncState& s = state[id];
        BarrierPlan b;
        b.resource = id;
        b.buffer = r.buffer;
        b.srcStages = s.writeStages | s.readStages;
        b.srcAccess = s.writeAccess;
        b.oldLayout = s.layout;
        handBackImport(b, r);
        if (!out.resources[id].used && b.oldLayout == b.newLayout) continue;
        out.finalBarriers.push_back(b);
        out.resources[id].lastLayout = r.buffer ? VK_IMAGE_LAYOUT_UNDEFINED : s.layout;
    }
}

}  // namespace rg::detail
