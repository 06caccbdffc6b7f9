#include "ui/document/presetsmenu.h"

#include <QActionGroup>
#include <QDir>
#include <QFileInfo>

#include "document/presetlibrary.h"

namespace sylva::ui {

PresetsMenu::PresetsMenu(std::function<QString()> previewed, QWidget* parent)
    : QMenu(tr("&Presets"), parent), mPreviewed(std::move(previewed)) {
    setObjectName(QStringLiteral("presetsMenu"));
    mGroup = new QActionGroup(this);
    connect(this, &QMenu::aboutToShow, this, &PresetsMenu::populate);
    populate();
}

void PresetsMenu::populate() {
    clear();
    for (QAction* action : mGroup->actions())
        mGroup->removeAction(action);
    const QString dir = doc::PresetLibrary::directory();
    const QList<doc::PresetInfo> presets = doc::PresetLibrary::list(dir);
    if (presets.isEmpty()) {
        QAction* none =
            addAction(dir.isEmpty() ? tr("No presets folder found (set SYLVA_PRESETS_DIR)")
                                    : tr("No presets in %1").arg(QDir::toNativeSeparators(dir)));
        none->setEnabled(false);
        return;
    }
    const QString previewed = mPreviewed();
    for (const doc::PresetInfo& preset : presets) {
        QAction* action = addAction(preset.name);
        action->setData(preset.path);
        action->setToolTip(preset.path);
        action->setCheckable(true);
        action->setChecked(!previewed.isEmpty() && QFileInfo(preset.path) == QFileInfo(previewed));
        mGroup->addAction(action);
        connect(action, &QAction::triggered, this,
                [this, path = preset.path] { Q_EMIT openRequested(path); });
    }
}

} // namespace sylva::ui
