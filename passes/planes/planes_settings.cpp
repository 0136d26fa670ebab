// The planes' field table (seed 002).
#include "lightscatter/limits.h"
#include "planes_method.h"
#include "shared/settings_table.h"

namespace ls {

std::vector<SettingsField> PlanesMethod::settingsFields() const {
    using P = lightscatter::PlanesSettings;
    namespace L = lightscatter::limits;
    FieldsOf<P> f("planes", &Settings::planes);
    f.whole("count", &P::count, 2, 4096, "")
        .profiles({256, 128, 100, 128, 64, 48})
        .former({"planeCount", "slicePlanes"})
        .doc("planes across the light's volume");
    f.number("spacing", &P::spacing, 1e-6, L::kMaxLength,
             "metres between sampling planes, or 0: `count` planes")
        .zeroIsOff()
        .slider(0, 10)
        .former({"planeSpacing"})
        .doc("planes at most this far apart, metres (0: count)");
    // Profile values in PlaneTarget's order: Float16 0, Float32 1, Rgba8Channels 2.
    f.choice("target", &P::target, {"float16", "float32", "rgba8"})
        .profiles({1, 0, 2, 0, 0, 2})
        .former({"planeTarget", "sliceTarget"})
        .doc("what the planes blend into");
    f.boolean("scaling", &P::scaling)
        .former({"planeScaling", "slicePlaneScaling"})
        .doc("fewer planes as the light's volume shrinks on screen");
    f.number("range", &P::range, 1e-30, 1e30,
             "or 0: automatic; the 8-bit target is scaled by 4 / range")
        .zeroIsOff()
        .slider(0, 1e3)
        .former({"planeRange", "sliceRange"})
        .doc("rgba8: the luminance that fills the channels (0: from the light)");
    f.boolean("dither", &P::dither)
        .former({"planeDither", "sliceDither"})
        .doc("rgba8: stochastic rounding");
    f.whole("blur", &P::blur, 0, 8, "pixels")
        .former({"planeBlur", "sliceBlur"})
        .doc("blur at composite, pixels");
    f.number("ambient", &P::ambient, 0, L::kMaxAmbient,
             "1/m^2, beside the inverse square; lightscatter.h, limits::kMaxAmbient")
        .slider(0, 10)
        .former({"planeAmbient", "sliceAmbient"})
        .doc("ambient term beside the inverse square, 1/m^2");
    return f.take();
}

}  // namespace ls
