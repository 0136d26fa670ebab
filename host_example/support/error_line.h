#pragma once
// The one line an error becomes on stderr, after main() puts "lightscatter: " in front.
#include <string>

namespace host {

// Drops a "lightscatter: " the message already starts with (the plugin's messages carry their
// own, which made "lightscatter: lightscatter: ...") and joins several lines with "; ". Whatever
// reaches it of a user's input is then still one line of at most kMaxLineChars, control characters
// escaped (terminal_text.h): the backstop behind each message's own cut of what it quotes.
std::string errorLine(const std::string& message);

}  // namespace host
