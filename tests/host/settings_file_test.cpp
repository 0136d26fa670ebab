// --settings FILE.json: every field of lightscatter::Settings by name, overlaid on a profile;
// unknown fields and bad values are one line naming the file and the field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "settings_fields.h"
#include "settings_file.h"

namespace {

namespace fs = std::filesystem;

class HostSettingsFile : public ::testing::Test {
  protected:
    void SetUp() override {
        file_ =
            (fs::temp_directory_path() / ("host_settings_" + std::to_string(::getpid()) + ".json"))
                .string();
    }
    void TearDown() override { fs::remove(file_); }

    lightscatter::Settings load(const std::string& text,
                                lightscatter::Settings base = lightscatter::Settings{}) const {
        std::ofstream(file_) << text;
        return host::loadSettingsFile(file_, base);
    }
    // The message without the "FILE: " in front.
    std::string errorFor(const std::string& text) const {
        try {
            load(text);
        } catch (const std::runtime_error& e) {
            const std::string m = e.what();
            EXPECT_EQ(m.find('\n'), std::string::npos) << m;
            return m.rfind(file_ + ": ", 0) == 0 ? m.substr(file_.size() + 2)
                                                 : "(file not named) " + m;
        }
        return "(no error)";
    }

    std::string file_;
};

TEST_F(HostSettingsFile, EveryFieldByName) {
    const lightscatter::Settings s = load(R"({
        "slices": 512, "samplesPerSlice": 256, "initialSampleStep": 8, "refinementThreshold": 0.05,
        "inscatterRefinementThreshold": 0.1, "bilateralThreshold": 0.2, "minMaxTrees": false, "shadowFilter": "nearest", "fixup": false,
        "fixupMaxSteps": 64, "shadowDepthBias": -0.001, "interpolation": "inscattering",
        "shadowMapSize": 1024})");
    EXPECT_EQ(s.epipolar.slices, 512u);
    EXPECT_EQ(s.epipolar.samplesPerSlice, 256u);
    EXPECT_EQ(s.epipolar.initialSampleStep, 8u);
    EXPECT_FLOAT_EQ(s.epipolar.refinementThreshold, 0.05f);
    EXPECT_FLOAT_EQ(s.epipolar.inscatterRefinementThreshold, 0.1f);
    EXPECT_FLOAT_EQ(s.epipolar.bilateralThreshold, 0.2f);
    EXPECT_FALSE(s.epipolar.minMaxTrees);
    EXPECT_EQ(s.shadowFilter, lightscatter::ShadowFilter::Nearest);
    EXPECT_FALSE(s.epipolar.fixup);
    EXPECT_EQ(s.epipolar.fixupMaxSteps, 64u);
    EXPECT_FLOAT_EQ(s.shadowDepthBias, -0.001f);
    EXPECT_EQ(s.epipolar.interpolation, lightscatter::Interpolation::Inscattering);
    EXPECT_EQ(s.shadowMapSize, 1024u);

