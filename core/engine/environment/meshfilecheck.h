#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "engine/util/text.h"

namespace sylva::env {

/// Most triangles an obstacle or terrain mesh may hold, and most items any element of a PLY
/// header may declare (Assimp reserves memory for what a header declares before reading it).
/// About 1 GB of collision data; decimate larger meshes before using them as obstacles.
inline constexpr std::size_t kMaxObstacleTriangles = 10'000'000;

/// Checks the parts of a mesh file that Debian's Assimp 5.2.5 trusts without checking, before
/// the file is handed to it (fuzzing found Assimp reading past a PLY header that has no
/// `end_header`). Today: PLY files (by extension or by their `ply` first line) must have a
/// well-formed header (format, element and property lines, `end_header`), element counts of at
/// most \p maxItems, at most one `vertex` element and one `face` or `tristrips` element (Assimp
/// sizes its arrays by the first and wrote a later, larger one past them: fuzz finding 24), no
/// control characters in the header (Assimp also ends a line at `\r`, `\0` and `\f`), and at
/// least as many data bytes (binary) or lines (ASCII) as the header declares. Collada files (by
/// extension or a `<COLLADA` root element) must declare every `count` as a whole number from 1
/// to 9·maxItems (every data array must declare one) and hold only whole numbers in their index
/// lists (`<p>`, `<v>`, `<vcount>`): Assimp reserves what counts declare, crashed on a count of
/// 0 or not a number, and asked for 2.4 GB for a stray token in an index list. Every Collada
/// accessor must fit in the `float_array` it names (`offset + (count − 1)·stride + params`, each a
/// whole number: Assimp reads them unchecked, SEGV on a large offset), and skins, animations and
/// name arrays are refused (obstacles are static; an accessor over a name array crashed Assimp).
/// Binary glTF files (a `glTF` magic, whatever the extension) must be version 1 or 2 and declare a
/// total length and JSON and binary chunk lengths that fit in the file: Assimp allocates the JSON
/// chunk's length before checking it (4 GB for a 2 KB file). glTF JSON (binary, `.gltf`, or
/// any file that starts like JSON) must parse, draw no primitive as a line loop or a
/// triangle fan or a line strip (modes 2, 6, 3: Assimp builds those from earlier faces, read
/// through a null pointer when one was empty, and asked for 64 GB for an empty strip), nor a
/// triangle strip of fewer than 3 vertices, and keep every accessor inside its buffer view, every
/// view inside its buffer and every buffer inside its data (Assimp read past a buffer);
/// sparse accessors, and skins without inverse bind matrices, are refused. A Collada index list
/// must come after its primitive's VERTEX input (and a polylist's `<vcount>`), hold whole
/// numbers only, and not be shorter than its primitive declares; a Collada scene graph
/// (`<instance_node>`), a glTF node hierarchy and an FBX file's model links (checkFbx(), by
/// extension, magic or content) must not loop and stay within kMaxSceneNodes and
/// kMaxSceneDepth. Other formats pass
/// unchecked (OBJ files go through objGeometryOnly() instead).
///
/// \throw InvalidInput "obstacle mesh '<file>': PLY ..." naming what is wrong.
/// \throw LimitExceeded when a PLY element count exceeds \p maxItems or a Collada count
/// 9·\p maxItems.
/// \throw IoError when the file cannot be read.
void checkMeshFile(const std::filesystem::path& file, std::size_t maxItems = kMaxObstacleTriangles);

/// The text of an OBJ file with its line (`l`) and point (`p`) elements and its material
/// libraries (`mtllib`, and `mg`) made comments, as Debian's Assimp 5.2.5 would split it into
/// lines. Obstacles keep only triangles, so nothing is lost. Assimp's line elements are unsafe:
/// one of a single vertex takes a vertex slot without counting an index, and a later line then
/// writes past the vertex array (fuzz findings 12 and 15; upstream oss-fuzz 54187, fixed after
/// 5.2.5). A file read from memory reads its own text as the material library that `mtllib`
/// names, and the MTL parser wrote past a buffer on an OBJ's text (finding 18).
std::string objGeometryOnly(std::string text);

} // namespace sylva::env
