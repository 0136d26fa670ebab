#pragma once
// --settings FILE.json: lightscatter::Settings by field name, for the custom profile.
#include <string>

#include <lightscatter/lightscatter.h>

namespace host {

// Reads FILE.json, a JSON object whose keys are fields of lightscatter::Settings; each field it
// gives replaces the one in `base` (the chosen profile's settings). Unknown or repeated keys,
// wrong types and values the plugin would refuse throw one line naming the file and the field.
lightscatter::Settings loadSettingsFile(const std::string& path, lightscatter::Settings base);

}  // namespace host