    const lightscatter::Settings c = load(R"({"coneSamples": 64, "coneLimited": false,
        "coneJitter": true, "shadowSampling": false})");
    EXPECT_EQ(c.coneMarch.samples, 64u);
    EXPECT_FALSE(c.coneMarch.limited);
    EXPECT_TRUE(c.coneMarch.jitter);
    EXPECT_FALSE(c.shadowSampling);

    const lightscatter::Settings p = load(R"({"planeCount": 200, "planeTarget": "rgba8",
        "planeScaling": true, "planeRange": 0.5, "planeDither": false, "planeBlur": 3,
        "planeAmbient": 0.02, "noiseAmplitude": 0.75, "noiseScale": 2.5,
        "noiseVelocity": [0.1, -0.2, 0.3, -0.4]})");
    EXPECT_EQ(p.planes.count, 200u);
    EXPECT_EQ(p.planes.target, lightscatter::PlaneTarget::Rgba8Channels);
    EXPECT_TRUE(p.planes.scaling);
    EXPECT_FLOAT_EQ(p.planes.range, 0.5f);
    EXPECT_FALSE(p.planes.dither);
    EXPECT_EQ(p.planes.blur, 3u);
    EXPECT_FLOAT_EQ(p.planes.ambient, 0.02f);
    EXPECT_FLOAT_EQ(p.noiseAmplitude, 0.75f);
    EXPECT_FLOAT_EQ(p.noiseScale, 2.5f);
    EXPECT_EQ(p.noiseVelocity, (std::array<float, 4>{0.1f, -0.2f, 0.3f, -0.4f}));
    const lightscatter::Settings m =
        load(R"({"lightModel": "simplified", "simplifiedA0": 0.04, "simplifiedA1": 0.5})");
    EXPECT_EQ(m.lightModel, lightscatter::LightModel::Simplified);
    EXPECT_FLOAT_EQ(m.simplifiedA0, 0.04f);
    EXPECT_FLOAT_EQ(m.simplifiedA1, 0.5f);
    EXPECT_EQ(load(R"({"lightModel": "full"})").lightModel, lightscatter::LightModel::Full);
    EXPECT_EQ(load(R"({"planeTarget": "float16"})").planes.target,
              lightscatter::PlaneTarget::Float16);
    EXPECT_EQ(load(R"({"planeTarget": "float32"})").planes.target,
              lightscatter::PlaneTarget::Float32);
    const lightscatter::Settings f = load(R"({"froxelTile": 16, "froxelSlices": 128,
        "froxelFarDistance": 50, "froxelTemporal": true, "froxelHistoryWeight": 0.8})");
    EXPECT_EQ(f.froxels.tile, 16u);
    EXPECT_EQ(f.froxels.slices, 128u);
    EXPECT_FLOAT_EQ(f.froxels.farDistance, 50.0f);
    EXPECT_TRUE(f.froxels.temporal);
    EXPECT_FLOAT_EQ(f.froxels.historyWeight, 0.8f);
}

// The viewer's "save settings": every field written, and read back to the same settings; a field
// of Settings the list leaves out would keep its default on the way back and fail here.
TEST_F(HostSettingsFile, AWrittenFileReadsBackToTheSameSettings) {
    lightscatter::Settings s;
    s.epipolar.slices = 512;
    s.epipolar.refinementThreshold = 0.07f;
    s.epipolar.minMaxTrees = false;
    s.shadowFilter = lightscatter::ShadowFilter::Nearest;
    s.planes.target = lightscatter::PlaneTarget::Rgba8Channels;
    s.noiseVelocity = {0.25f, -0.5f, 0.125f, 1.0f};
    s.lightModel = lightscatter::LightModel::Simplified;
    s.froxels.historyWeight = 0.3f;
    s.froxels.pixelHistory = true;
    const lightscatter::Settings back = load(host::settingsFileText(s));
    for (const host::SettingField& f : host::settingFields())
        for (int c = 0; c < (f.kind == host::SettingField::Kind::Vector4 ? 4 : 1); ++c)
            EXPECT_EQ(host::fieldValue(back, f, c), host::fieldValue(s, f, c)) << f.name;
    // 37 fields today: a member added to a method's settings is added to its table, then here.
    EXPECT_EQ(host::settingFields().size(), 37u);
    EXPECT_EQ(host::settingsFileText(s).find("0.07000000"), std::string::npos)
        << "floats are written as their shortest decimal";
}

// The froxel presets by name: the grid's sizes, "-temporal" for the temporal mode and "-pixels" for
// it with still frames refined per pixel; each preset sets both modes' switches.
TEST_F(HostSettingsFile, FroxelPresetsSetTheGrid) {
    lightscatter::Settings s;
    s.froxels.temporal = true;
    ASSERT_EQ(lightscatter::applyMethodPreset("froxels-unreal", s), lightscatter::Method::Froxels);
    EXPECT_EQ(s.froxels.tile, 16u);
    EXPECT_EQ(s.froxels.slices, 64u);
    EXPECT_FALSE(s.froxels.temporal);
    ASSERT_EQ(lightscatter::applyMethodPreset("froxels-hdrp-temporal", s),
              lightscatter::Method::Froxels);
    EXPECT_EQ(s.froxels.tile, 8u);
    EXPECT_TRUE(s.froxels.temporal);
    EXPECT_FALSE(s.froxels.pixelHistory);
    ASSERT_EQ(lightscatter::applyMethodPreset("froxels-unreal-pixels", s),
              lightscatter::Method::Froxels);
    EXPECT_EQ(s.froxels.tile, 16u);
    EXPECT_TRUE(s.froxels.temporal);
    EXPECT_TRUE(s.froxels.pixelHistory);
    ASSERT_EQ(lightscatter::applyMethodPreset("froxels-hdrp-temporal", s),
              lightscatter::Method::Froxels);
    EXPECT_FALSE(s.froxels.pixelHistory);
    const lightscatter::Settings before = s;
    for (const char* name :
         {"froxels", "froxels-", "-temporal", "froxels-hdrp-temporal-temporal", "froxels-pixels"})
        EXPECT_FALSE(lightscatter::applyMethodPreset(name, s)) << name;
    EXPECT_EQ(s.froxels.tile, before.froxels.tile);
    EXPECT_EQ(s.froxels.temporal, before.froxels.temporal);
}

