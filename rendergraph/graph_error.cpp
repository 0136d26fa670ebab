#include "graph_error.h"

namespace rg {

const char* ruleName(Rule rule) {
    switch (rule) {
        case Rule::UnknownResource:
            return "unknown resource";
        case Rule::NeverWritten:
            return "read of a never-written resource";
        case Rule::FormatUnsupported:
            return "format not valid for the usage on this device";
        case Rule::UsageNotDeclared:
            return "imported resource lacks the usage flag";
        case Rule::ExtentMismatch:
            return "attachment extents differ";
        case Rule::Cycle:
            return "cycle between passes";
        case Rule::UnorderedWriters:
            return "unordered writers";
        case Rule::StencilWithoutStencilFormat:
            return "stencil use on a format without stencil";
        case Rule::DepthWithoutDepthFormat:
            return "depth use on a format without depth";
        case Rule::ColorOnDepthFormat:
            return "color or storage use on a depth-stencil format";
        case Rule::ImportWithoutFinalLayout:
            return "imported image without a final layout";
        case Rule::ConflictingUses:
            return "conflicting uses in one pass";
        case Rule::WrongPassType:
            return "use not allowed in this pass type";
        case Rule::BadDescription:
            return "invalid resource description";
        case Rule::ImportChanged:
            return "import changed incompatibly";
    }
    return "unknown rule";
}

}  // namespace rg
