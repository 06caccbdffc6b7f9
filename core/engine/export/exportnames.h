#pragma once

#include <string>

namespace sylva::exporter {

/// \p speciesName as an object name for OBJ/glTF/FBX: letters, digits and '-' kept, anything
/// else '_' ("tree" when empty), as `sylva-cli tree` and the editor name a species' object.
std::string objectNameFor(const std::string& speciesName);

/// \p name with every character but letters, digits, '-' and '_' replaced by '_': the stem
/// the LOD chain and the wind's Pivot Painter files give their files.
std::string fileSafeName(const std::string& name);

} // namespace sylva::exporter