// The planes method's fields under their former names (named after "slice" until the word came
// to mean only an epipolar line) read as the fields; a file that gives one field under both names
// is refused, naming both, and the plugin's rules name the field as the file gave it.
TEST_F(HostSettingsFile, FormerNamesOfThePlaneFieldsStillRead) {
    const lightscatter::Settings p = load(R"({"slicePlanes": 200, "sliceTarget": "rgba8",
        "slicePlaneScaling": true, "sliceRange": 0.5, "sliceDither": false, "sliceBlur": 3,
        "sliceAmbient": 0.02})");
    EXPECT_EQ(p.planes.count, 200u);
    EXPECT_EQ(p.planes.target, lightscatter::PlaneTarget::Rgba8Channels);
    EXPECT_TRUE(p.planes.scaling);
    EXPECT_FLOAT_EQ(p.planes.range, 0.5f);
    EXPECT_FALSE(p.planes.dither);
    EXPECT_EQ(p.planes.blur, 3u);
    EXPECT_FLOAT_EQ(p.planes.ambient, 0.02f);
    // Old and new names mix, one name per field.
    const lightscatter::Settings mixed = load(R"({"slicePlanes": 64, "planeTarget": "float32"})");
    EXPECT_EQ(mixed.planes.count, 64u);
    EXPECT_EQ(mixed.planes.target, lightscatter::PlaneTarget::Float32);

    struct Names {
        const char *former, *current, *value;
    };
    for (const Names& n :
         {Names{"slicePlanes", "planeCount", "64"},
          Names{"sliceTarget", "planeTarget", "\"float32\""},
          Names{"slicePlaneScaling", "planeScaling", "true"},
          Names{"sliceRange", "planeRange", "0.5"}, Names{"sliceDither", "planeDither", "false"},
          Names{"sliceBlur", "planeBlur", "2"}, Names{"sliceAmbient", "planeAmbient", "0.01"}}) {
        const std::string former = n.former, current = n.current, value = n.value;
        // Read in the keys' order (nlohmann sorts an object's keys).
        const auto [first, second] = std::minmax(former, current);
        const lightscatter::SettingsField* f = lightscatter::findSettingsField(current);
        ASSERT_NE(f, nullptr) << current;
        EXPECT_EQ(
            errorFor("{\"" + current + "\": " + value + ", \"" + former + "\": " + value + "}"),
            first + " and " + second + " are one field (" + f->name + "): give it once");
    }
    EXPECT_EQ(errorFor(R"({"sliceTarget": "rgba16"})"),
              "sliceTarget = \"rgba16\": must be one of float16, float32, rgba8");
    EXPECT_EQ(errorFor(R"({"slicePlanes": 1})"), "slicePlanes = 1: must be in [2, 4096]");
    EXPECT_EQ(errorFor(R"({"sliceBlur": 9})"), "sliceBlur = 9: must be in [0, 8] (pixels)");
    // A field nested under its method's member, or named in full, and a former name of it: one
    // field given twice.
    EXPECT_EQ(errorFor(R"({"planes": {"count": 64}, "planeCount": 64})"),
              "planeCount and planes.count are one field (planes.count): give it once");
    EXPECT_EQ(load(R"({"planes": {"count": 64}, "epipolar.slices": 256})").planes.count, 64u);
    EXPECT_EQ(load(R"({"planes": {"count": 64}, "epipolar.slices": 256})").epipolar.slices, 256u);
}

