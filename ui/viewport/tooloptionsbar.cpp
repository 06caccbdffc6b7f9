#include "ui/viewport/tooloptionsbar.h"

#include <QActionGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QKeySequence>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QStringList>

#include "document/document.h"
#include "document/errormessage.h"
#include "engine/util/error.h"

namespace sylva::ui {

std::vector<std::pair<std::string, double>> parseBrushMix(const QString& text,
                                                          const QString& species) {
    std::vector<std::pair<std::string, double>> mix;
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty()) {
        if (!species.isEmpty()) mix.emplace_back(species.toStdString(), 1.0);
        return mix;
    }
    for (const QString& part : trimmed.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QStringList words = part.simplified().split(QLatin1Char(' '));
        bool ok = words.size() == 2;
        const double weight = ok ? words[1].toDouble(&ok) : 0.0;
        if (!ok)
            throw InvalidInput("the mix is \"species weight, species weight\", got \"" +
                               part.trimmed().toStdString() + "\"");
        mix.emplace_back(words[0].toStdString(), weight);
    }
    return mix;
}

ToolOptionsBar::ToolOptionsBar(ToolController& tools, doc::Document& document, QWidget* parent)
    : QToolBar(parent), mTools(tools), mDocument(document) {
    setWindowTitle(tr("Tools"));
    setObjectName(QStringLiteral("toolsToolBar"));
    mToolGroup = new QActionGroup(this);
    const struct {
        ToolController::Tool tool;
        QString label, key, tip;
    } toolList[] = {
        {ToolController::Tool::Select, tr("Select"), QStringLiteral("V"),
         tr("Click a tree or obstacle to select it (Shift adds, Ctrl toggles, Ctrl+drag draws a "
            "box); [ and ] step through the trees")},
        {ToolController::Tool::Move, tr("Move"), QStringLiteral("M"),
         tr("Drag selected trees along the ground (Ctrl+drag rotates, Shift+drag scales; arrow "
            "keys nudge). They re-adapt to the obstacles when you let go")},
        {ToolController::Tool::Place, tr("Place"), QStringLiteral("P"),
         tr("Click the ground to plant a tree of the chosen species")},
        {ToolController::Tool::Brush, tr("Brush"), QStringLiteral("B"),
         tr("Paint trees of the species mix with the radius and density below; one stroke is "
            "one undo step")},
        {ToolController::Tool::Erase, tr("Erase"), QStringLiteral("E"),
         tr("Remove the hand-placed trees the brush passes over")},
        {ToolController::Tool::Branch, tr("Branch"), QStringLiteral("K"),
         tr("Click a branch of a hand-placed tree to select it (its settings in Properties), "
            "drag it to bend it about its base, Delete prunes it; each is one undo step")},
    };
    for (const auto& t : toolList) {
        QAction* a = addAction(t.label);
        a->setObjectName(QStringLiteral("tool_") + ToolController::name(t.tool));
        a->setCheckable(true);
        a->setChecked(t.tool == mTools.tool());
        a->setShortcut(QKeySequence(t.key));
        a->setToolTip(QStringLiteral("%1 (%2): %3").arg(t.label, t.key, t.tip));
        mToolGroup->addAction(a);
        connect(a, &QAction::triggered, this, [this, tool = t.tool] { mTools.setTool(tool); });
    }
    connect(&mTools, &ToolController::toolChanged, this, [this](ToolController::Tool tool) {
        for (QAction* a : mToolGroup->actions())
            a->setChecked(a->objectName() == QStringLiteral("tool_") + ToolController::name(tool));
        showOptionsOf(tool);
    });
    addSeparator();
    auto* speciesLabel = new QLabel(tr(" Species: "), this);
    addWidget(speciesLabel);
    mSpecies = new QComboBox(this);
    mSpecies->setObjectName(QStringLiteral("toolSpecies"));
    mSpecies->setToolTip(tr("The species the Place tool plants, and the Brush when no mix "
                            "is given"));
    mSpecies->setMinimumContentsLength(10);
    addWidget(mSpecies);
    connect(mSpecies, &QComboBox::currentTextChanged, this, [this](const QString& name) {
        mTools.setPlaceSpecies(name.toStdString());
        applyBrushSettings();
    });
    connect(&mDocument, &doc::Document::changed, this, [this](const doc::DocumentChange& c) {
        if (c.what & (doc::DocumentChange::Species | doc::DocumentChange::Reset)) syncSpecies();
    });
    auto* radiusLabel = new QLabel(tr(" Radius: "), this);
    addWidget(radiusLabel);
    mRadius = new QDoubleSpinBox(this);
    mRadius->setObjectName(QStringLiteral("brushRadius"));
    mRadius->setRange(0.5, 100);
    mRadius->setValue(mTools.brush().radius);
    mRadius->setSuffix(tr(" m"));
    mRadius->setToolTip(tr("Brush and eraser radius, metres"));
    addWidget(mRadius);
    auto* densityLabel = new QLabel(tr(" Density: "), this);
    addWidget(densityLabel);
    mDensity = new QDoubleSpinBox(this);
    mDensity->setObjectName(QStringLiteral("brushDensity"));
    mDensity->setRange(0.01, 50);
    mDensity->setValue(mTools.brush().density);
    mDensity->setSuffix(tr(" /100 m²"));
    mDensity->setToolTip(tr("Trees tried per 100 m² under the brush; spacing rules keep "
                            "trunks out of each other's crowns and out of obstacles"));
    addWidget(mDensity);
    auto* mixLabel = new QLabel(tr(" Mix: "), this);
    addWidget(mixLabel);
    mMix = new QLineEdit(this);
    mMix->setObjectName(QStringLiteral("brushMix"));
    mMix->setPlaceholderText(tr("e.g. alder 70, ternary 30"));
    mMix->setToolTip(tr("Species and weights the brush paints; empty: the chosen species"));
    mMix->setMinimumWidth(160);
    addWidget(mMix);
    connect(mRadius, &QDoubleSpinBox::valueChanged, this, [this] { applyBrushSettings(); });
    connect(mDensity, &QDoubleSpinBox::valueChanged, this, [this] { applyBrushSettings(); });
    connect(mMix, &QLineEdit::editingFinished, this, [this] { applyBrushSettings(); });
    // A mix typed and then painted with at once (the view takes no focus from the field, so
    // editingFinished may not come): taken as soon as it reads; errors wait for editingFinished.
    connect(mMix, &QLineEdit::textChanged, this, [this] { applyBrushSettings(false); });
    // The brush paints what the bar shows from the first stroke, untouched fields included.
    syncSpecies();
    mSpeciesRow = {speciesLabel, mSpecies};
    mRadiusRow = {radiusLabel, mRadius};
    mBrushRows = {densityLabel, mDensity, mixLabel, mMix};
    showOptionsOf(mTools.tool());
}

