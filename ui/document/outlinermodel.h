#pragma once

#include <QAbstractItemModel>
#include <QHash>
#include <QSet>
#include <QStringList>

#include "document/document.h"

namespace sylva::ui {

/// The document as a tree for the Outliner dock (QtNodes' and Tiled's model/view split: the
/// model only reads the document and turns edits into document calls). Top level: Species (each
/// with its graph's nodes), Trees (each with its hand edits of single branches, orphaned ones
/// marked), Domains, Obstacles, Camera, Light. Trees are checkable (shown in the viewport or
/// hidden); species are renamed in place (an undoable edit).
class OutlinerModel : public QAbstractItemModel {
    Q_OBJECT

public:
    enum Group { SpeciesGroup, TreesGroup, DomainsGroup, ObstaclesGroup, CameraItem, LightItem };
    static constexpr int kGroups = 6;

    explicit OutlinerModel(doc::Document& document, QObject* parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    /// The document item an index stands for, or none (a group heading, a node).
    std::optional<doc::ItemRef> itemAt(const QModelIndex& index) const;
    QModelIndex indexOf(const doc::ItemRef& item) const;
    /// The index of the group heading (or the Camera and Light items).
    QModelIndex groupIndex(Group group) const;

    /// Trees hidden in the viewport (their check box cleared). Not part of the document.
    const QSet<doc::TreeId>& hiddenTrees() const { return mHidden; }
    /// The branch edits each tree's last generation found no branch for (marked "orphaned").
    void setOrphanedEdits(const QHash<doc::TreeId, QSet<QString>>& orphans);

Q_SIGNALS:
    void hiddenTreesChanged(const QSet<sylva::doc::TreeId>& hidden);
    /// A rename or another edit through the model failed; the message says why.
    void editFailed(const QString& message);

private:
    /// Reads the node lists of every species, or of species \p only.
    void readNodes(int only = -1);
    void pruneHidden();
    int groupSize(int group) const;

    doc::Document& mDocument;
    std::vector<QStringList> mNodes; ///< per species: "id (type)" of its graph's nodes
    QSet<doc::TreeId> mHidden;
    QHash<doc::TreeId, QSet<QString>> mOrphans;
};

} // namespace sylva::ui