TEST_F(HostSettingsFile, FieldsLeftOutKeepTheProfilesValues) {
    const auto base = lightscatter::profileSettings(lightscatter::Profile::LowHighPerformance);
    const lightscatter::Settings s = load(R"({"minMaxTrees": false})", base);
    EXPECT_EQ(s.epipolar.slices, base.epipolar.slices);
    EXPECT_EQ(s.epipolar.samplesPerSlice, base.epipolar.samplesPerSlice);
    EXPECT_EQ(s.shadowMapSize, base.shadowMapSize);
    EXPECT_FALSE(s.epipolar.minMaxTrees);
}

TEST_F(HostSettingsFile, BadFieldsAreNamed) {
    EXPECT_EQ(errorFor(R"({"slice": 4})").substr(0, 62),
              "unknown key 'slice' (known keys: shadowMapSize, shadowFilter, ");
    EXPECT_NE(errorFor(R"({"slice": 4})").find("epipolar.slices, epipolar.samplesPerSlice"),
              std::string::npos);
    EXPECT_EQ(errorFor(R"({"epipolar": {"slice": 4}})").substr(0, 40),
              "unknown key 'epipolar.slice' (known keys");
    EXPECT_EQ(errorFor(R"({"slices": 512, "slices": 256})"),
              "key 'slices' appears twice in one object");
    EXPECT_EQ(errorFor(R"({"slices": -4})"),
              "slices = -4: must be a whole number from 0 to 4294967295");
    EXPECT_EQ(errorFor(R"({"slices": 4294967296})"),
              "slices = 4294967296: must be a whole number from 0 to 4294967295");
    EXPECT_EQ(errorFor(R"({"slices": 3})"),
              "slices = 3: must be a multiple of 4 in [4, 16384] (a quarter per screen edge)");
    EXPECT_EQ(errorFor(R"({"epipolar": {"slices": 3}})"),
              "epipolar.slices = 3: must be a multiple of 4 in [4, 16384] (a quarter per screen "
              "edge)");
    EXPECT_EQ(errorFor(R"({"initialSampleStep": 3})"),
              "initialSampleStep = 3: must be a power of two in [1, 128] (the first ray-marching "
              "samples' spacing)");
    EXPECT_EQ(errorFor(R"({"refinementThreshold": 0})"),
              "refinementThreshold = 0: must be > 0 and finite (only compared)");
    EXPECT_EQ(errorFor(R"({"inscatterRefinementThreshold": -1})"),
              "inscatterRefinementThreshold = -1: must be >= 0 and finite (0: off)");
    EXPECT_EQ(errorFor(R"({"shadowDepthBias": 1e39})"),
              "shadowDepthBias = 1e+39: must be a finite number");
    EXPECT_EQ(errorFor(R"({"minMaxTrees": 1})"), "minMaxTrees = 1: must be true or false");
    EXPECT_EQ(errorFor(R"({"shadowFilter": "trilinear"})"),
              "shadowFilter = \"trilinear\": must be one of nearest, bilinear");
    EXPECT_EQ(errorFor(R"({"interpolation": 2})"),
              "interpolation = 2: must be one of shadowed-fraction, inscattering");
    EXPECT_EQ(errorFor(R"({"shadowMapSize": 16385})"),
              "shadowMapSize = 16385: must be 0 or in [1, 16384]");
    EXPECT_EQ(errorFor(R"({"planeTarget": "rgba16"})"),
              "planeTarget = \"rgba16\": must be one of float16, float32, rgba8");
    EXPECT_EQ(errorFor(R"({"noiseAmplitude": 2})"), "noiseAmplitude = 2: must be in [0, 1]");
    EXPECT_EQ(errorFor(R"({"noiseAmplitude": "loud"})"),
              "noiseAmplitude = \"loud\": must be a number");
    EXPECT_EQ(errorFor(R"({"planeCount": 1})"), "planeCount = 1: must be in [2, 4096]");
    EXPECT_EQ(errorFor(R"({"planeBlur": 9})"), "planeBlur = 9: must be in [0, 8] (pixels)");
    EXPECT_EQ(errorFor(R"({"planeDither": "yes"})"),
              "planeDither = \"yes\": must be true or false");
    EXPECT_EQ(errorFor(R"({"noiseScale": 0})"),
              "noiseScale = 0: must be in [1e-06, 1e+08] (a tile's size; lightscatter.h, "
              "limits::kMinNoiseScale)");
    // Rendered an all-NaN Lin with planes and exit 0 (issue #22): now refused before any device.
    EXPECT_EQ(errorFor(R"({"planeAmbient": 1e37})"),
              "planeAmbient = 1e+37: must be in [0, 1e+06] (1/m^2, beside the inverse square; "
              "lightscatter.h, limits::kMaxAmbient)");
    EXPECT_EQ(errorFor(R"({"noiseVelocity": [1, 2, 3]})"),
              "noiseVelocity = [1,2,3]: must be an array of 4 numbers");
    EXPECT_EQ(errorFor(R"({"noiseVelocity": 0.1})"),
              "noiseVelocity = 0.1: must be an array of 4 numbers");
    EXPECT_EQ(errorFor(R"({"lightModel": "cheap"})"),
              "lightModel = \"cheap\": must be one of full, simplified");
    EXPECT_EQ(errorFor(R"({"simplifiedA1": 0})"),
              "simplifiedA1 = 0: must be in [0.001, 1000] (seed 004's falloff I / (a1 r^2 + a0); "
              "lightscatter.h, limits::kMinSimplifiedA1)");
    EXPECT_EQ(
        errorFor(R"({"simplifiedA0": -1})"),
        "simplifiedA0 = -1: must be in [0, 1e+16] (m^2, seed 004's falloff I / (a1 r^2 + a0); "
        "lightscatter.h, limits::kMaxSimplifiedA0)");
    EXPECT_EQ(errorFor(R"({"simplifiedA0": "small"})"),
              "simplifiedA0 = \"small\": must be a number");
    EXPECT_EQ(errorFor(R"({"noiseVelocity": [0, 0, true, 0]})"),
              "noiseVelocity[2] = true: must be a number");
    EXPECT_EQ(errorFor(R"({"noiseVelocity": [0, 0, 0, 1e39]})"),
              "noiseVelocity[3] = 1e+39: must be a finite number");
    EXPECT_EQ(errorFor("[512]"), "the top level must be a JSON object of settings");
    EXPECT_EQ(errorFor("{"),
              "malformed JSON at byte 2: [json.exception.parse_error.101] parse error at line 1, "
              "column 2: syntax error while parsing object key - unexpected end of input; "
              "expected string literal");
}