void ToolOptionsBar::showOptionsOf(ToolController::Tool tool) {
    using T = ToolController::Tool;
    const auto enable = [](const QList<QWidget*>& row, bool on) {
        for (QWidget* w : row)
            w->setEnabled(on);
    };
    enable(mSpeciesRow, tool == T::Place || tool == T::Brush);
    enable(mRadiusRow, tool == T::Brush || tool == T::Erase);
    enable(mBrushRows, tool == T::Brush);
}

void ToolOptionsBar::syncSpecies() {
    const QString current = mSpecies->currentText();
    QSignalBlocker block(mSpecies);
    mSpecies->clear();
    for (const doc::ProjectSpecies& sp : mDocument.project().species)
        mSpecies->addItem(QString::fromStdString(sp.name));
    if (!current.isEmpty()) mSpecies->setCurrentText(current);
    mTools.setPlaceSpecies(mSpecies->currentText().toStdString());
    applyBrushSettings(false);
}

void ToolOptionsBar::applyBrushSettings(bool reportErrors) {
    ToolController::Brush brush;
    brush.radius = float(mRadius->value());
    brush.density = float(mDensity->value());
    try {
        brush.mix = parseBrushMix(mMix->text(), mSpecies->currentText());
        mTools.setBrush(brush);
    } catch (...) {
        if (reportErrors) Q_EMIT failed(QString::fromStdString(doc::currentErrorMessage()));
    }
}

} // namespace sylva::ui
