#include "settings_file.h"

#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "scene/input_file.h"
#include "scene/json_input.h"

namespace host {
namespace {

using nlohmann::json;

constexpr uint64_t kSettingsFileCap = 1 * kMiB;

constexpr const char* kFields[] = {"slices",
                                   "samplesPerSlice",
                                   "initialSampleStep",
                                   "refinementThreshold",
                                   "inscatterRefinementThreshold",
                                   "bilateralThreshold",
                                   "minMaxTrees",
                                   "shadowFilter",
                                   "fixup",
                                   "fixupMaxSteps",
                                   "shadowDepthBias",
                                   "interpolation",
                                   "shadowMapSize",
                                   "coneSamples",
                                   "coneLimited",
                                   "coneJitter",
                                   "shadowSampling",
                                   "slicePlanes",
                                   "sliceTarget",
                                   "slicePlaneScaling",
                                   "sliceRange",
                                   "sliceDither",
                                   "sliceBlur",
                                   "sliceAmbient",
                                   "noiseAmplitude",
                                   "noiseScale",
                                   "noiseVelocity",
                                   "lightModel",
                                   "simplifiedA0",
                                   "simplifiedA1"};

std::string knownFields() {
    std::string s;
    for (const char* f : kFields) s += (s.empty() ? "" : ", ") + std::string(f);
    return s;
}

class SettingsReader {
  public:
    explicit SettingsReader(const std::string& path) : path_(path) {}

    lightscatter::Settings read(lightscatter::Settings s) const {
        const json root = parse();
        if (!root.is_object()) fail("the top level must be a JSON object of settings");
        for (const auto& item : root.items()) {
            const std::string& key = item.key();
            const json& v = item.value();
            if (key == "slices")
                s.slices = whole(v, key);
            else if (key == "samplesPerSlice")
                s.samplesPerSlice = whole(v, key);
            else if (key == "initialSampleStep")
                s.initialSampleStep = whole(v, key);
            else if (key == "refinementThreshold")
                s.refinementThreshold = number(v, key);
            else if (key == "inscatterRefinementThreshold")
                s.inscatterRefinementThreshold = number(v, key);
            else if (key == "bilateralThreshold")
                s.bilateralThreshold = number(v, key);
            else if (key == "minMaxTrees")
                s.minMaxTrees = boolean(v, key);
            else if (key == "shadowFilter")
                s.shadowFilter = oneOf<lightscatter::ShadowFilter>(
                    v, key,
                    {{"bilinear", lightscatter::ShadowFilter::Bilinear},
                     {"nearest", lightscatter::ShadowFilter::Nearest}});
            else if (key == "fixup")
                s.fixup = boolean(v, key);
            else if (key == "fixupMaxSteps")
                s.fixupMaxSteps = whole(v, key);
            else if (key == "shadowDepthBias")
                s.shadowDepthBias = number(v, key);
            else if (key == "interpolation")
                s.interpolation = oneOf<lightscatter::Interpolation>(
                    v, key,
                    {{"shadowed-fraction", lightscatter::Interpolation::ShadowedFraction},
                     {"inscattering", lightscatter::Interpolation::Inscattering}});
            else if (key == "coneSamples")
                s.coneSamples = whole(v, key);
            else if (key == "coneLimited")
                s.coneLimited = boolean(v, key);
            else if (key == "coneJitter")
                s.coneJitter = boolean(v, key);
            else if (key == "shadowSampling")
                s.shadowSampling = boolean(v, key);
            else if (key == "slicePlanes")
                s.slicePlanes = whole(v, key);
            else if (key == "sliceTarget")
                s.sliceTarget = oneOf<lightscatter::SliceTarget>(
                    v, key,
                    {{sliceTargetName(lightscatter::SliceTarget::Float16),
                      lightscatter::SliceTarget::Float16},
                     {sliceTargetName(lightscatter::SliceTarget::Float32),
                      lightscatter::SliceTarget::Float32},
                     {sliceTargetName(lightscatter::SliceTarget::Rgba8Channels),
                      lightscatter::SliceTarget::Rgba8Channels}});
            else if (key == "slicePlaneScaling")
                s.slicePlaneScaling = boolean(v, key);
            else if (key == "sliceRange")
                s.sliceRange = number(v, key);
            else if (key == "sliceDither")
                s.sliceDither = boolean(v, key);
            else if (key == "sliceBlur")
                s.sliceBlur = whole(v, key);
            else if (key == "sliceAmbient")
                s.sliceAmbient = number(v, key);
            else if (key == "noiseAmplitude")
                s.noiseAmplitude = number(v, key);
            else if (key == "noiseScale")
                s.noiseScale = number(v, key);
            else if (key == "noiseVelocity")
                s.noiseVelocity = numbers<4>(v, key);
            else if (key == "lightModel")
                s.lightModel = oneOf<lightscatter::LightModel>(
                    v, key,
                    {{lightModelName(lightscatter::LightModel::Full),
                      lightscatter::LightModel::Full},
                     {lightModelName(lightscatter::LightModel::Simplified),
                      lightscatter::LightModel::Simplified}});
            else if (key == "simplifiedA0")
                s.simplifiedA0 = number(v, key);
            else if (key == "simplifiedA1")
                s.simplifiedA1 = number(v, key);
            else if (key == "shadowMapSize") {
                s.shadowMapSize = whole(v, key);
                if (s.shadowMapSize < 1 || s.shadowMapSize > 16384)
                    fail(key + " = " + echo(v) + ": must be from 1 to 16384");
            } else {
                fail("unknown key '" + echoText(key) + "' (known keys: " + knownFields() + ")");
            }
        }
        checkWithThePlugin(s);
        return s;
    }