// A number as the shortest text that reads back as it: how a person copies a bound from a field's
// table (0.99, 1e+30), and how the viewer saves a float (3.4028235e+38).
template <class T>
std::string shortest(T v) {
    char text[64];
    const auto r = std::to_chars(text, text + sizeof text, v);
    return std::string(text, r.ptr);
}

// `value` as the field's JSON: a Vector4 takes it in every component.
std::string fieldText(const host::SettingField& f, const std::string& value) {
    const std::string v = f.kind == host::SettingField::Kind::Vector4
                              ? "[" + value + ", " + value + ", " + value + ", " + value + "]"
                              : value;
    return "{\"" + f.name + "\": " + v + "}";
}

// A float field was compared with its double bound (issue #42): 0.99f is above 0.99, so
// "froxelHistoryWeight: 0.99" was refused with "must be in [0, 0.99]". Every bound of every field
// is accepted written as its table gives it, and the first float past it is refused with a message
// that quotes both the value and the bound as the floats compared, never the one as the other.
TEST_F(HostSettingsFile, EveryBoundIsAcceptedAtTheBoundAndQuotedAsApplied) {
    using Kind = host::SettingField::Kind;
    const double kFloatMax = std::numeric_limits<float>::max();
    size_t bounds = 0;
    for (const host::SettingField& f : host::settingFields()) {
        if (f.kind != Kind::Number && f.kind != Kind::Vector4 && f.kind != Kind::Whole) continue;
        SCOPED_TRACE(f.name);
        const bool isFloat = f.kind != Kind::Whole;
        auto fits = [&](double v) {
            const auto w = static_cast<uint64_t>(v);
            return isFloat ||
                   ((!f.powerOfTwo || (w != 0 && (w & (w - 1)) == 0)) && w % f.multipleOf == 0);
        };
        // The upper bound; FLT_MAX where only finiteness bounds it, as the viewer saves it.
        const double hi = std::min(f.max, kFloatMax);
        const std::string hiText = isFloat ? shortest(float(hi)) : shortest(hi);
        if (fits(hi)) {
            EXPECT_EQ(errorFor(fieldText(f, shortest(hi))), "(no error)") << shortest(hi);
            EXPECT_EQ(errorFor(fieldText(f, hiText)), "(no error)") << hiText;
            ++bounds;
        }
        if (!f.minExclusive && fits(f.min)) {
            EXPECT_EQ(errorFor(fieldText(f, shortest(f.min))), "(no error)") << shortest(f.min);
            ++bounds;
        }
        if (hi >= kFloatMax) continue;  // nothing past it but infinity, refused as such
        const std::string past =
            isFloat ? shortest(std::nextafter(float(hi), std::numeric_limits<float>::infinity()))
                    : shortest(hi + 1);
        const std::string m = errorFor(fieldText(f, past));
        EXPECT_NE(m.find(" = " + past + ": must be "), std::string::npos) << m;
        EXPECT_NE(m.find(hiText, m.find(": must be ")), std::string::npos) << m;
        EXPECT_NE(past, hiText);
    }
    EXPECT_GE(bounds, 40u);
    // The issue's four, by their former flat names.
    EXPECT_EQ(errorFor(R"({"froxelHistoryWeight": 0.99})"), "(no error)");
    EXPECT_EQ(errorFor(R"({"planeSpacing": 1e-6})"), "(no error)");
    EXPECT_EQ(errorFor(R"({"froxelFarDistance": 1e-6})"), "(no error)");
    EXPECT_EQ(errorFor(R"({"planeRange": 1e30})"), "(no error)");
    EXPECT_EQ(errorFor(R"({"froxelHistoryWeight": 0.9900001})"),
              "froxelHistoryWeight = 0.9900001: must be in [0, 0.99] (the history's share of "
              "each froxel; 1 would never take a new frame)");
}

