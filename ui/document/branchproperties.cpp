#include "ui/document/branchproperties.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>

#include "document/errormessage.h"
#include "engine/util/error.h"
#include "ui/generation/treebranches.h"

namespace sylva::ui {

BranchProperties::BranchProperties(doc::Document& document, doc::Document::BranchRef branch,
                                   std::function<const GenerationResult&()> result, QWidget* parent)
    : QGroupBox(parent), mDocument(document), mBranch(std::move(branch)),
      mResult(std::move(result)) {
    setObjectName(QStringLiteral("branchProperties"));
    setTitle(tr("Branch %1").arg(QString::fromStdString(mBranch.branch)));
    auto* form = new QFormLayout(this);
    mState = new QLabel(this);
    mState->setObjectName(QStringLiteral("branchState"));
    mState->setWordWrap(true);
    form->addRow(tr("Edit:"), mState);
    auto scaleBox = [this, form](const QString& name, const QString& label, const QString& tip) {
        auto* box = new QDoubleSpinBox(this);
        box->setObjectName(name);
        box->setRange(double(skel::kBranchScaleMin), double(skel::kBranchScaleMax));
        box->setSingleStep(0.05);
        box->setDecimals(2);
        box->setKeyboardTracking(false);
        box->setToolTip(tip);
        form->addRow(label, box);
        return box;
    };
    mLength = scaleBox(QStringLiteral("branchLength"), tr("Length scale:"),
                       tr("Scales the branch's own length about its base, 0.05 to 20; what it "
                          "carries follows"));
    mRadius = scaleBox(QStringLiteral("branchRadius"), tr("Radius scale:"),
                       tr("Scales the thickness of the branch and what it carries, 0.05 to 20"));
    mLock = new QCheckBox(tr("Keep through regrowth"), this);
    mLock->setObjectName(QStringLiteral("branchLock"));
    mLock->setToolTip(tr("Locked: the branch and what it carries keep their exact shape when "
                         "the species or the seed changes"));
    form->addRow(tr("Lock:"), mLock);
    mPrune = new QPushButton(tr("Prune"), this);
    mPrune->setObjectName(QStringLiteral("branchPrune"));
    mPrune->setToolTip(tr("Removes the branch and everything it carries (Delete)"));
    form->addRow(QString(), mPrune);

    auto edit = [this](const std::function<void(skel::BranchEdit&)>& change) {
        apply([this, change] {
            skel::BranchEdit e = branchEditOf(mDocument, mBranch.tree, mBranch.branch);
            change(e);
            if (!e.lock) { // unlocked: the kept geometry goes too
                e.locked.clear();
                e.lockedLeaves.clear();
                e.lockedBase = glm::vec3(0.0f);
            }
            applyBranchEdit(mDocument, shownTree(mResult(), mBranch.tree), mBranch.tree, e);
        });
    };
    connect(mLength, &QDoubleSpinBox::valueChanged, this,
            [edit](double v) { edit([v](skel::BranchEdit& e) { e.length = float(v); }); });
    connect(mRadius, &QDoubleSpinBox::valueChanged, this,
            [edit](double v) { edit([v](skel::BranchEdit& e) { e.radius = float(v); }); });
    connect(mLock, &QCheckBox::toggled, this,
            [edit](bool on) { edit([on](skel::BranchEdit& e) { e.lock = on; }); });
    connect(mPrune, &QPushButton::clicked, this, [this] {
        apply([this] {
            if (mDocument.selectedBranch() != mBranch) mDocument.setSelectedBranch(mBranch);
            pruneSelectedBranch(mDocument, shownTree(mResult(), mBranch.tree));
        });
    });
    refresh();
}

void BranchProperties::apply(const std::function<void()>& edit) {
    if (mUpdating) return;
    try {
        edit();
    } catch (...) {
        Q_EMIT failed(QString::fromStdString(doc::currentErrorMessage()));
        refresh();
    }
}

void BranchProperties::refresh() {
    if (mDocument.treeIndex(mBranch.tree) < 0) return;
    mUpdating = true;
    const skel::BranchEdit e = branchEditOf(mDocument, mBranch.tree, mBranch.branch);
    QStringList state;
    if (e.prune) state << tr("pruned");
    if (e.bend) state << tr("bent");
    if (e.length != 1.0f) state << tr("length ×%1").arg(double(e.length));
    if (e.radius != 1.0f) state << tr("radius ×%1").arg(double(e.radius));
    if (e.lock) state << tr("locked");
    mState->setText(state.isEmpty() ? tr("none (as grown)") : state.join(QStringLiteral(", ")));
    mLength->setValue(double(e.length));
    mRadius->setValue(double(e.radius));
    mLock->setChecked(e.lock);
    mLength->setEnabled(!e.lock);
    mRadius->setEnabled(!e.lock);
    mPrune->setEnabled(!e.lock && mBranch.branch.find('.') != std::string::npos);
    mUpdating = false;
}

} // namespace sylva::ui
