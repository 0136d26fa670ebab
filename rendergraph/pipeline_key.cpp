#include "pipeline_key.h"

#include <algorithm>
#include <bit>

namespace rg {
namespace {

class KeyWriter {
  public:
    explicit KeyWriter(PipelineKey& key) : key_(key) {}
    // Each group starts with a tag and its element count, so that fields of different lengths can
    // never line up into the same key.
    void tag(uint64_t t, size_t count = 0) {
        key_.push_back(t);
        key_.push_back(count);
    }
    void put(uint64_t v) { key_.push_back(v); }
    void code(ShaderCode c) {
        put(reinterpret_cast<uintptr_t>(c.words));
        put(c.bytes);
    }
    void bindings(const std::vector<Binding>& bindings) {
        std::vector<Binding> sorted = bindings;  // a layout's binding order means nothing
        std::sort(sorted.begin(), sorted.end(),
                  [](const Binding& a, const Binding& b) { return a.binding < b.binding; });
        tag(1, sorted.size());
        for (const Binding& b : sorted) {
            put(b.binding);
            put(static_cast<uint64_t>(b.type));
            put(b.stages);
        }
    }
    void specialization(const Specialization& s) {
        auto values = s.values;  // nor does the order the constants were set in
        std::stable_sort(values.begin(), values.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        tag(2, values.size());
        for (const auto& [id, v] : values) put((static_cast<uint64_t>(id) << 32) | v);
    }

  private:
    PipelineKey& key_;
};

}  // namespace

PipelineKey pipelineKey(ShaderCode code, const std::vector<Binding>& bindings,
                        uint32_t pushConstantBytes, const Specialization& specialization) {
    PipelineKey key;
    KeyWriter w(key);
    w.tag(0x636f6d70);  // compute
    w.code(code);
    w.bindings(bindings);
    w.put(pushConstantBytes);
    w.specialization(specialization);
    return key;
}

PipelineKey pipelineKey(const GraphicsPipelineDesc& d) {
// A field added to GraphicsPipelineDesc changes its size: this fails until the field is in the key
// below (and in the test that changes each field, tests/rendergraph/pipeline_key_test.cpp).
#if defined(__x86_64__) || defined(__aarch64__)
    static_assert(sizeof(GraphicsPipelineDesc) == 240, "a new pipeline field must join its key");
#endif
    PipelineKey key;
    KeyWriter w(key);
    w.tag(0x67726170);  // graphics
    w.code(d.vertex);
    w.code(d.fragment);
    w.bindings(d.bindings);
    w.put(d.pushConstantBytes);
    w.specialization(d.specialization);
    w.tag(3, d.formats.colors.size());
    for (VkFormat f : d.formats.colors) w.put(static_cast<uint64_t>(f));
    w.put(static_cast<uint64_t>(d.formats.depth));
    w.put(static_cast<uint64_t>(d.formats.stencil));
    w.put(static_cast<uint64_t>(d.topology));
    w.tag(4, d.vertexBindings.size());
    for (const auto& b : d.vertexBindings) {
        w.put(b.binding);
        w.put(b.stride);
        w.put(static_cast<uint64_t>(b.inputRate));
    }
    w.tag(5, d.vertexAttributes.size());
    for (const auto& a : d.vertexAttributes) {
        w.put(a.location);
        w.put(a.binding);
        w.put(static_cast<uint64_t>(a.format));
        w.put(a.offset);
    }
    w.put(d.cullMode);
    w.put(static_cast<uint64_t>(d.frontFace));
    w.put(d.depthTest);
    w.put(d.depthWrite);
    w.put(static_cast<uint64_t>(d.depthCompare));
    w.put(d.stencilTest);
    const VkStencilOpState& s = d.stencil;
    for (uint64_t v :
         {uint64_t(s.failOp), uint64_t(s.passOp), uint64_t(s.depthFailOp), uint64_t(s.compareOp),
          uint64_t(s.compareMask), uint64_t(s.writeMask), uint64_t(s.reference)})
        w.put(v);
    w.put(static_cast<uint64_t>(d.blend));
    w.put(d.colorWriteMask);
    w.put(d.depthBias);
    return key;
}

}  // namespace rg