// The viewer writes FLT_MAX as 3.4028235e+38, which as a double lies above FLT_MAX: it is read as
// FLT_MAX, and only a value that rounds past it is refused.
TEST_F(HostSettingsFile, TheLargestFloatAsWrittenReadsBack) {
    lightscatter::Settings s;
    s.epipolar.bilateralThreshold = std::numeric_limits<float>::max();
    s.noiseVelocity = {-std::numeric_limits<float>::max(), 0, 0, 0};
    EXPECT_NE(host::settingsFileText(s).find("3.4028235e+38"), std::string::npos);
    const lightscatter::Settings back = load(host::settingsFileText(s));
    EXPECT_EQ(back.epipolar.bilateralThreshold, s.epipolar.bilateralThreshold);
    EXPECT_EQ(back.noiseVelocity, s.noiseVelocity);
    // Half a float's step above FLT_MAX rounds to infinity.
    EXPECT_EQ(errorFor(R"({"bilateralThreshold": 3.40282357e+38})"),
              "bilateralThreshold = 3.40282357e+38: must be a finite number");
}

TEST_F(HostSettingsFile, OnlyARegularFileIsRead) {
    try {
        host::loadSettingsFile("/dev/zero", {});
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "/dev/zero: settings file is a character device, not a regular file");
    }
}

}  // namespace

