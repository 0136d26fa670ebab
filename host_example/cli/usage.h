#pragma once
// The command line's usage text: all commands, or one command with its options explained.
#include <string>

namespace host {

std::string usage();                                // every command, one or two lines each
std::string commandUsage(const std::string& name);  // "" for an unknown command

}  // namespace host
