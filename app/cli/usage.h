#pragma once

#include <string>

namespace sylva::cli {

/// The help text of \p command (usage line, arguments and options), what
/// `sylva-cli <command> --help` prints; nullptr for an unknown command.
const char* commandHelp(const std::string& command);

/// The first line of commandHelp(): "usage: sylva-cli <command> ...".
std::string commandUsageLine(const std::string& command);

} // namespace sylva::cli
