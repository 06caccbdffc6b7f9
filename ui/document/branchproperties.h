#pragma once

#include <functional>

#include <QGroupBox>

#include "document/document.h"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace sylva::ui {

struct GenerationResult;

/// The selected branch in Properties (the Branch tool's selection): its id, length and
/// radius scale, lock and a Prune button. Each change is one undo step through the document;
/// locking keeps the branch's geometry as the tree shows it (applyBranchEdit). A value the
/// document refuses is reported (failed()) and the editors show the document's again.
class BranchProperties : public QGroupBox {
    Q_OBJECT

public:
    BranchProperties(doc::Document& document, doc::Document::BranchRef branch,
                     std::function<const GenerationResult&()> result, QWidget* parent = nullptr);

    /// Puts the document's values into the editors.
    void refresh();

Q_SIGNALS:
    void failed(const QString& message);

private:
    void apply(const std::function<void()>& edit);

    doc::Document& mDocument;
    doc::Document::BranchRef mBranch;
    std::function<const GenerationResult&()> mResult;
    QLabel* mState = nullptr;
    QDoubleSpinBox* mLength = nullptr;
    QDoubleSpinBox* mRadius = nullptr;
    QCheckBox* mLock = nullptr;
    QPushButton* mPrune = nullptr;
    bool mUpdating = false;
};

} // namespace sylva::ui
