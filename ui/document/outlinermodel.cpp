#include "ui/document/outlinermodel.h"

#include <QColor>
#include <QFileInfo>

#include "document/errormessage.h"
#include "document/speciesgraphedit.h"

namespace sylva::ui {

namespace {

// internalId: kind in the top byte, group (or species row for nodes) in the next 24 bits.
enum Kind : quintptr { kGroup = 1, kItem = 2, kNode = 3, kEdit = 4 };
quintptr pack(Kind kind, int a) {
    return (quintptr(kind) << 56) | quintptr(a);
}
Kind kindOf(const QModelIndex& i) {
    return static_cast<Kind>(i.internalId() >> 56);
}
int argOf(const QModelIndex& i) {
    return static_cast<int>(i.internalId() & 0xFFFFFF);
}

QString vec(const glm::vec3& v) {
    return QStringLiteral("%1, %2, %3").arg(v.x, 0, 'g', 4).arg(v.y, 0, 'g', 4).arg(v.z, 0, 'g', 4);
}

} // namespace

OutlinerModel::OutlinerModel(doc::Document& document, QObject* parent)
    : QAbstractItemModel(parent), mDocument(document) {
    connect(&document, &doc::Document::changed, this, [this](const doc::DocumentChange& c) {
        beginResetModel();
        // Node lists come from species files on disk: read again only when species changed,
        // not at every step of a drag.
        // A parameter or graph edit of one species re-reads that one (species files are parsed
        // again for each read, and a slider drag edits many times a second).
        const int one = mDocument.speciesIndex(c.species.toStdString());
        if (c.what == doc::DocumentChange::Species && one >= 0 &&
            mNodes.size() == mDocument.project().species.size())
            readNodes(one);
        else if (c.what & (doc::DocumentChange::Species | doc::DocumentChange::Reset))
            readNodes();
        pruneHidden();
        endResetModel();
    });
    readNodes();
}

void OutlinerModel::readNodes(int only) {
    const auto& all = mDocument.project().species;
    if (only < 0) mNodes.assign(all.size(), QStringList());
    for (std::size_t k = 0; k < all.size(); ++k) {
        if (only >= 0 && int(k) != only) continue;
        const doc::ProjectSpecies& s = all[k];
        QStringList nodes;
        try {
            const sylva::Value g = mDocument.speciesGraph(s.name);
            for (const sylva::Value& n : doc::graphNodes(g))
                nodes << QStringLiteral("%1 (%2)").arg(
                    QString::fromStdString(n.string("id", "?")),
                    QString::fromStdString(n.string("type", "?")));
        } catch (const std::exception& e) {
            nodes << tr("cannot read: %1").arg(QString::fromUtf8(e.what()));
        }
        mNodes[k] = nodes;
    }
}

void OutlinerModel::pruneHidden() {
    QSet<doc::TreeId> alive;
    for (doc::TreeId id : mDocument.treeIds())
        if (mHidden.contains(id)) alive.insert(id);
    if (alive != mHidden) {
        mHidden = alive;
        Q_EMIT hiddenTreesChanged(mHidden);
    }
}

int OutlinerModel::groupSize(int group) const {
    const doc::Project& p = mDocument.project();
    switch (group) {
    case SpeciesGroup:
        return int(p.species.size());
    case TreesGroup:
        return int(p.instances.size());
    case DomainsGroup:
        return int(p.domains.size());
    case ObstaclesGroup:
        return int(p.obstacles.size());
    default:
        return 0;
    }
}

QModelIndex OutlinerModel::index(int row, int column, const QModelIndex& parent) const {
    if (row < 0 || column != 0) return {};
    if (!parent.isValid())
        return row < kGroups ? createIndex(row, 0, pack(kGroup, row)) : QModelIndex();
    if (kindOf(parent) == kGroup)
        return row < groupSize(parent.row()) ? createIndex(row, 0, pack(kItem, parent.row()))
                                             : QModelIndex();
    if (kindOf(parent) == kItem && argOf(parent) == SpeciesGroup &&
        parent.row() < int(mNodes.size()) && row < mNodes[std::size_t(parent.row())].size())
        return createIndex(row, 0, pack(kNode, parent.row()));
    if (kindOf(parent) == kItem && argOf(parent) == TreesGroup &&
        parent.row() < int(mDocument.project().instances.size()) &&
        row < int(mDocument.project().instances[std::size_t(parent.row())].branchEdits.size()))
        return createIndex(row, 0, pack(kEdit, parent.row()));
    return {};
}

void OutlinerModel::setOrphanedEdits(const QHash<doc::TreeId, QSet<QString>>& orphans) {
    if (orphans == mOrphans) return;
    beginResetModel();
    mOrphans = orphans;
    endResetModel();
}

QModelIndex OutlinerModel::parent(const QModelIndex& child) const {
    if (!child.isValid()) return {};
    switch (kindOf(child)) {
    case kItem:
        return createIndex(argOf(child), 0, pack(kGroup, argOf(child)));
    case kNode:
        return createIndex(argOf(child), 0, pack(kItem, SpeciesGroup));
    case kEdit:
        return createIndex(argOf(child), 0, pack(kItem, TreesGroup));
    default:
        return {};
    }
}

int OutlinerModel::rowCount(const QModelIndex& parent) const {
    if (!parent.isValid()) return kGroups;
    if (kindOf(parent) == kGroup) return groupSize(parent.row());
    if (kindOf(parent) == kItem && argOf(parent) == SpeciesGroup &&
        parent.row() < int(mNodes.size()))
        return int(mNodes[std::size_t(parent.row())].size());
    if (kindOf(parent) == kItem && argOf(parent) == TreesGroup &&
        parent.row() < int(mDocument.project().instances.size()))
        return int(mDocument.project().instances[std::size_t(parent.row())].branchEdits.size());
    return 0;
}

int OutlinerModel::columnCount(const QModelIndex&) const {
    return 1;
}

QVariant OutlinerModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const doc::Project& p = mDocument.project();
    const int row = index.row();
    if (kindOf(index) == kGroup) {
        if (role == Qt::DisplayRole) {
            switch (row) {
            case SpeciesGroup:
                return tr("Species (%1)").arg(p.species.size());
            case TreesGroup:
                return tr("Trees (%1)").arg(p.instances.size());
            case DomainsGroup:
                return tr("Domains (%1)").arg(p.domains.size());
            case ObstaclesGroup:
                return tr("Obstacles (%1)").arg(p.obstacles.size());
            case CameraItem:
                return tr("Camera");
            case LightItem:
                return tr("Light");
            }
        }
        if (role == Qt::ToolTipRole && row == CameraItem)
            return tr("Position %1, looking at %2: the LOD reference and the start view")
                .arg(vec(p.cameraPosition), vec(p.cameraTarget));
        if (role == Qt::ToolTipRole && row == LightItem)
            return tr("Light direction %1").arg(vec(p.lightDirection));
        return {};
    }
    if (kindOf(index) == kNode) {
        if (role == Qt::DisplayRole) return mNodes[std::size_t(argOf(index))][row];
        return {};
    }
    if (kindOf(index) == kEdit) {
        const std::size_t tree = std::size_t(argOf(index));
        const skel::BranchEdit& e = p.instances[tree].branchEdits[std::size_t(row)];
        const QString id = QString::fromStdString(e.branch);
        const bool orphaned = mOrphans.value(mDocument.treeIds()[tree]).contains(id);
        if (role == Qt::DisplayRole) {
            QStringList what;
            if (e.prune) what << tr("pruned");
            if (e.bend) what << tr("bent");
            if (e.length != 1.0f) what << tr("length ×%1").arg(double(e.length));
            if (e.radius != 1.0f) what << tr("radius ×%1").arg(double(e.radius));
            if (e.lock) what << tr("locked");
            const QString text = tr("Branch %1: %2").arg(id, what.join(QStringLiteral(", ")));
            return orphaned ? tr("%1 (orphaned)").arg(text) : text;
        }
        if (role == Qt::ToolTipRole)
            return orphaned ? tr("The grown tree has no branch %1 now: the edit is kept and "
                                 "applies again when the branch grows back")
                                  .arg(id)
                            : tr("A hand edit of branch %1 (Branch tool, doc.edit_branch)").arg(id);
        if (role == Qt::ForegroundRole && orphaned) return QColor(200, 90, 40);
        return {};
    }
    switch (argOf(index)) {
    case SpeciesGroup: {
        const doc::ProjectSpecies& s = p.species[std::size_t(row)];
        if (role == Qt::DisplayRole || role == Qt::EditRole) return QString::fromStdString(s.name);
        if (role == Qt::ToolTipRole)
            return s.file.empty() ? tr("Stored in the project (edited here)")
                                  : tr("From %1").arg(QString::fromStdString(s.file));
        break;
    }
    case TreesGroup: {
        const doc::ProjectInstance& t = p.instances[std::size_t(row)];
        const doc::TreeId id = mDocument.treeIds()[std::size_t(row)];
        if (role == Qt::DisplayRole)
            return tr("%1 #%2").arg(QString::fromStdString(t.species)).arg(id);
        if (role == Qt::ToolTipRole)
            return tr("At %1 m, rotated %2°, scale %3, seed %4")
                .arg(vec(t.position))
                .arg(t.rotation)
                .arg(t.scale)
                .arg(qulonglong(t.seed));
        if (role == Qt::CheckStateRole) return mHidden.contains(id) ? Qt::Unchecked : Qt::Checked;
        break;
    }
    case DomainsGroup: {
        const doc::PlacementDomain& d = p.domains[std::size_t(row)];
        int trees = 0;
        for (const auto& [name, n] : d.counts)
            trees += n;
        if (role == Qt::DisplayRole)
            return tr("%1 %2: %3 trees")
                .arg(QString::fromStdString(d.shape))
                .arg(row + 1)
                .arg(trees);
        break;
    }
    case ObstaclesGroup: {
        const doc::ProjectObstacle& o = p.obstacles[std::size_t(row)];
        if (role == Qt::DisplayRole) return QFileInfo(QString::fromStdString(o.file)).fileName();
        if (role == Qt::ToolTipRole) return QString::fromStdString(o.file);
        break;
    }
    }
    return {};
}

