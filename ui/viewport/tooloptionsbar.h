#pragma once

#include <string>
#include <utility>
#include <vector>

#include <QList>
#include <QString>
#include <QToolBar>

#include "ui/viewport/toolcontroller.h"

class QActionGroup;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;

namespace sylva::doc {
class Document;
}

namespace sylva::ui {

/// The brush's species mix typed as "species weight, species weight" ("alder 70, ternary 30");
/// an empty (or blank) \p text is \p species alone (nothing when that is empty too).
/// \throw InvalidInput naming the part that is not "species weight"
std::vector<std::pair<std::string, double>> parseBrushMix(const QString& text,
                                                          const QString& species);

/// The Tools toolbar: one checkable action per tool (with its shortcut) and the tools' options,
/// the species the Place tool plants and the Brush's radius, density and mix. Every change goes
/// to the ToolController through its public calls; the species list follows the document.
class ToolOptionsBar : public QToolBar {
    Q_OBJECT

public:
    ToolOptionsBar(ToolController& tools, doc::Document& document, QWidget* parent = nullptr);

Q_SIGNALS:
    /// A brush setting the tools refused (a mix that does not parse); the message says why.
    void failed(const QString& message);

private:
    /// The radius, density and mix shown, to the brush; a mix that does not parse is reported
    /// (failed()) only when \p reportErrors.
    void applyBrushSettings(bool reportErrors = true);
    void syncSpecies();
    /// Enables the options \p tool uses (the species for Place and Brush, the radius for Brush
    /// and Erase, density and mix for Brush) and greys out the rest, so that the bar says
    /// which of its fields the current tool reads.
    void showOptionsOf(ToolController::Tool tool);

    ToolController& mTools;
    doc::Document& mDocument;
    QActionGroup* mToolGroup = nullptr;
    QComboBox* mSpecies = nullptr;
    QDoubleSpinBox* mRadius = nullptr;
    QDoubleSpinBox* mDensity = nullptr;
    QLineEdit* mMix = nullptr;
    /// Each option's label and field, greyed out together.
    QList<QWidget*> mSpeciesRow, mRadiusRow, mBrushRows;
};

} // namespace sylva::ui
