#include "volume_out.h"

#include <string>

#include "froxels/froxel_nodes.h"

namespace lightscatter::detail {

size_t gridLight(const ValidatedFrame& frame) {
    for (size_t i = 0; i < frame.touchesView.size(); ++i)
        if (frame.touchesView[i]) return i;
    return 0;
}

FroxelVolume volumeLayout(const ValidatedFrame& frame, VkExtent2D screen) {
    const ls::LightSetup& s = frame.lights[gridLight(frame)];
    const ls::FroxelGrid grid = ls::froxelGrid(screen, ls::froxelSettings(s.settings.froxels));
    const ls::FroxelDepthRange z =
        ls::froxelDepthRange(s.camera.nearPlane, s.camera.farPlane, s.camera.infiniteFar,
                             s.medium.maxDistance, s.settings.froxels.farDistance);
    return {grid.columns, grid.rows, grid.slices, grid.tile, z.nearZ, z.farZ};
}

void checkVolumeOut(const ImageInput& volumeOut, const ValidatedFrame& frame,
                    const std::vector<MethodChoice>& choices, VkExtent2D screen) {
    const MethodChoice& chosen = choices.at(gridLight(frame));
    if (!chosen.unit().caps().exportsVolume)
        throw InvalidInput(std::string("lightscatter: volumeOut is given but the frame runs ") +
                           methodName(chosen.method) +
                           ", which keeps no 3D grid: only froxels export one (leave volumeOut "
                           "empty, or choose froxels)");
    const FroxelVolume v = volumeLayout(frame, screen);
    if (volumeOut.extent.width != v.width || volumeOut.extent.height != v.height ||
        volumeOut.depth != v.depth)
        throw InvalidInput(
            "lightscatter: volumeOut.extent " + std::to_string(volumeOut.extent.width) + "x" +
            std::to_string(volumeOut.extent.height) + "x" + std::to_string(volumeOut.depth) +
            " differs from the froxel grid's " + std::to_string(v.width) + "x" +
            std::to_string(v.height) + "x" + std::to_string(v.depth) +
            " (froxelVolume(): the screen over Settings::froxels.tile, and froxels.slices)");
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
