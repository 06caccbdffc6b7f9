#include "document/commands/speciescommands.h"

namespace sylva::doc::cmd {

namespace {
/// Edits merge per species and node: typing in one grammar is one step, another node is not.
struct SpeciesKey {
    int index = 0;
    QString node;
    bool operator==(const SpeciesKey&) const = default;
};
} // namespace

QUndoCommand* changeSpecies(Document& doc, int index, const ProjectSpecies& oldSpecies,
                            const ProjectSpecies& newSpecies, const QString& node, bool commit,
                            const QString& label) {
    return new ChangeValue<SpeciesKey, ProjectSpecies>(
        doc, kMergeSpecies, {index, node}, oldSpecies, newSpecies, commit,
        [](Document& d, const SpeciesKey& key, const ProjectSpecies& v) {
            d.rawSetSpecies(key.index, v, key.node);
        },
        label);
}

} // namespace sylva::doc::cmd
