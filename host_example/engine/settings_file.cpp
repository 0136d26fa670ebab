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

bool isGroup(const std::string& key) {
    for (const SettingField& f : settingFields())
        if (fieldGroup(f) == key) return true;
    return false;
}

class SettingsReader {
  public:
    explicit SettingsReader(const std::string& path) : path_(path) {}

    lightscatter::Settings read(lightscatter::Settings s) const {
        const json root = parse();
        if (!root.is_object()) fail("the top level must be a JSON object of settings");
        // Each field given, with its key as written (a method's fields nested under its member,
        // or named in full, or by a former flat name).
        std::vector<std::pair<const SettingField*, std::string>> given;
        auto take = [&](const std::string& key, const json& v) {
            const SettingField* f = findSettingField(key);
            if (!f)
                fail("unknown key '" + echoText(key) + "' (known keys: " + knownFieldNames() + ")");
            for (const auto& [other, written] : given)
                if (other == f)
                    fail(written + " and " + key + " are one field (" + f->name +
                         "): give it once");
            given.emplace_back(f, key);
            try {
                setFieldFromJson(s, *f, v, key);
            } catch (const std::runtime_error& e) {
                fail(e.what());
            }
        };
        for (const auto& item : root.items()) {
            if (item.value().is_object() && isGroup(item.key())) {
                for (const auto& inner : item.value().items())
                    take(item.key() + "." + inner.key(), inner.value());
            } else {
                take(item.key(), item.value());
            }
        }
        checkWithThePlugin(s, given);
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

    // The plugin's own rules (multiples, powers of two, ranges), reported in this file's terms:
    // under the name the file gave the field.
    void checkWithThePlugin(
        const lightscatter::Settings& s,
        const std::vector<std::pair<const SettingField*, std::string>>& given) const {
        try {
            lightscatter::checkSettings(s, "");
        } catch (const lightscatter::InvalidInput& e) {
            std::string why = e.what();
            const std::string lead = "lightscatter: ";
            if (why.rfind(lead, 0) == 0) why.erase(0, lead.size());
            for (const auto& [f, written] : given)
                if (why.rfind(f->name + " ", 0) == 0 || why.rfind(f->name + "[", 0) == 0)
                    why.replace(0, f->name.size(), written);
            fail(why);
        }
    }

    std::string path_;
};

}  // namespace

lightscatter::Settings loadSettingsFile(const std::string& path, lightscatter::Settings base) {
    return SettingsReader(path).read(base);
}

}  // namespace host
