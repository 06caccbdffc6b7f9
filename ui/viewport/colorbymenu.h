#pragma once

#include <QMenu>

#include "ui/viewport/attributecolors.h"

class QActionGroup;

namespace sylva::skel {
struct Skeleton;
}

namespace sylva::ui {

/// View ▸ Colour by: one checkable entry per ColorBy mode; the modes a shown tree cannot
/// colour by are greyed out. What colouring does to the view is the window's.
class ColorByMenu : public QMenu {
    Q_OBJECT

public:
    explicit ColorByMenu(ColorBy mode, QWidget* parent = nullptr);

    /// Checks \p mode's entry (without emitting chosen()).
    void setMode(ColorBy mode);
    /// Enables the modes \p skeleton has (Material always); every mode while nothing is shown
    /// (\p shown false). A forest has no one skeleton: null.
    void enableFor(const skel::Skeleton* skeleton, bool shown);

Q_SIGNALS:
    /// An entry was chosen.
    void chosen(sylva::ui::ColorBy mode);

private:
    QActionGroup* mGroup = nullptr;
};

} // namespace sylva::ui
