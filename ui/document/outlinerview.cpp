#include "ui/document/outlinerview.h"

#include "document/document.h"
#include "ui/document/outlinermodel.h"

namespace sylva::ui {

OutlinerView::OutlinerView(doc::Document& document, OutlinerModel* model, QWidget* parent)
    : QTreeView(parent), mDocument(document), mModel(model) {
    setObjectName(QStringLiteral("outlinerView"));
    setModel(mModel);
    setHeaderHidden(true);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::DoubleClicked);
    setContextMenuPolicy(Qt::ActionsContextMenu);
    connect(mModel, &QAbstractItemModel::modelReset, this, [this] {
        for (int g : {OutlinerModel::SpeciesGroup, OutlinerModel::TreesGroup,
                      OutlinerModel::DomainsGroup, OutlinerModel::ObstaclesGroup})
            expand(mModel->groupIndex(OutlinerModel::Group(g)));
        showDocumentSelection();
    });
    connect(selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
        if (mSyncing) return;
        QList<doc::ItemRef> items;
        for (const QModelIndex& i : selectionModel()->selectedIndexes())
            if (auto item = mModel->itemAt(i); item && !items.contains(*item)) items << *item;
        mSyncing = true;
        mDocument.setSelection(items);
        mSyncing = false;
    });
    connect(&mDocument, &doc::Document::selectionChanged, this,
            &OutlinerView::showDocumentSelection);
}

void OutlinerView::showDocumentSelection() {
    if (mSyncing) return;
    mSyncing = true;
    QItemSelection selection;
    for (const doc::ItemRef& item : mDocument.selection()) {
        const QModelIndex i = mModel->indexOf(item);
        if (i.isValid()) selection.select(i, i);
    }
    selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect);
    mSyncing = false;
}

} // namespace sylva::ui
