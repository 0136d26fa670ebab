#pragma once
// Rows of a method's field table (lightscatter::SettingsField), written against the method's own
// settings struct: `FieldsOf<EpipolarSettings> f("epipolar", &Settings::epipolar)` and then one
// chain of calls per field, so that a field's name, range, slider, profile values and doc are
// written once, beside its accessors.
#include <cmath>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "lightscatter/settings.h"

namespace ls {

using lightscatter::Settings;
using lightscatter::SettingsField;

// A Number's bound when only finiteness limits it.
inline constexpr double kFiniteMax = 3.4028234663852886e38;  // FLT_MAX

// Settings' own fields: what every method that samples a shadow map reads, and what a frame asks
// of its method beyond docs/model.md (shared_settings.cpp).
std::vector<SettingsField> sharedSettingsFields();

// One row, being written.
class FieldRow {
  public:
    explicit FieldRow(SettingsField& f) : f_(&f) {}
    // Its names before version 0.4, newest first.
    FieldRow& former(std::initializer_list<const char*> names) {
        for (const char* n : names) f_->formerNames.emplace_back(n);
        return *this;
    }
    FieldRow& slider(double lo, double hi, bool logarithmic = false) {
        f_->sliderMin = lo;
        f_->sliderMax = hi;
        f_->logarithmic = logarithmic;
        return *this;
    }
    // (min, max] instead of [min, max].
    FieldRow& aboveMin() {
        f_->minExclusive = true;
        return *this;
    }
    FieldRow& zeroIsOff() {
        f_->zeroIsOff = true;
        return *this;
    }
    FieldRow& multipleOf(uint32_t n) {
        f_->multipleOf = n;
        return *this;
    }
    FieldRow& powerOfTwo() {
        f_->powerOfTwo = true;
        return *this;
    }
    // Each sized profile's value, in lightscatter::Profile's order.
    FieldRow& profiles(std::array<double, lightscatter::kSizedProfiles> values) {
        f_->profileSized = true;
        f_->profileValues = values;
        return *this;
    }
    FieldRow& doc(const char* text) {
        f_->doc = text;
        return *this;
    }

  private:
    SettingsField* f_;
};

// The rows of one struct of Settings: a method's (`member` its member of Settings), or Settings'
// own (no member, no group).
template <class Group>
class FieldsOf {
  public:
    FieldsOf(std::string group, Group Settings::*member)
        : group_(std::move(group)), member_(member) {}
    FieldsOf() = default;

    FieldRow whole(const char* name, uint32_t Group::*m, double lo, double hi, const char* rule) {
        SettingsField& f = add(name, SettingsField::Kind::Whole, lo, hi, rule);
        f.get = [g = member_, m](const Settings& s, int) {
            return static_cast<double>(of(g, s).*m);
        };
        f.set = [g = member_, m](Settings& s, double v, int) {
            of(g, s).*m =
                static_cast<uint32_t>(std::fmin(std::fmax(std::round(v), 0.0), 4294967295.0));
        };
        return FieldRow(f);
    }
    FieldRow number(const char* name, float Group::*m, double lo, double hi, const char* rule) {
        SettingsField& f = add(name, SettingsField::Kind::Number, lo, hi, rule);
        f.get = [g = member_, m](const Settings& s, int) {
            return static_cast<double>(of(g, s).*m);
        };
        f.set = [g = member_, m](Settings& s, double v, int) {
            of(g, s).*m = static_cast<float>(v);
        };
        return FieldRow(f);
    }
    FieldRow boolean(const char* name, bool Group::*m) {
        SettingsField& f = add(name, SettingsField::Kind::Boolean, 0, 1, "");
        f.get = [g = member_, m](const Settings& s, int) { return of(g, s).*m ? 1.0 : 0.0; };
        f.set = [g = member_, m](Settings& s, double v, int) { of(g, s).*m = v != 0.0; };
        return FieldRow(f);
    }
    // `names`: the enum's values' names, in its order.
    template <class Enum>
    FieldRow choice(const char* name, Enum Group::*m, std::vector<std::string> names) {
        const double last = static_cast<double>(names.size()) - 1;
        SettingsField& f = add(name, SettingsField::Kind::Choice, 0, last, "");
        f.choices = std::move(names);
        f.get = [g = member_, m](const Settings& s, int) {
            return static_cast<double>(static_cast<int>(of(g, s).*m));
        };
        f.set = [g = member_, m](Settings& s, double v, int) {
            of(g, s).*m = static_cast<Enum>(static_cast<int>(v));
        };
        return FieldRow(f);
    }
    FieldRow vector4(const char* name, std::array<float, 4> Group::*m, double lo, double hi,
                     const char* rule) {
        SettingsField& f = add(name, SettingsField::Kind::Vector4, lo, hi, rule);
        f.get = [g = member_, m](const Settings& s, int c) {
            return static_cast<double>((of(g, s).*m)[static_cast<size_t>(c & 3)]);
        };
        f.set = [g = member_, m](Settings& s, double v, int c) {
            (of(g, s).*m)[static_cast<size_t>(c & 3)] = static_cast<float>(v);
        };
        return FieldRow(f);
    }

    std::vector<SettingsField> take() { return std::move(*rows_); }

  private:
    SettingsField& add(const char* name, SettingsField::Kind kind, double lo, double hi,
                       const char* rule) {
        SettingsField f;
        f.name = group_.empty() ? std::string(name) : group_ + "." + name;
        f.kind = kind;
        f.min = f.sliderMin = lo;
        f.max = f.sliderMax = hi;
        f.rule = rule;
        rows_->push_back(std::move(f));
        return rows_->back();
    }
    using Member = Group Settings::*;
    static const Group& of(Member g, const Settings& s) {
        if constexpr (std::is_same_v<Group, Settings>)
            return s;
        else
            return s.*g;
    }
    static Group& of(Member g, Settings& s) {
        if constexpr (std::is_same_v<Group, Settings>)
            return s;
        else
            return s.*g;
    }

    std::string group_;
    Member member_ = nullptr;
    std::shared_ptr<std::vector<SettingsField>> rows_ =
        std::make_shared<std::vector<SettingsField>>();
};

}  // namespace ls
