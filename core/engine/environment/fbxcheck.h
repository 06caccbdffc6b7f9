#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace sylva::env {

/// Most nested scopes (`{ … }` in ASCII, records in records in binary) of an FBX file: Assimp's
/// readers recurse per scope (100,000 nested ASCII scopes overflowed the stack). Real files
/// nest a handful.
inline constexpr std::uint64_t kMaxFbxNesting = 256;

/// Checks what Debian's Assimp 5.2.5 trusts in an FBX file (binary: a `Kaydara FBX Binary`
/// magic; otherwise ASCII) before it reads it: scopes nested at most kMaxFbxNesting deep, and
/// the models' parent links (`C: "OO", child, parent`) as Assimp's converter follows them from
/// the root: no loop (a model that is its own parent or ancestor recursed until the stack
/// overflowed, finding 29), at most kMaxSceneNodes models once a model with several parents is
/// copied under each, at most kMaxSceneDepth deep (scenegraphwalk.h). The binary record
/// structure is checked as Assimp's tokenizer checks it (record ends inside their parent, the
/// property lists and the null records that close nested lists).
/// \param where the start of every message ("obstacle mesh '<file>': cannot read it: ").
/// \throw InvalidInput for a loop or a malformed binary record, LimitExceeded for the limits.
void checkFbx(std::string_view bytes, const std::string& where);

} // namespace sylva::env
