// The properties panel's species page (issue 30): an artist picks a species in the outliner and
// sets how many variants its forest trees share (K) by typing or with the arrow keys; each
// edit is one undo step and undo gives back the exact document.
#include <QAbstractItemView>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QTest>
#include <QUndoStack>

#include "document/document.h"
#include "ui/document/outlinermodel.h"
#include "ui/document/outlinerview.h"
#include "ui/document/propertiespanel.h"

using namespace sylva;
using namespace sylva::ui;

class TestPropertiesPanel : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void variantsSpinSetsKAsOneUndoStep() {
        doc::Document document;
        document.open(QDir(QStringLiteral(SYLVA_TEST_DATA_DIR))
                          .filePath(QStringLiteral("projects/small.sylva")));
        QWidget window;
        auto* layout = new QHBoxLayout(&window);
        OutlinerModel model(document);
        auto* outliner = new OutlinerView(document, &model, &window);
        auto* panel = new PropertiesPanel(document, &window);
        layout->addWidget(outliner);
        layout->addWidget(panel);
        window.resize(900, 600);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QByteArray before = document.serialized();
        QCOMPARE(document.project().species[1].variants, 8); // the default

        // Click the second species in the outliner.
        const QModelIndex shrub = model.indexOf({doc::ItemRef::Kind::Species, 1});
        outliner->scrollTo(shrub);
        QTest::mouseClick(outliner->viewport(), Qt::LeftButton, {},
                          outliner->visualRect(shrub).center());
        QCOMPARE(document.selection(),
                 QList<doc::ItemRef>{(doc::ItemRef{doc::ItemRef::Kind::Species, 1})});
        auto* spin = panel->findChild<QDoubleSpinBox*>(QStringLiteral("spin0"));
        QVERIFY(spin);
        QCOMPARE(spin->value(), 8.0);
        QCOMPARE(spin->decimals(), 0);
        QCOMPARE(spin->maximum(), 256.0);

        // Type 3 and press Enter: one step, only that species' K changed.
        const int steps = document.undoStack()->count();
        QTest::mouseDClick(spin->findChild<QLineEdit*>(), Qt::LeftButton);
        QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(spin, QStringLiteral("3"));
        QTest::keyClick(spin, Qt::Key_Return);
        QCOMPARE(document.project().species[1].variants, 3);
        QCOMPARE(document.project().species[0].variants, 8);
        QCOMPARE(document.undoStack()->count(), steps + 1);
        QVERIFY(document.serialized().contains("\"variants\": 3"));

        // The arrow key: another step.
        QTest::keyClick(spin, Qt::Key_Up);
        QCOMPARE(document.project().species[1].variants, 4);
        QCOMPARE(document.undoStack()->count(), steps + 2);

        // 0: every tree unique, said in words.
        QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(spin, QStringLiteral("0"));
        QTest::keyClick(spin, Qt::Key_Return);
        QCOMPARE(document.project().species[1].variants, 0);
        QCOMPARE(spin->text(), spin->specialValueText());

        // Undo three times: the document as it was, byte for byte; redo, and the panel follows.
        document.undoStack()->undo();
        QCOMPARE(spin->value(), 4.0);
        document.undoStack()->undo();
        document.undoStack()->undo();
        QCOMPARE(document.serialized(), before);
        QCOMPARE(spin->value(), 8.0);
        document.undoStack()->redo();
        QCOMPARE(document.project().species[1].variants, 3);
        QCOMPARE(spin->value(), 3.0);

        // The same value again is no step.
        const int now = document.undoStack()->index();
        document.setSpeciesVariants("shrub", 3);
        QCOMPARE(document.undoStack()->index(), now);
        QVERIFY_THROWS_EXCEPTION(std::exception, document.setSpeciesVariants("shrub", 257));
        QVERIFY_THROWS_EXCEPTION(std::exception, document.setSpeciesVariants("nope", 2));
    }

    // Issue #40: a tree's three position boxes, each with " m", cut their unit off in the dock;
    // the unit is in the row's label instead, and each box shows its whole value.
    void positionBoxesShowTheirValueAndTheRowItsUnit() {
        doc::Document document;
        document.open(QDir(QStringLiteral(SYLVA_TEST_DATA_DIR))
                          .filePath(QStringLiteral("projects/small.sylva")));
        QWidget window;
        auto* layout = new QHBoxLayout(&window);
        auto* panel = new PropertiesPanel(document, &window);
        layout->addWidget(panel);
        window.resize(300, 600);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        document.selectTrees({document.treeIds().front()});
        QTest::qWait(50);
        auto* x = panel->findChild<QDoubleSpinBox*>(QStringLiteral("spin0"));
        QVERIFY(x);
        QVERIFY(x->suffix().isEmpty());
        auto* form = panel->findChild<QFormLayout*>();
        QVERIFY(form);
        auto* label = qobject_cast<QLabel*>(form->labelForField(x->parentWidget()));
        QVERIFY(label);
        QCOMPARE(label->text(), QStringLiteral("Position (m):"));
        for (int i = 0; i < 3; ++i) {
            auto* box = panel->findChild<QDoubleSpinBox*>(QStringLiteral("spin%1").arg(i));
            box->setValue(-123.45);
            const int text = box->fontMetrics().horizontalAdvance(box->text());
            QVERIFY2(
                text < box->width(),
                qPrintable(
                    QStringLiteral("%1 px of text in a %2 px box").arg(text).arg(box->width())));
        }
    }
};

QTEST_MAIN(TestPropertiesPanel)
#include "test_propertiespanel.moc"
