#pragma once
// What a pass declares: its kind and every use it makes of a resource. The compiler derives order,
// lifetimes, layouts and barriers from these declarations alone.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "resources.h"

namespace rg {

class PassContext;

enum class PassType : uint8_t { Graphics, Compute, Transfer };
enum class LoadOp : uint8_t { Load, Clear, DontCare };

enum class UseKind : uint8_t {
    Sampled,           // texture fetch
    StorageRead,       // imageLoad
    StorageWrite,      // imageStore of every texel later read; earlier contents not read
    StorageReadWrite,  // imageLoad and imageStore
    ColorAttachment,   // written; LoadOp::Load also reads the previous contents
    DepthTest,         // depth attachment, test only
    DepthWrite,        // depth attachment, test and write
    StencilTest,       // stencil attachment, test only: a read of the stencil aspect
    StencilWrite,      // stencil attachment written (and tested if loaded)
    TransferSrc,
    TransferDst,
    UniformBuffer,
    StorageBufferRead,
    StorageBufferWrite,
    StorageBufferReadWrite,
};

const char* useKindName(UseKind kind);
bool isWrite(UseKind kind);
bool isBufferOnly(UseKind kind);  // uniform and storage-buffer uses
bool isImageOnly(UseKind kind);   // sampled, storage image and attachment uses
bool isAttachment(UseKind kind);
// The usage flags an image or buffer needs for this use.
VkImageUsageFlags imageUsageFor(UseKind kind);
VkBufferUsageFlags bufferUsageFor(UseKind kind);

struct ResourceUse {
    UseKind kind = UseKind::Sampled;
    bool buffer = false;
    uint32_t graph = 0;
    uint32_t resource = kInvalidIndex;
    uint32_t inVersion = 0;                  // the version read or overwritten
    uint32_t outVersion = kInvalidIndex;     // the version produced, for writes
    VkPipelineStageFlags2 shaderStages = 0;  // 0: the pass type's natural stage
    LoadOp load = LoadOp::Load;
    VkClearValue clear{};
    VkImageAspectFlags aspect = 0;  // Sampled depth-stencil images: which aspect is read

    // Whether the pass needs the contents of `inVersion` (as opposed to only coming after it).
    bool readsContents() const;
};

struct PassDecl {
    std::string name;
    PassType type = PassType::Compute;
    std::vector<ResourceUse> uses;
    std::function<void(PassContext&)> execute;
    bool sideEffect = false;  // never culled (e.g. it writes something outside the graph)
    // Graphics: an occlusion query counts the samples that pass its tests (FrameTimings reads it).
    bool countSamples = false;
    // A graphics pass without attachments (its fragments only write storage images) renders over
    // this extent; with attachments it is theirs.
    VkExtent2D renderArea{0, 0};
};

}  // namespace rg