bool OutlinerModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    const std::optional<doc::ItemRef> item = itemAt(index);
    if (!item) return false;
    if (item->kind == doc::ItemRef::Kind::Tree && role == Qt::CheckStateRole) {
        if (value.toInt() == Qt::Checked)
            mHidden.remove(item->id);
        else
            mHidden.insert(item->id);
        Q_EMIT dataChanged(index, index, {Qt::CheckStateRole});
        Q_EMIT hiddenTreesChanged(mHidden);
        return true;
    }
    if (item->kind == doc::ItemRef::Kind::Species && role == Qt::EditRole) {
        try {
            mDocument.renameSpecies(mDocument.project().species[item->id].name,
                                    value.toString().trimmed().toStdString());
            return true;
        } catch (...) {
            Q_EMIT editFailed(QString::fromStdString(doc::currentErrorMessage()));
        }
    }
    return false;
}

Qt::ItemFlags OutlinerModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (kindOf(index) == kItem && argOf(index) == TreesGroup) f |= Qt::ItemIsUserCheckable;
    if (kindOf(index) == kItem && argOf(index) == SpeciesGroup) f |= Qt::ItemIsEditable;
    return f;
}

std::optional<doc::ItemRef> OutlinerModel::itemAt(const QModelIndex& index) const {
    using K = doc::ItemRef::Kind;
    if (!index.isValid()) return std::nullopt;
    if (kindOf(index) == kGroup) {
        if (index.row() == CameraItem) return doc::ItemRef{K::Camera, 0};
        if (index.row() == LightItem) return doc::ItemRef{K::Light, 0};
        return std::nullopt;
    }
    if (kindOf(index) == kNode) return doc::ItemRef{K::Species, std::uint32_t(argOf(index))};
    if (kindOf(index) == kEdit)
        return doc::ItemRef{K::Tree, mDocument.treeIds()[std::size_t(argOf(index))]};
    const auto row = std::uint32_t(index.row());
    switch (argOf(index)) {
    case SpeciesGroup:
        return doc::ItemRef{K::Species, row};
    case TreesGroup:
        return doc::ItemRef{K::Tree, mDocument.treeIds()[row]};
    case DomainsGroup:
        return doc::ItemRef{K::Domain, row};
    case ObstaclesGroup:
        return doc::ItemRef{K::Obstacle, row};
    }
    return std::nullopt;
}

QModelIndex OutlinerModel::groupIndex(Group group) const {
    return index(int(group), 0);
}

QModelIndex OutlinerModel::indexOf(const doc::ItemRef& item) const {
    using K = doc::ItemRef::Kind;
    switch (item.kind) {
    case K::Tree: {
        const int row = mDocument.treeIndex(item.id);
        return row < 0 ? QModelIndex() : index(row, 0, groupIndex(TreesGroup));
    }
    case K::Species:
        return index(int(item.id), 0, groupIndex(SpeciesGroup));
    case K::Domain:
        return index(int(item.id), 0, groupIndex(DomainsGroup));
    case K::Obstacle:
        return index(int(item.id), 0, groupIndex(ObstaclesGroup));
    case K::Camera:
        return groupIndex(CameraItem);
    case K::Light:
        return groupIndex(LightItem);
    case K::Project:
        return {};
    }
    return {};
}

} // namespace sylva::ui
