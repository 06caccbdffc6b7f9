#pragma once

#include "document/commands/command.h"

namespace sylva::doc::cmd {

QUndoCommand* addObstacle(Document& doc, int index, const ProjectObstacle& obstacle);
QUndoCommand* removeObstacle(Document& doc, int index);
/// Moves, rotates or scales an obstacle; merges while a drag is in progress.
QUndoCommand* changeObstacle(Document& doc, int index, const ProjectObstacle& obstacle,
                             bool commit);

QUndoCommand* addDomain(Document& doc, int index, const PlacementDomain& domain);
QUndoCommand* removeDomain(Document& doc, int index);
/// Changes a domain's shape, extent or tree counts; merges while a drag is in progress.
QUndoCommand* changeDomain(Document& doc, int index, const PlacementDomain& domain, bool commit);

/// Changes the project seed, camera or light.
QUndoCommand* changeSettings(Document& doc, const Document::Settings& settings, bool commit,
                             const QString& label);

} // namespace sylva::doc::cmd
