#pragma once

#include <QTreeView>

namespace sylva::doc {
class Document;
}

namespace sylva::ui {

class OutlinerModel;

/// The outliner's tree: the document's species, trees, domains and obstacles (OutlinerModel),
/// its groups open, and its selection and the document's kept the same both ways (a click here
/// selects in the document; a selection made elsewhere shows here).
class OutlinerView : public QTreeView {
    Q_OBJECT

public:
    OutlinerView(doc::Document& document, OutlinerModel* model, QWidget* parent = nullptr);

private:
    void showDocumentSelection();

    doc::Document& mDocument;
    OutlinerModel* mModel;
    bool mSyncing = false; ///< while one selection is being copied to the other
};

} // namespace sylva::ui
