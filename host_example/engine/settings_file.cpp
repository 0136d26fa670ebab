#include "settings_file.h"

#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "scene/input_file.h"
#include "scene/json_input.h"
#include "settings_fields.h"

namespace host {
namespace {

using nlohmann::json;

constexpr uint64_t kSettingsFileCap = 1 * kMiB;

// The planes method's fields were named after "slice" until the word came to mean only an
// epipolar line; files written with those names still read.
constexpr std::pair<const char*, const char*> kFormerNames[] = {
    {"slicePlanes", "planeCount"},         {"sliceTarget", "planeTarget"},
    {"slicePlaneScaling", "planeScaling"}, {"sliceRange", "planeRange"},
    {"sliceDither", "planeDither"},        {"sliceBlur", "planeBlur"},
    {"sliceAmbient", "planeAmbient"}};

// The field a key names: itself, or the field of its former name.
std::string currentName(const std::string& key) {
    for (const auto& [former, current] : kFormerNames)
        if (key == former) return current;
    return key;
}

std::string knownFields() {
    std::string s;
    for (const SettingField& f : settingFields())
        s += (s.empty() ? "" : ", ") + std::string(f.name);
    return s;
}

class SettingsReader {
  public:
    explicit SettingsReader(const std::string& path) : path_(path) {}

    lightscatter::Settings read(lightscatter::Settings s) const {
        const json root = parse();
        if (!root.is_object()) fail("the top level must be a JSON object of settings");
        for (const auto& item : root.items()) {
            const std::string& key = item.key();  // as written, for the messages
            const std::string field = currentName(key);
            if (field != key && root.contains(field))
                fail(key + " and " + field + " are one field (" + key +
                     " is its former name): give it once");
            const json& v = item.value();
            const SettingField* f = findSettingField(field);
            if (!f) fail("unknown key '" + echoText(key) + "' (known keys: " + knownFields() + ")");
            switch (f->kind) {
                case SettingField::Kind::Whole:
                    setFieldValue(s, *f, whole(v, key));
                    break;
                case SettingField::Kind::Number:
                    setFieldValue(s, *f, number(v, key));
                    break;
                case SettingField::Kind::Boolean:
                    setFieldValue(s, *f, boolean(v, key) ? 1.0 : 0.0);
                    break;
                case SettingField::Kind::Choice:
                    setFieldValue(s, *f, static_cast<double>(oneOf(v, key, f->choices)));
                    break;
                case SettingField::Kind::Vector4: {
                    const std::array<float, 4> a = numbers<4>(v, key);
                    for (int c = 0; c < 4; ++c) setFieldValue(s, *f, a[c], c);
                    break;
                }
            }
            if (field == "shadowMapSize" && (s.shadowMapSize < 1 || s.shadowMapSize > 16384))
                fail(key + " = " + echo(v) + ": must be from 1 to 16384");
        }
        checkWithThePlugin(s, root);
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

    // The index of the choice `v` names.
    size_t oneOf(const json& v, const std::string& key,
                 const std::vector<const char*>& choices) const {
        std::string names;
        for (size_t i = 0; i < choices.size(); ++i) {
            if (v.is_string() && v.get<std::string>() == choices[i]) return i;
            names += (names.empty() ? "" : ", ") + std::string(choices[i]);
        }
        fail(key + " = " + echo(v) + ": must be one of " + names);
    }

    // The plugin's own rules (multiples, powers of two, ranges), applied without a GPU through
    // its budget, and reported in this file's terms: under the name `root` gave the field.
    void checkWithThePlugin(const lightscatter::Settings& s, const json& root) const {
        try {
            (void)lightscatter::budget(lightscatter::Profile::Custom, 64, 64, 64,
                                       lightscatter::LightType::Spot, &s);
        } catch (const lightscatter::InvalidInput& e) {
            std::string why = e.what();
            for (const char* prefix : {"lightscatter: ", "custom."})
                if (why.rfind(prefix, 0) == 0) why.erase(0, std::char_traits<char>::length(prefix));
            for (const auto& [former, current] : kFormerNames)
                if (root.contains(former) && why.rfind(std::string(current) + " ", 0) == 0)
                    why.replace(0, std::char_traits<char>::length(current), former);
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

const char* planeTargetName(lightscatter::PlaneTarget target) {
    switch (target) {
        case lightscatter::PlaneTarget::Float16:
            return "float16";
        case lightscatter::PlaneTarget::Float32:
            return "float32";
        case lightscatter::PlaneTarget::Rgba8Channels:
            return "rgba8";
    }
    return "unknown";
}

}  // namespace host
