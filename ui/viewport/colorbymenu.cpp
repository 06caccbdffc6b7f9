#include "ui/viewport/colorbymenu.h"

#include <utility>

#include <QActionGroup>

namespace sylva::ui {

ColorByMenu::ColorByMenu(ColorBy mode, QWidget* parent) : QMenu(tr("&Colour by"), parent) {
    setObjectName(QStringLiteral("colorMenu"));
    mGroup = new QActionGroup(this);
    const std::pair<ColorBy, QString> modes[] = {{ColorBy::Material, tr("&Material")},
                                                 {ColorBy::Light, tr("&Light (per internode)")},
                                                 {ColorBy::Vigour, tr("&Vigour")},
                                                 {ColorBy::Age, tr("&Age")},
                                                 {ColorBy::BranchOrder, tr("Branch &order")}};
    for (const auto& [m, label] : modes) {
        QAction* action = addAction(label);
        action->setCheckable(true);
        action->setChecked(m == mode);
        action->setData(static_cast<int>(m));
        mGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, m = m] { Q_EMIT chosen(m); });
    }
}

void ColorByMenu::setMode(ColorBy mode) {
    for (QAction* action : mGroup->actions())
        action->setChecked(action->data().toInt() == static_cast<int>(mode));
}

void ColorByMenu::enableFor(const skel::Skeleton* skeleton, bool shown) {
    for (QAction* action : mGroup->actions()) {
        const auto mode = static_cast<ColorBy>(action->data().toInt());
        action->setEnabled(mode == ColorBy::Material ||
                           (skeleton && hasAttribute(*skeleton, mode)) || !shown);
    }
}

} // namespace sylva::ui