namespace {

// Each field of a settings file holding `levels` arrays within one another (200 KB at 100,000).
std::string deep(const std::string& field, size_t levels) {
    return "{\"" + field + "\": " + std::string(levels, '[') + std::string(levels, ']') + "}";
}

// A deep value used to overflow the stack when its error message wrote it out (exit 139, no
// message), and a 30,000-level one made a 60 KB "line". Both are refused while parsing now.
TEST_F(HostSettingsFile, DeepNestingIsRefusedWhileParsing) {
    for (size_t levels : {size_t{30000}, size_t{100000}}) {
        for (const char* field : {"slices", "minMaxTrees", "noiseVelocity", "lightModel"}) {
            SCOPED_TRACE(std::string(field) + " " + std::to_string(levels));
            const std::string m = errorFor(deep(field, levels));
            EXPECT_EQ(m.rfind(std::string(field) + "[0][0][0]", 0), 0u) << m;
            EXPECT_NE(m.find(": arrays and objects nest more than 64 deep here"), std::string::npos)
                << m;
            EXPECT_LE(m.size(), 200u) << m;
        }
    }
}

TEST_F(HostSettingsFile, EchoedValuesAreCut) {
    std::string many = R"({"slices": [0)";
    for (int i = 1; i < 100000; ++i) many += ",0";
    const std::string m = errorFor(many + "]}");
    // 80 characters of the value: "[", 38 times "0," and "...".
    std::string echoed = "[";
    for (int i = 0; i < 38; ++i) echoed += "0,";
    EXPECT_EQ(m, "slices = " + echoed + "...: must be a whole number from 0 to 4294967295");
    const std::string key = errorFor("{\"" + std::string(100000, 'k') + "\": 1}");
    EXPECT_EQ(key.rfind("unknown key 'kkkk", 0), 0u) << key;
    EXPECT_LE(key.size(), 1000u) << key;  // the known keys follow
    EXPECT_EQ(errorFor(R"({"minMaxTrees": true, "minMaxTrees": false})"),
              "key 'minMaxTrees' appears twice in one object");
}

}  // namespace

// The file the viewer's "save settings" wrote at version 0.3 (b27d13c: every field flat, under the
// names of that release; settings/viewer_b27d13c.json, saved from a panel script that set a field
// of every method away from its default) reads into the grouped fields.
TEST(HostSettingsFileFormer, TheFileTheViewerWroteAtVersion03Reads) {
    const std::string path = LS_SOURCE_DIR "/tests/host/settings/viewer_b27d13c.json";
    const lightscatter::Settings s = host::loadSettingsFile(path, lightscatter::Settings{});
    EXPECT_EQ(s.epipolar.slices, 512u);
    EXPECT_EQ(s.epipolar.samplesPerSlice, 256u);
    EXPECT_EQ(s.epipolar.initialSampleStep, 8u);
    EXPECT_FLOAT_EQ(s.epipolar.refinementThreshold, 0.05f);
    EXPECT_FLOAT_EQ(s.epipolar.bilateralThreshold, 0.2f);
    EXPECT_FALSE(s.epipolar.minMaxTrees);
    EXPECT_EQ(s.epipolar.fixupMaxSteps, 64u);
    EXPECT_FLOAT_EQ(s.shadowDepthBias, 0.001f);
    EXPECT_EQ(s.shadowMapSize, 2048u);
    EXPECT_EQ(s.coneMarch.samples, 48u);
    EXPECT_FALSE(s.coneMarch.limited);
    EXPECT_TRUE(s.coneMarch.jitter);
    EXPECT_EQ(s.planes.count, 96u);
    EXPECT_EQ(s.planes.target, lightscatter::PlaneTarget::Float32);
    EXPECT_TRUE(s.planes.scaling);
    EXPECT_EQ(s.planes.blur, 2u);
    EXPECT_FLOAT_EQ(s.planes.ambient, 0.5f);
    EXPECT_FLOAT_EQ(s.noiseScale, 2.0f);
    EXPECT_FLOAT_EQ(s.simplifiedA0, 0.01f);
    EXPECT_EQ(s.froxels.tile, 16u);
    EXPECT_EQ(s.froxels.slices, 32u);
    EXPECT_FLOAT_EQ(s.froxels.farDistance, 40.0f);
    EXPECT_TRUE(s.froxels.temporal);
    EXPECT_FLOAT_EQ(s.froxels.historyWeight, 0.8f);
    // Every field it holds is one of today's, so that nothing it set is dropped: it round-trips
    // through today's writer to the same settings.
    const std::string rewritten = host::settingsFileText(s);
    const std::string copy =
        (fs::temp_directory_path() / ("viewer_b27d13c_" + std::to_string(::getpid()) + ".json"))
            .string();
    std::ofstream(copy) << rewritten;
    const lightscatter::Settings again = host::loadSettingsFile(copy, lightscatter::Settings{});
    fs::remove(copy);
    EXPECT_EQ(host::settingsFileText(again), rewritten);
}