  private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error(path_ + ": " + what);
    }

    json parse() const {
        try {
            return readJsonFile(path_, "settings file", kSettingsFileCap);
        } catch (const JsonInputError& e) {
            throw std::runtime_error(e.what());
        }
    }

    uint32_t whole(const json& v, const std::string& key) const {
        const bool negative =
            v.is_number_integer() && !v.is_number_unsigned() && v.get<int64_t>() < 0;
        if (!v.is_number_integer() || negative ||
            v.get<uint64_t>() > std::numeric_limits<uint32_t>::max())
            fail(key + " = " + echo(v) + ": must be a whole number from 0 to 4294967295");
        return static_cast<uint32_t>(v.get<uint64_t>());
    }

    float number(const json& v, const std::string& key) const {
        if (!v.is_number()) fail(key + " = " + echo(v) + ": must be a number");
        const double d = v.get<double>();
        if (!std::isfinite(d) || std::fabs(d) > double(std::numeric_limits<float>::max()))
            fail(key + " = " + echo(v) + ": must be a finite number");
        return static_cast<float>(d);
    }

    template <size_t N>
    std::array<float, N> numbers(const json& v, const std::string& key) const {
        if (!v.is_array() || v.size() != N)
            fail(key + " = " + echo(v) + ": must be an array of " + std::to_string(N) + " numbers");
        std::array<float, N> out{};
        for (size_t i = 0; i < N; ++i) out[i] = number(v[i], key + "[" + std::to_string(i) + "]");
        return out;
    }

    bool boolean(const json& v, const std::string& key) const {
        if (!v.is_boolean()) fail(key + " = " + echo(v) + ": must be true or false");
        return v.get<bool>();
    }

    template <class Enum>
    Enum oneOf(const json& v, const std::string& key,
               std::initializer_list<std::pair<const char*, Enum>> choices) const {
        std::string names;
        for (const auto& [word, value] : choices) {
            if (v.is_string() && v.get<std::string>() == word) return value;
            names += (names.empty() ? "" : ", ") + std::string(word);
        }
        fail(key + " = " + echo(v) + ": must be one of " + names);
    }

    // The plugin's own rules (multiples, powers of two, ranges), applied without a GPU through
    // its budget, and reported in this file's terms.
    void checkWithThePlugin(const lightscatter::Settings& s) const {
        try {
            (void)lightscatter::budget(lightscatter::Profile::Custom, 64, 64, 64,
                                       lightscatter::LightType::Spot, &s);
        } catch (const lightscatter::InvalidInput& e) {
            std::string why = e.what();
            for (const char* prefix : {"lightscatter: ", "custom."})
                if (why.rfind(prefix, 0) == 0) why.erase(0, std::char_traits<char>::length(prefix));
            fail(why);
        }
    }

    std::string path_;
};

}  // namespace

lightscatter::Settings loadSettingsFile(const std::string& path, lightscatter::Settings base) {
    return SettingsReader(path).read(base);
}

const char* lightModelName(lightscatter::LightModel model) {
    return model == lightscatter::LightModel::Simplified ? "simplified" : "full";
}

const char* sliceTargetName(lightscatter::SliceTarget target) {
    switch (target) {
        case lightscatter::SliceTarget::Float16:
            return "float16";
        case lightscatter::SliceTarget::Float32:
            return "float32";
        case lightscatter::SliceTarget::Rgba8Channels:
            return "rgba8";
    }
    return "unknown";
}

}  // namespace host
