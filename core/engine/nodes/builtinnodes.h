#pragma once

// What the built-in node types offer beyond their registration (builtinnodes.cpp): the one
// place outside each type's own file that names the types.

#include <string>

#include "engine/graph/graph.h"

namespace sylva::nodes {

/// The species a bare grammar file is wrapped into (`sylva-cli tree file.lsys`, a grammar
/// opened as a species): node `grow`, the built-in L-system generator reading \p grammarFile
/// (relative to the graph's baseDir), into node `mesh`, the built-in mesher, its output. The
/// caller sets name, baseDir and sourceFile.
graph::SpeciesGraph grammarSpecies(const std::string& grammarFile);

} // namespace sylva::nodes
