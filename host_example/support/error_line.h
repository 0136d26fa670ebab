#pragma once
// The one line an error becomes on stderr, after main() puts "lightscatter: " in front.
#include <string>

namespace host {

// Drops a "lightscatter: " the message already starts with (the plugin's messages carry their
// own, which made "lightscatter: lightscatter: ...") and joins several lines with "; ".
std::string errorLine(const std::string& message);

}  // namespace host
