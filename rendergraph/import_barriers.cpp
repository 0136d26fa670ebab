#include "import_barriers.h"

namespace rg::detail {

ImportEnd importStart(const ResourceDecl& r) {
    if (r.buffer)
        return {VK_IMAGE_LAYOUT_UNDEFINED, r.importedBuffer.initialStages,
                r.importedBuffer.initialAccess};
    return {r.importedImage.initialLayout, r.importedImage.initialStages,
            r.importedImage.initialAccess};
}

ImportEnd importFinish(const ResourceDecl& r) {
    if (r.buffer)
        return {VK_IMAGE_LAYOUT_UNDEFINED, r.importedBuffer.finalStages,
                r.importedBuffer.finalAccess};
    return {r.importedImage.finalLayout, r.importedImage.finalStages, r.importedImage.finalAccess};
}

void waitOnImport(BarrierPlan& b, const ResourceDecl& r) {
    const ImportEnd start = importStart(r);
    b.srcStages = start.stages;
    b.srcAccess = start.access;
    b.oldLayout = start.layout;
}

void handBackImport(BarrierPlan& b, const ResourceDecl& r) {
    const ImportEnd finish = importFinish(r);
    b.dstStages = finish.stages;
    b.dstAccess = finish.access;
    b.newLayout = finish.layout;
}

}  // namespace rg::detail
