#include "ui/preferencesdialog.h"

#include <algorithm>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>

#include "ui/viewport/viewport.h"

namespace sylva::ui {

PreferencesDialog::PreferencesDialog(int autosaveMs, const QString& recoveryFolder, int samples,
                                     QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("preferencesDialog"));
    setWindowTitle(tr("Preferences"));
    auto* form = new QFormLayout(this);
    mMinutes = new QSpinBox(this);
    mMinutes->setObjectName(QStringLiteral("autosaveMinutes"));
    mMinutes->setRange(1, 60);
    mMinutes->setSuffix(tr(" min"));
    mMinutes->setValue(std::max(1, autosaveMs / 60000));
    mMinutes->setToolTip(tr("While there are unsaved edits, a recovery copy is written this often "
                            "and a few seconds after the last edit. It never replaces your file."));
    form->addRow(tr("Autosave every:"), mMinutes);
    auto* folder = new QLabel(QDir::toNativeSeparators(recoveryFolder), this);
    folder->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(tr("Recovery folder:"), folder);
    mSamples = new QComboBox(this);
    mSamples->setObjectName(QStringLiteral("viewportSamples"));
    mSamples->addItem(tr("Automatic (off on a software renderer)"), Viewport::kAutoSamples);
    mSamples->addItem(tr("Off"), 0);
    mSamples->addItem(tr("2× multisampling"), 2);
    mSamples->addItem(tr("4× multisampling"), 4);
    mSamples->addItem(tr("8× multisampling"), 8);
    mSamples->setCurrentIndex(std::max(0, mSamples->findData(samples)));
    mSamples->setToolTip(tr("Smooths the edges in the 3D view. Without a graphics card (a "
                            "software renderer) it makes every frame two to three times slower. "
                            "Takes effect when Sylva starts next."));
    form->addRow(tr("Antialiasing:"), mSamples);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

int PreferencesDialog::autosaveSeconds() const {
    return mMinutes->value() * 60;
}

int PreferencesDialog::samples() const {
    return mSamples->currentData().toInt();
}

} // namespace sylva::ui
