#include "volume_out.h"

#include <string>

#include "registry/method_registry.h"

namespace lightscatter::detail {

namespace {

// The method that writes the frame's volume: the grid light's where it exports one, else the
// first that does (froxelVolume() asks before any method is chosen).
const ls::MethodUnit& volumeMethod(const MethodChoice* chosen) {
    if (chosen && chosen->unit().caps().exportsVolume) return chosen->unit();
    for (const ls::MethodUnit* unit : ls::methodRegistry())
        if (unit->caps().exportsVolume) return *unit;
    throw std::logic_error("no method exports a volume");
}

FroxelVolume layoutOf(const ls::VolumeLayout& v) {
    return {v.width, v.height, v.depth, v.tile, v.nearZ, v.farZ};
}

}  // namespace

size_t gridLight(const ValidatedFrame& frame) {
    for (size_t i = 0; i < frame.touchesView.size(); ++i)
        if (frame.touchesView[i]) return i;
    return 0;
}

FroxelVolume volumeLayout(const ValidatedFrame& frame, VkExtent2D screen) {
    return layoutOf(volumeMethod(nullptr).exportedVolume(frame.lights[gridLight(frame)], screen));
}

void checkVolumeOut(const ImageInput& volumeOut, const ValidatedFrame& frame,
                    const std::vector<MethodChoice>& choices, VkExtent2D screen) {
    const MethodChoice& chosen = choices.at(gridLight(frame));
    const std::string exporters =
        methodsWhere([](const ls::MethodCaps& c) { return c.exportsVolume; });
    if (!chosen.unit().caps().exportsVolume)
        throw InvalidInput(std::string("lightscatter: volumeOut is given but the frame runs ") +
                           methodName(chosen.method) + ", which keeps no 3D grid: only " +
                           exporters + " export one (leave volumeOut empty, or choose " +
                           exporters + ")");
    const ls::VolumeLayout v = chosen.unit().exportedVolume(frame.lights[gridLight(frame)], screen);
    if (volumeOut.extent.width != v.width || volumeOut.extent.height != v.height ||
        volumeOut.depth != v.depth)
        throw InvalidInput(
            "lightscatter: volumeOut.extent " + std::to_string(volumeOut.extent.width) + "x" +
            std::to_string(volumeOut.extent.height) + "x" + std::to_string(volumeOut.depth) +
            " differs from the " + methodName(chosen.method) + " grid's " +
            std::to_string(v.width) + "x" + std::to_string(v.height) + "x" +
            std::to_string(v.depth) + " (froxelVolume(): " + v.rule + ")");
}

}  // namespace lightscatter::detail

namespace lightscatter {

FroxelVolume froxelVolume(const FrameDescription& frame, VkExtent2D maxRenderSize) {
    const VkExtent2D screen = maxRenderSize.width != 0 ? maxRenderSize : frame.depth.extent;
    if (screen.width == 0 || screen.height == 0)
        throw InvalidInput("lightscatter: depth.extent is " + std::to_string(screen.width) + "x" +
                           std::to_string(screen.height) +
                           ": the grid covers the screen, which must not be empty");
    return detail::volumeLayout(detail::validateFrame(frame, false), screen);
}

}  // namespace lightscatter
