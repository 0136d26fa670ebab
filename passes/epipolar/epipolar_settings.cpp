// Epipolar sampling's field table: every choice seed 000 leaves open.
#include "epipolar_method.h"
#include "shared/settings_table.h"

namespace ls {

std::vector<SettingsField> EpipolarMethod::settingsFields() const {
    using lightscatter::EpipolarSettings;
    using E = EpipolarSettings;
    FieldsOf<E> f("epipolar", &Settings::epipolar);
    f.whole("slices", &E::slices, 4, 16384, "a quarter per screen edge")
        .multipleOf(4)
        .slider(4, 4096)
        .profiles({2048, 1024, 1024, 1024, 512, 512})
        .former({"slices"})
        .doc("epipolar lines, a multiple of 4");
    f.whole("samplesPerSlice", &E::samplesPerSlice, 2, 16384, "")
        .slider(2, 4096)
        .profiles({1024, 1024, 512, 1024, 512, 256})
        .former({"samplesPerSlice"})
        .doc("samples along each line");
    f.whole("initialSampleStep", &E::initialSampleStep, 1, 128,
            "the first ray-marching samples' spacing")
        .powerOfTwo()
        .former({"initialSampleStep"})
        .doc("ray-marching samples every N samples (a power of two)");
    f.number("refinementThreshold", &E::refinementThreshold, 0, kFiniteMax, "only compared")
        .aboveMin()
        .slider(1e-4, 1, true)
        .former({"refinementThreshold"})
        .doc("relative camera-z jump that is a depth break");
    f.number("inscatterRefinementThreshold", &E::inscatterRefinementThreshold, 0, kFiniteMax,
             "0: off")
        .slider(0, 1)
        .former({"inscatterRefinementThreshold"})
        .doc("march between samples whose in-scattering differs this much (0: off)");
    f.number("bilateralThreshold", &E::bilateralThreshold, 0, kFiniteMax, "only compared")
        .aboveMin()
        .slider(1e-4, 1, true)
        .former({"bilateralThreshold"})
        .doc("relative camera-z difference the unwarp accepts");
    f.boolean("minMaxTrees", &E::minMaxTrees)
        .former({"minMaxTrees"})
        .doc("1D min/max binary trees per slice");
    f.boolean("fixup", &E::fixup)
        .former({"fixup"})
        .doc("ray-march the pixels the unwarp cannot interpolate");
    f.whole("fixupMaxSteps", &E::fixupMaxSteps, 0, 4294967295.0, "0: every shadow-map texel")
        .slider(0, 4096)
        .former({"fixupMaxSteps"})
        .doc("at most this many steps per fix-up pixel (0: every texel)");
    f.choice("interpolation", &E::interpolation, {"shadowed-fraction", "inscattering"})
        .former({"interpolation"})
        .doc("what epipolar samples carry to the screen");
    return f.take();
}

}  // namespace ls
