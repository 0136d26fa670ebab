#include "composite_target.h"

#include "pass_helpers.h"

namespace ls {

CompositeOutputs addCompositeTarget(rg::BindingTable& table, const CompositeTarget& target) {
    CompositeOutputs written;
    written.color = table.storageReadWrite(LS_BINDING_ENGINE_COLOR, target.color);
    // Read-modify-written: a later light adds to it, and a pixel the pass leaves to another keeps
    // what it holds.
    written.inscatterOut = table.storageReadWriteIfValid(LS_BINDING_LIN_OUT, target.inscatterOut);
    return written;
}

}  // namespace ls
