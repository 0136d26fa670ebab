#include "pass_decl.h"

namespace rg {

const char* useKindName(UseKind kind) {
    switch (kind) {
        case UseKind::Sampled:
            return "sampled";
        case UseKind::StorageRead:
            return "storage read";
        case UseKind::StorageWrite:
            return "storage write";
        case UseKind::StorageReadWrite:
            return "storage read-write";
        case UseKind::ColorAttachment:
            return "color attachment";
        case UseKind::DepthTest:
            return "depth test";
        case UseKind::DepthWrite:
            return "depth write";
        case UseKind::StencilTest:
            return "stencil test";
        case UseKind::StencilWrite:
            return "stencil write";
        case UseKind::TransferSrc:
            return "transfer source";
        case UseKind::TransferDst:
            return "transfer destination";
        case UseKind::UniformBuffer:
            return "uniform buffer";
        case UseKind::StorageBufferRead:
            return "storage buffer read";
        case UseKind::StorageBufferWrite:
            return "storage buffer write";
        case UseKind::StorageBufferReadWrite:
            return "storage buffer read-write";
    }
    return "unknown use";
}

bool isWrite(UseKind kind) {
    switch (kind) {
        case UseKind::StorageWrite:
        case UseKind::StorageReadWrite:
        case UseKind::ColorAttachment:
        case UseKind::DepthWrite:
        case UseKind::StencilWrite:
        case UseKind::TransferDst:
        case UseKind::StorageBufferWrite:
        case UseKind::StorageBufferReadWrite:
            return true;
        default:
            return false;
    }
}

bool isBufferOnly(UseKind kind) {
    switch (kind) {
        case UseKind::UniformBuffer:
        case UseKind::StorageBufferRead:
        case UseKind::StorageBufferWrite:
        case UseKind::StorageBufferReadWrite:
            return true;
        default:
            return false;
    }
}

bool isImageOnly(UseKind kind) {
    return !isBufferOnly(kind) && kind != UseKind::TransferSrc && kind != UseKind::TransferDst;
}

bool isAttachment(UseKind kind) {
    switch (kind) {
        case UseKind::ColorAttachment:
        case UseKind::DepthTest:
        case UseKind::DepthWrite:
        case UseKind::StencilTest:
        case UseKind::StencilWrite:
            return true;
        default:
            return false;
    }
}

VkImageUsageFlags imageUsageFor(UseKind kind) {
    switch (kind) {
        case UseKind::Sampled:
            return VK_IMAGE_USAGE_SAMPLED_BIT;
        case UseKind::StorageRead:
        case UseKind::StorageWrite:
        case UseKind::StorageReadWrite:
            return VK_IMAGE_USAGE_STORAGE_BIT;
        case UseKind::ColorAttachment:
            return VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
        case UseKind::DepthTest:
        case UseKind::DepthWrite:
        case UseKind::StencilTest:
        case UseKind::StencilWrite:
            return VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
        case UseKind::TransferSrc:
            return VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        case UseKind::TransferDst:
            return VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        default:
            return 0;
    }
}

VkBufferUsageFlags bufferUsageFor(UseKind kind) {
    switch (kind) {
        case UseKind::UniformBuffer:
            return VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
        case UseKind::StorageBufferRead:
        case UseKind::StorageBufferWrite:
        case UseKind::StorageBufferReadWrite:
            return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        case UseKind::TransferSrc:
            return VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
        case UseKind::TransferDst:
            return VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        default:
            return 0;
    }
}

bool ResourceUse::readsContents() const {
    switch (kind) {
        case UseKind::StorageWrite:
        case UseKind::TransferDst:
        case UseKind::StorageBufferWrite:
            return false;
        case UseKind::ColorAttachment:
        case UseKind::DepthWrite:
        case UseKind::StencilWrite:
            return load == LoadOp::Load;
        default:
            return true;
    }
}

}  // namespace rg
