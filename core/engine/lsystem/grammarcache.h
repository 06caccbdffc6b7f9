#pragma once
// Parsed grammars kept for the next growth: a species grown at seed after seed (`import sylva`,
// the editor's preview, a forest's variants) parsed its grammar file again every time.
#include <filesystem>
#include <memory>
#include <string>

#include "engine/lsystem/grammar.h"

namespace sylva::lsys {

/// The grammar in \p path, parsed once for each version of the file: while the file's size,
/// modification time, inode and device are those of the last parse, that parse is returned
/// (one stat() instead of an open, a read and a parse). A file written in the last two seconds
/// is parsed again at every call (its time may not yet tell a second write apart). Throws IoError
/// when the file cannot be read and InvalidInput with parseGrammar()'s diagnostics (a failed parse
/// is not kept). Thread-safe; keeps the last kGrammarCacheEntries files.
std::shared_ptr<const Grammar> parsedGrammarFile(const std::filesystem::path& path);

/// parseGrammar(text, fileName), kept for the same text and file name (inline grammars).
std::shared_ptr<const Grammar> parsedGrammarText(const std::string& text,
                                                 const std::string& fileName);

inline constexpr std::size_t kGrammarCacheEntries = 16;

} // namespace sylva::lsys
