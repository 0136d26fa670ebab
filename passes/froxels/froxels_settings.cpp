// The froxel grid's field table.
#include "froxels_method.h"
#include "lightscatter/limits.h"
#include "shared/settings_table.h"

namespace ls {

std::vector<SettingsField> FroxelsMethod::settingsFields() const {
    using F = lightscatter::FroxelsSettings;
    namespace L = lightscatter::limits;
    FieldsOf<F> f("froxels", &Settings::froxels);
    f.whole("tile", &F::tile, 2, 64, "pixels").former({"froxelTile"}).doc("a column's pixels");
    f.whole("slices", &F::slices, 4, 512, "").former({"froxelSlices"}).doc("depth slices");
    f.number("farDistance", &F::farDistance, 1e-6, L::kMaxLength, "or 0: the medium's maxDistance")
        .zeroIsOff()
        .slider(0, 1000)
        .former({"froxelFarDistance"})
        .doc("the grid's far end, metres (0: the medium's)");
    f.boolean("temporal", &F::temporal)
        .former({"froxelTemporal"})
        .doc("jitter and blend with the previous frame");
    f.number("historyWeight", &F::historyWeight, 0, 0.99,
             "the history's share of each froxel; 1 would never take a new frame")
        .former({"froxelHistoryWeight"})
        .doc("the history's weight in the blend (0.75 for 0.9 where the camera moved)");
    f.boolean("pixelHistory", &F::pixelHistory)
        .doc("still frames refined per pixel (needs temporal)");
    return f.take();
}

}  // namespace ls
