#pragma once
// Text that came from a user (a path, a label, a value) on its way to a terminal: a file named
// "t\e]0;PWNED\a.json" must not set the terminal's title, and a megabyte of it must not become a
// megabyte of error line.
#include <cstddef>
#include <string>

namespace host {

// The longest line the program prints about one thing: room for two paths of PATH_MAX (4096)
// and the words around them; everything echoed from a file is cut far shorter where it is quoted.
constexpr size_t kMaxLineChars = 10000;

// `text` with every control character (C0, DEL, and C1 written as UTF-8) escaped as JSON writes
// it ("\n", "\u001b"), cut to at most `limit` bytes with "..." at the cut, never inside a UTF-8
// sequence.
std::string terminalText(const std::string& text, size_t limit = kMaxLineChars);

}  // namespace host
