#pragma once

#include "document/commands/command.h"

namespace sylva::doc::cmd {

/// Replaces species \p index (a parameter or grammar edit of node \p node); merges while the
/// same node is being edited (a slider drag, a burst of typing).
QUndoCommand* changeSpecies(Document& doc, int index, const ProjectSpecies& oldSpecies,
                            const ProjectSpecies& newSpecies, const QString& node, bool commit,
                            const QString& label);

} // namespace sylva::doc::cmd
