#include "document/commands/scenecommands.h"

namespace sylva::doc::cmd {

namespace {

QUndoCommand* obstacleEdit(Document& doc, bool remove, int index, const ProjectObstacle& o) {
    return new ListEdit<ProjectObstacle>(
        doc, remove, index, o,
        [](Document& d, int i, const ProjectObstacle& v) { d.rawInsertObstacle(i, v); },
        [](Document& d, int i) { d.rawRemoveObstacle(i); },
        remove ? QCoreApplication::translate("Commands", "Remove obstacle")
               : QCoreApplication::translate("Commands", "Add obstacle"));
}

QUndoCommand* domainEdit(Document& doc, bool remove, int index, const PlacementDomain& dom) {
    return new ListEdit<PlacementDomain>(
        doc, remove, index, dom,
        [](Document& d, int i, const PlacementDomain& v) { d.rawInsertDomain(i, v); },
        [](Document& d, int i) { d.rawRemoveDomain(i); },
        remove ? QCoreApplication::translate("Commands", "Remove domain")
               : QCoreApplication::translate("Commands", "Add domain"));
}

} // namespace

QUndoCommand* addObstacle(Document& doc, int index, const ProjectObstacle& obstacle) {
    return obstacleEdit(doc, false, index, obstacle);
}

QUndoCommand* removeObstacle(Document& doc, int index) {
    return obstacleEdit(doc, true, index, doc.project().obstacles[static_cast<std::size_t>(index)]);
}

QUndoCommand* changeObstacle(Document& doc, int index, const ProjectObstacle& obstacle,
                             bool commit) {
    const ProjectObstacle& old = doc.project().obstacles[static_cast<std::size_t>(index)];
    QString label = QCoreApplication::translate("Commands", "Transform obstacle");
    if (old.file != obstacle.file)
        label = QCoreApplication::translate("Commands", "Change obstacle mesh");
    return new ChangeValue<int, ProjectObstacle>(
        doc, kMergeObstacle, index, old, obstacle, commit,
        [](Document& d, const int& i, const ProjectObstacle& v) { d.rawSetObstacle(i, v); }, label);
}

QUndoCommand* addDomain(Document& doc, int index, const PlacementDomain& domain) {
    return domainEdit(doc, false, index, domain);
}

QUndoCommand* removeDomain(Document& doc, int index) {
    return domainEdit(doc, true, index, doc.project().domains[static_cast<std::size_t>(index)]);
}

QUndoCommand* changeDomain(Document& doc, int index, const PlacementDomain& domain, bool commit) {
    const PlacementDomain& old = doc.project().domains[static_cast<std::size_t>(index)];
    return new ChangeValue<int, PlacementDomain>(
        doc, kMergeDomain, index, old, domain, commit,
        [](Document& d, const int& i, const PlacementDomain& v) { d.rawSetDomain(i, v); },
        old.counts != domain.counts ? QCoreApplication::translate("Commands", "Change tree counts")
                                    : QCoreApplication::translate("Commands", "Change domain"));
}

QUndoCommand* changeSettings(Document& doc, const Document::Settings& settings, bool commit,
                             const QString& label) {
    // One key: consecutive camera drags merge; a seed change commits at once.
    return new ChangeValue<int, Document::Settings>(
        doc, kMergeSettings, 0, doc.settings(), settings, commit,
        [](Document& d, const int&, const Document::Settings& v) { d.rawSetSettings(v); }, label);
}

} // namespace sylva::doc::cmd
