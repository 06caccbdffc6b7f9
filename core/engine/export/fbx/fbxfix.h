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

/// What the repair states besides the repaired structure.
struct FbxRepairOptions {
    double unitScale = 100.0; ///< centimetres per unit (100: metres)
    /// Frames per second of the file's animation (> 0): GlobalSettings' TimeMode becomes custom
    /// (14) with this CustomFrameRate, which Blender and Assimp sample the curves at. Assimp
    /// writes 24 fps (TimeMode 11) whatever the animation's rate. 0 leaves both.
    double frameRate = 0.0;
    /// Length of the animation in seconds (> 0): every AnimationStack's LocalStop and
    /// ReferenceStop and GlobalSettings' TimeSpanStop. Assimp writes whole seconds for the
    /// stack (an integer division) and 1 s for the scene. 0 leaves them.
    double animationSeconds = 0.0;
};

/// The repair with the unit, the frame rate and the animation's length of \p options. Also
/// gives AnimationLayer and References records their empty child list: Assimp writes no null
/// record there (it puts an empty string where its null record should be), so Assimp's own
/// reader finds no scope in the layer ("expected compound scope") and drops the animation.
std::string repairAssimpFbxBinary(std::string_view bytes, const FbxRepairOptions& options);

/// The same unit statement for ASCII FBX: rewrites the value of the `UnitScaleFactor` and
/// `OriginalUnitScaleFactor` properties (`P: "UnitScaleFactor", "double", "Number", "",1`).
std::string setFbxAsciiUnitScale(std::string text, double unitScale = 100.0);

} // namespace sylva::exporter
