// The Tools toolbar: the brush-mix parser (pure), and the bar driving a ToolController through
// its public calls: tool actions both ways, the species list following the document, the
// brush's radius, density and mix, a mix that does not parse.
#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>

#include "document/document.h"
#include "engine/util/error.h"
#include "ui/generation/treegenerator.h"
#include "ui/viewport/tooloptionsbar.h"
#include "ui/viewport/viewport.h"

using namespace sylva;
using namespace sylva::ui;

using Mix = std::vector<std::pair<std::string, double>>;

class TestToolOptionsBar : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void parsesTheMix() {
        QCOMPARE(parseBrushMix(QStringLiteral("alder 70, ternary 30"), QStringLiteral("oak")),
                 Mix({{"alder", 70.0}, {"ternary", 30.0}}));
        QCOMPARE(parseBrushMix(QStringLiteral("  alder   0.5 ,, birch 2 "), {}),
                 Mix({{"alder", 0.5}, {"birch", 2.0}}));
        // Empty: the chosen species alone; nothing when none is chosen either.
        QCOMPARE(parseBrushMix(QStringLiteral("   "), QStringLiteral("oak")), Mix({{"oak", 1.0}}));
        QCOMPARE(parseBrushMix({}, {}), Mix());
    }

    void refusesAMixThatIsNotSpeciesAndWeight() {
        for (const char* bad : {"alder", "alder seventy", "alder 70 30", "alder 70, birch"}) {
            try {
                parseBrushMix(QLatin1String(bad), QStringLiteral("oak"));
                QFAIL(bad);
            } catch (const InvalidInput& e) {
                QVERIFY2(QString::fromUtf8(e.what()).contains(QStringLiteral("species weight")),
                         e.what());
            }
        }
    }

    void drivesTheTools() {
        doc::Document document;
        Viewport view;
        GenerationResult none;
        ToolController tools(document, view, [&none]() -> const GenerationResult& { return none; });
        ToolOptionsBar bar(tools, document);
        QCOMPARE(bar.objectName(), QStringLiteral("toolsToolBar"));
        QSignalSpy failed(&bar, &ToolOptionsBar::failed);

        // The tool actions and the controller follow each other.
        auto* brushAction = bar.findChild<QAction*>(QStringLiteral("tool_brush"));
        auto* eraseAction = bar.findChild<QAction*>(QStringLiteral("tool_erase"));
        QVERIFY(brushAction && eraseAction);
        brushAction->trigger();
        QCOMPARE(tools.tool(), ToolController::Tool::Brush);
        tools.setTool(ToolController::Tool::Erase);
        QVERIFY(eraseAction->isChecked());
        QVERIFY(!brushAction->isChecked());
        // The bar greys out the options the current tool does not read.
        QVERIFY(bar.findChild<QDoubleSpinBox*>(QStringLiteral("brushRadius"))->isEnabled());
        QVERIFY(!bar.findChild<QLineEdit*>(QStringLiteral("brushMix"))->isEnabled());
        QVERIFY(!bar.findChild<QComboBox*>(QStringLiteral("toolSpecies"))->isEnabled());
        tools.setTool(ToolController::Tool::Branch);
        QVERIFY(!bar.findChild<QDoubleSpinBox*>(QStringLiteral("brushRadius"))->isEnabled());
        tools.setTool(ToolController::Tool::Brush);
        QVERIFY(bar.findChild<QLineEdit*>(QStringLiteral("brushMix"))->isEnabled());
        QVERIFY(bar.findChild<QComboBox*>(QStringLiteral("toolSpecies"))->isEnabled());
        tools.setTool(ToolController::Tool::Erase);

        // The species list is the document's.
        document.open(QDir(QStringLiteral(SYLVA_TEST_DATA_DIR))
                          .filePath(QStringLiteral("projects/small.sylva")));
        auto* species = bar.findChild<QComboBox*>(QStringLiteral("toolSpecies"));
        QCOMPARE(species->count(), 2);
        QCOMPARE(species->itemText(1), QStringLiteral("shrub"));
        species->setCurrentText(QStringLiteral("shrub"));
        QCOMPARE(tools.placeSpecies(), std::string("shrub"));
        QCOMPARE(tools.brush().mix, Mix({{"shrub", 1.0}}));

        // Radius, density and mix.
        bar.findChild<QDoubleSpinBox*>(QStringLiteral("brushRadius"))->setValue(9.5);
        bar.findChild<QDoubleSpinBox*>(QStringLiteral("brushDensity"))->setValue(3.0);
        auto* mix = bar.findChild<QLineEdit*>(QStringLiteral("brushMix"));
        mix->setText(QStringLiteral("bush 70, shrub 30"));
        Q_EMIT mix->editingFinished();
        QCOMPARE(tools.brush().radius, 9.5f);
        QCOMPARE(tools.brush().density, 3.0f);
        QCOMPARE(tools.brush().mix, Mix({{"bush", 70.0}, {"shrub", 30.0}}));
        QCOMPARE(failed.size(), 0);

        // A mix that does not parse: a message, and the tools keep the last good brush.
        mix->setText(QStringLiteral("bush seventy"));
        Q_EMIT mix->editingFinished();
        QCOMPARE(failed.size(), 1);
        QVERIFY(failed.front().front().toString().contains(QStringLiteral("bush seventy")));
        QCOMPARE(tools.brush().mix, Mix({{"bush", 70.0}, {"shrub", 30.0}}));
    }

    // Issue #40: with the bar's species shown and Mix left empty, the first stroke painted every
    // species (the bar pushed its settings only when a field changed).
    void theBrushPaintsWhatTheBarShowsUntouched() {
        doc::Document document;
        document.open(QDir(QStringLiteral(SYLVA_TEST_DATA_DIR))
                          .filePath(QStringLiteral("projects/small.sylva")));
        Viewport view;
        GenerationResult none;
        ToolController tools(document, view, [&none]() -> const GenerationResult& { return none; });
        ToolOptionsBar bar(tools, document);
        auto* species = bar.findChild<QComboBox*>(QStringLiteral("toolSpecies"));
        QVERIFY(!species->currentText().isEmpty());
        QCOMPARE(tools.brush().mix, Mix({{species->currentText().toStdString(), 1.0}}));
        // A document opened after the bar was made: its first species, at once.
        doc::Document other;
        ToolController tools2(other, view, [&none]() -> const GenerationResult& { return none; });
        ToolOptionsBar bar2(tools2, other);
        other.open(QDir(QStringLiteral(SYLVA_TEST_DATA_DIR))
                       .filePath(QStringLiteral("projects/small.sylva")));
        auto* species2 = bar2.findChild<QComboBox*>(QStringLiteral("toolSpecies"));
        QCOMPARE(tools2.brush().mix, Mix({{species2->currentText().toStdString(), 1.0}}));
        // A mix typed and painted with before the field lost focus.
        bar2.findChild<QLineEdit*>(QStringLiteral("brushMix"))->setText(QStringLiteral("shrub 2"));
        QCOMPARE(tools2.brush().mix, Mix({{"shrub", 2.0}}));
    }
};

QTEST_MAIN(TestToolOptionsBar)
#include "test_tooloptionsbar.moc"
