#pragma once

#include "document/project.h"

namespace sylva::doc {

/// Reads and checks every file \p project links before anything is replaced by it: each species
/// file (parsed, its graph validated against the node metadata), each grammar a species graph
/// names (inline or `grammar_file`, parsed: errors carry file:line:col; a file into the
/// parsed-grammar cache the growth reads), every other file a node parameter names (it must be
/// readable), and every obstacle and terrain mesh (loaded as the generation loads it, into the
/// scene cache the generation then reads). Opening is atomic because Document::open calls this
/// first. \throw InvalidInput / IoError / LimitExceeded naming the linked file.
void checkLinkedFiles(const Project& project);

} // namespace sylva::doc
