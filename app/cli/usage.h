#pragma once

#include <string>

namespace sylva::cli {

/// The help text of \p command (usage line, arguments and options), what
/// `sylva-cli <command> --help` prints; nullptr for an unknown command.
const char* commandHelp(const std::string& command);

/// \p text with "{formats}" as the format table's extensions for a usage line
/// ("obj,usda,glb,gltf,fbx") and "{extensions}" as a list (".obj, .usda, .glb, .gltf, .fbx").
std::string expandFormats(std::string text);

/// The first line of commandHelp(): "usage: sylva-cli <command> ...".
std::string commandUsageLine(const std::string& command);

} // namespace sylva::cli
