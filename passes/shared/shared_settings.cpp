// Settings' own fields: those no one method owns.
#include "lightscatter/limits.h"
#include "settings_table.h"

namespace ls {

std::vector<SettingsField> sharedSettingsFields() {
    namespace L = lightscatter::limits;
    using lightscatter::LightModel;
    using lightscatter::ShadowFilter;
    FieldsOf<Settings> f;
    f.whole("shadowMapSize", &Settings::shadowMapSize, 1, 16384, "")
        .zeroIsOff()
        .profiles({4096, 2048, 1024, 2048, 1024, 512})
        .doc("the profile's recommended shadow map (0: none)");
    f.choice("shadowFilter", &Settings::shadowFilter, {"nearest", "bilinear"})
        .doc("shadow-map look-ups: nearest texel or 2x2 PCF");
    f.number("shadowDepthBias", &Settings::shadowDepthBias, -1, 1,
             "the depth range: beyond it every ray is lit, or shadowed, all the same")
        .slider(-0.01, 0.01)
        .doc("added to the ray's light-space depth");
    f.boolean("shadowSampling", &Settings::shadowSampling)
        .doc("false: seed 003's mode without shadow look-ups");
    f.number("noiseAmplitude", &Settings::noiseAmplitude, 0, 1, "")
        .doc("seed 002's scrolling noise");
    f.number("noiseScale", &Settings::noiseScale, L::kMinNoiseScale, L::kMaxNoiseScale,
             "a tile's size; lightscatter.h, limits::kMinNoiseScale")
        .slider(1e-3, 1e3, true)
        .doc("a noise tile's size");
    f.vector4("noiseVelocity", &Settings::noiseVelocity, -kFiniteMax, kFiniteMax,
              "tiles per second")
        .slider(-1, 1)
        .doc("tiles per second, two layers");
    f.choice("lightModel", &Settings::lightModel, {"full", "simplified"})
        .doc("seed 004's simplified model");
    f.number("simplifiedA0", &Settings::simplifiedA0, 0, L::kMaxSimplifiedA0,
             "m^2, seed 004's falloff I / (a1 r^2 + a0); lightscatter.h, limits::kMaxSimplifiedA0")
        .slider(0, 1)
        .doc("a0 of I / (a1 r^2 + a0), m^2");
    f.number("simplifiedA1", &Settings::simplifiedA1, L::kMinSimplifiedA1, L::kMaxSimplifiedA1,
             "seed 004's falloff I / (a1 r^2 + a0); lightscatter.h, limits::kMinSimplifiedA1")
        .slider(L::kMinSimplifiedA1, L::kMaxSimplifiedA1, true)
        .doc("a1 of I / (a1 r^2 + a0)");
    return f.take();
}

}  // namespace ls
