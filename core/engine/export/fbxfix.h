#pragma once

#include <string>
#include <string_view>

namespace sylva::exporter {

/// Repairs binary FBX 7.5 as Assimp 5.2.5 writes it, and states metres as its unit.
///
/// Assimp ends a node with children at the end of its last child, without the 25-byte null
/// record that FBX 7.5 requires there (and pads the footer differently from the FBX SDK), so
/// neither Blender ("failed to read nested block sentinel") nor Assimp itself can read the
/// file back. This parses the node tree (27-byte header, then records of end offset, property
/// count, property bytes, name, properties, children), writes it again with a null record
/// after every child list and the top-level list, recomputes every end offset, and appends the
/// footer the way the FBX SDK and Blender write it. Property bytes are copied unchanged except
/// for GlobalSettings' UnitScaleFactor and OriginalUnitScaleFactor, set to \p unitScale
/// (centimetres per unit: 100 = the file is in metres, as Sylva's geometry is).
/// \throw InvalidInput when the bytes are not a well-formed binary FBX of version 7.5 or later.
std::string repairAssimpFbxBinary(std::string_view bytes, double unitScale = 100.0);

/// The same unit statement for ASCII FBX: rewrites the value of the `UnitScaleFactor` and
/// `OriginalUnitScaleFactor` properties (`P: "UnitScaleFactor", "double", "Number", "",1`).
std::string setFbxAsciiUnitScale(std::string text, double unitScale = 100.0);

} // namespace sylva::exporter
