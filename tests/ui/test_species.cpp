// Tuning a species as a user does, in the real window: the node graph edited with the mouse and
// keys (add from the Tab menu, connect by dragging from a port, a refused connection that says
// why, disconnect, delete, copy and paste) and every edit undone to the exact file; a grammar
// error typed in the grammar editor listed with its line within the debounce time and
// underlined; a parameter change through the panel that re-runs only the nodes downstream; a
// slider drag that is one undo step. Screenshots of the three editors.
#include <memory>

#include <QAbstractItemView>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSet>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTimer>

#include "demowindow.h"
#include "document/document.h"
#include "document/presetlibrary.h"
#include "engine/mesh/mesh.h"
#include "ui/document/presetbrowser.h"
#include "ui/generation/speciespreview.h"
#include "ui/generation/vertexdata.h"
#include "ui/grammar/grammareditor.h"
#include "ui/mainwindow.h"
#include "ui/nodes/curveeditor.h"
#include "ui/nodes/nodegraphscene.h"
#include "ui/nodes/nodegraphview.h"
#include "ui/nodes/parameterpanel.h"
#include "ui/speciesworkbench.h"
#include "ui/viewport/toolcontroller.h"
#include "ui/viewport/viewport.h"
#include "uitest.h"

using namespace sylva;
using namespace sylva::ui;

namespace {

constexpr int kTimeoutMs = 120000;

using sylva::ui::test::outputPath;

std::vector<std::string> inputsOf(const sylva::Value& g, const std::string& id) {
    std::vector<std::string> out;
    for (const sylva::Value& n : g.toObject().at("nodes").toArray())
        if (n.string("id", "") == id)
            if (const sylva::Value* in = n.find("inputs"))
                for (const sylva::Value& v : in->toArray())
                    out.push_back(v.toString());
    return out;
}

bool hasNode(const sylva::Value& g, const std::string& id) {
    for (const sylva::Value& n : g.toObject().at("nodes").toArray())
        if (n.string("id", "") == id) return true;
    return false;
}

} // namespace

/// A trunk from line 5 (0..4 m up) and one side branch from line 7 (0..-3 m along x at 4 m):
/// step 1, angle 90°, so where each rule's branch stands is known without growing it.
constexpr const char* kTwoRuleGrammar = "generations: 3\nangle: 90\nwidth: 0.3\naxiom: T\n"
                                        "T -> FFFFB\nB -> [+C]\nC -> FFF\n";

class TestSpecies : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<MainWindow> mWindow;
    QTemporaryDir mDir;

    doc::Document& document() { return mWindow->document(); }
    SpeciesWorkbench* bench() { return mWindow->workbench(); }
    NodeGraphScene* scene() { return bench()->graphScene(); }
    NodeGraphView* view() { return bench()->graphView(); }
    sylva::Value alder() { return document().speciesGraph("alder"); }

    void waitForPreview() {
        QTRY_VERIFY_WITH_TIMEOUT(!bench()->preview()->isBusy(), kTimeoutMs);
        QTest::qWait(30);
    }

    QPoint at(const QPointF& scenePos) { return view()->mapFromScene(scenePos); }

    /// Press, move in steps (buttons held) and release in the node editor's viewport.
    void drag(const QPoint& from, const QPoint& to) {
        test::dragThrough(view()->viewport(), {from, to}, {}, 8);
        QApplication::processEvents();
    }

    /// Drags a connection from \p from's output port onto \p to's body.
    void connectByMouse(const QString& from, const QString& to) {
        NodeItem* a = scene()->node(from);
        NodeItem* b = scene()->node(to);
        QVERIFY(a && b);
        drag(at(a->outputPort()), at(b->sceneBoundingRect().center()));
    }

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(mDir.isValid());
        mWindow = test::openDemoWindow(mDir, {1400, 950});
        QVERIFY(mWindow);
        QVERIFY(mWindow->waitForGeneration(kTimeoutMs));
        mWindow->editSpecies(QStringLiteral("alder"));
        QTRY_VERIFY(bench()->isVisible());
        waitForPreview();
        view()->frameAll();
    }

    void cleanupTestCase() { mWindow.reset(); }

    void graphShowsTheSpecies() {
        QCOMPARE(scene()->species(), QStringLiteral("alder"));
        QVERIFY(scene()->node(QStringLiteral("grow")));
        QVERIFY(scene()->node(QStringLiteral("mesh")));
        QCOMPARE(scene()->edges().size(), 1);
        // The generator is selected at once: its parameters and its grammar are shown.
        QCOMPARE(bench()->parameters()->node(), QStringLiteral("grow"));
        QCOMPARE(bench()->grammar()->node(), QStringLiteral("grow"));
        QVERIFY(bench()->grammar()->textEdit()->toPlainText().contains(QStringLiteral("axiom")));
        // Each node shows its compute time from the preview.
        const auto& runs = bench()->preview()->result().runs;
        QVERIFY(runs.count("grow") && runs.count("mesh"));
        QVERIFY(bench()->preview()->result().mesh);
        QVERIFY(bench()->preview()->editToResultMs() > 0.0);
        // A file parameter's field may be too narrow for its path: the tooltip has all of it,
        // then what the parameter is.
        QWidget* file = bench()->parameters()->editor(QStringLiteral("grammar_file"));
        QVERIFY(file);
        auto* path = file->findChild<QLineEdit*>();
        QVERIFY(path && path->text().endsWith(QStringLiteral("alder.lsys")));
        QVERIFY2(path->toolTip().startsWith(path->text() + QStringLiteral("\n\n")) &&
                     path->toolTip().endsWith(file->toolTip()),
                 qPrintable(path->toolTip()));
    }

    void savingUnderANewNameKeepsThePanels() {
        // Save As in another folder resets the document (paths are rewritten for it); the panels
        // empty on a reset, and must show the node the graph still has selected.
        QCOMPARE(scene()->selectedNodeIds(), QStringList{QStringLiteral("grow")});
        QVERIFY(QDir(mDir.path()).mkpath(QStringLiteral("elsewhere")));
        QVERIFY(mWindow->saveAs(mDir.filePath(QStringLiteral("elsewhere/renamed.sylva"))));
        QCOMPARE(scene()->selectedNodeIds(), QStringList{QStringLiteral("grow")});
        QCOMPARE(bench()->parameters()->node(), QStringLiteral("grow"));
        QCOMPARE(bench()->grammar()->node(), QStringLiteral("grow"));
        QVERIFY(bench()->grammar()->textEdit()->toPlainText().contains(QStringLiteral("axiom")));
        waitForPreview();
    }

    void editTheGraphWithMouseAndKeys() {
        const QByteArray original = document().serialized();
        const int steps = document().undoStack()->index();

        // Tab opens the searchable add menu; typing filters it and Enter adds the node.
        view()->setFocus();
        QCursor::setPos(view()->viewport()->mapToGlobal(view()->viewport()->rect().center()));
        QTest::keyClick(view(), Qt::Key_Tab);
        QMenu* menu = nullptr;
        QTRY_VERIFY((menu = qobject_cast<QMenu*>(QApplication::activePopupWidget())));
        auto* search = menu->findChild<QLineEdit*>(QStringLiteral("addNodeSearch"));
        QVERIFY(search);
        QTest::keyClicks(search, QStringLiteral("leav"));
        int visible = 0;
        for (QAction* a : menu->actions())
            visible += a->isVisible() && a->data().isValid() ? 1 : 0;
        QCOMPARE(visible, 1); // only "leaves" matches
        QTest::keyClick(search, Qt::Key_Return);
        QTRY_VERIFY(hasNode(alder(), "leaves"));
        QCOMPARE(document().undoStack()->index(), steps + 1);
        QApplication::processEvents();
        NodeItem* leaves = scene()->node(QStringLiteral("leaves"));
        QVERIFY(leaves);
        leaves->setPos(scene()->node(QStringLiteral("grow"))->pos() + QPointF(0, 120));
        view()->frameAll();

        // Connect by dragging from grow's output port onto leaves.
        connectByMouse(QStringLiteral("grow"), QStringLiteral("leaves"));
        QCOMPARE(inputsOf(alder(), "leaves"), std::vector<std::string>{"grow"});
        // leaves into mesh: mesh's one input is replaced.
        connectByMouse(QStringLiteral("leaves"), QStringLiteral("mesh"));
        QCOMPARE(inputsOf(alder(), "mesh"), std::vector<std::string>{"leaves"});
        QCOMPARE(scene()->edges().size(), 2);

        // A refused connection says why, and changes nothing.
        const QByteArray beforeRefusal = document().serialized();
        connectByMouse(QStringLiteral("mesh"), QStringLiteral("grow"));
        auto* refusal = bench()->findChild<QLabel*>(QStringLiteral("graphRefusal"));
        QVERIFY(refusal->text().contains(QStringLiteral("takes no input")));
        QCOMPARE(document().serialized(), beforeRefusal);

        // An adapt node (from the scene's API), connected, then picked up by its input end and
        // dropped on empty space: disconnected.
        QVERIFY(scene()->addNode(QStringLiteral("adapt"),
                                 scene()->node(QStringLiteral("mesh"))->pos() + QPointF(0, 140)));
        view()->frameAll();
        connectByMouse(QStringLiteral("grow"), QStringLiteral("adapt"));
        QCOMPARE(inputsOf(alder(), "adapt"), std::vector<std::string>{"grow"});
        NodeItem* adapt = scene()->node(QStringLiteral("adapt"));
        const QPointF empty = adapt->sceneBoundingRect().bottomRight() + QPointF(60, 60);
        drag(at(adapt->inputPort()), at(empty));
        QVERIFY(inputsOf(alder(), "adapt").empty());
        // Disconnecting what the tree needs is refused, with the reason.
        NodeItem* mesh = scene()->node(QStringLiteral("mesh"));
        drag(at(mesh->inputPort()), at(mesh->sceneBoundingRect().bottomRight() + QPointF(40, 90)));
        QCOMPARE(inputsOf(alder(), "mesh"), std::vector<std::string>{"leaves"});
        QVERIFY(refusal->text().contains(QStringLiteral("the tree needs it")));

        // Click a node and press Delete.
        adapt = scene()->node(QStringLiteral("adapt"));
        QTest::mouseClick(view()->viewport(), Qt::LeftButton, {},
                          at(adapt->sceneBoundingRect().center()));
        QCOMPARE(scene()->selectedNodeIds(), QStringList{QStringLiteral("adapt")});
        QTest::keyClick(view(), Qt::Key_Delete);
        QVERIFY(!hasNode(alder(), "adapt"));

        // Copy and paste leaves: a fresh id, same parameters.
        scene()->selectNode(QStringLiteral("leaves"));
        QTest::keyClick(view(), Qt::Key_C, Qt::ControlModifier);
        QTest::keyClick(view(), Qt::Key_V, Qt::ControlModifier);
        QVERIFY(hasNode(alder(), "leaves2"));

        // Moving a node with the mouse is one step and is saved.
        NodeItem* pasted = scene()->node(QStringLiteral("leaves2"));
        const int beforeMove = document().undoStack()->index();
        const QPoint grab = at(pasted->sceneBoundingRect().center() + QPointF(0, 10));
        drag(grab, grab + QPoint(60, 30));
        QTRY_COMPARE(document().undoStack()->index(), beforeMove + 1);
        QVERIFY(document().nodePosition("alder", "leaves2").has_value());

        // Undo everything: the exact file; redo everything: the edited graph again.
        const QByteArray edited = document().serialized();
        while (document().undoStack()->index() > steps)
            document().undoStack()->undo();
        QCOMPARE(document().serialized(), original);
        QTRY_COMPARE(scene()->edges().size(), 1);
        while (document().undoStack()->canRedo())
            document().undoStack()->redo();
        QCOMPARE(document().serialized(), edited);
        document().undoStack()->setIndex(steps);
        QCOMPARE(document().serialized(), original);
        waitForPreview();
    }

    void grammarErrorIsListedWhileTyping() {
        scene()->selectNode(QStringLiteral("grow"));
        GrammarEditor* g = bench()->grammar();
        QCOMPARE(g->node(), QStringLiteral("grow"));
        const QString original = g->textEdit()->toPlainText();
        const int steps = document().undoStack()->index();
        const int lines = g->textEdit()->document()->blockCount();
        g->textEdit()->setFocus();
        g->textEdit()->moveCursor(QTextCursor::End);
        QTest::keyClick(g->textEdit(), Qt::Key_Return);
        QTest::keyClicks(g->textEdit(), QStringLiteral("Q -> F[+F"));
        const int errorLine = g->textEdit()->textCursor().blockNumber() + 1;
        QVERIFY(errorLine >= lines);
        // Not checked on every key: the debounce timer (200 ms after the last key) does it.
        // (Its firing time is the event loop's; the test waits for it without timing it.)
        QVERIFY(g->diagnostics().empty());
        auto* debounce = g->findChild<QTimer*>(QStringLiteral("diagnosticsTimer"));
        QVERIFY(debounce && debounce->isActive());
        QCOMPARE(debounce->interval(), GrammarEditor::kDiagnosticsDelayMs);
        QTRY_VERIFY_WITH_TIMEOUT(!g->diagnostics().empty(), 10000);
        QCOMPARE(g->diagnostics().front().line, errorLine);
        QVERIFY(g->diagnosticsList()->item(0)->text().startsWith(
            QStringLiteral("line %1,").arg(errorLine)));
        // The squiggle is on that line, as an extra selection (the text is not edited).
        const QList<QTextEdit::ExtraSelection> marks = g->textEdit()->extraSelections();
        QCOMPARE(marks.size(), 1);
        QCOMPARE(marks.front().cursor.blockNumber(), errorLine - 1);
        QCOMPARE(marks.front().format.underlineStyle(), QTextCharFormat::WaveUnderline);
        QVERIFY(g->textEdit()->toPlainText().endsWith(QStringLiteral("Q -> F[+F")));
        // Click the error: the cursor jumps to it.
        g->textEdit()->moveCursor(QTextCursor::Start);
        QListWidgetItem* item = g->diagnosticsList()->item(0);
        QTest::mouseClick(g->diagnosticsList()->viewport(), Qt::LeftButton, {},
                          g->diagnosticsList()->visualItemRect(item).center());
        QCOMPARE(g->textEdit()->textCursor().blockNumber(), errorLine - 1);
        // The burst is one undo step that gives the grammar back.
        g->commitBurst();
        QCOMPARE(document().undoStack()->index(), steps + 1);
        document().undoStack()->undo();
        QCOMPARE(QString::fromStdString(document().grammar("alder", "grow")), original);
        QTRY_COMPARE(g->textEdit()->toPlainText(), original);
        QTRY_VERIFY(g->diagnostics().empty());
        waitForPreview();
    }

    /// The generations slider steps the preview through the derivation without editing the
    /// document (L-Py's Step); back at the end the grammar's own count is used again.
    void generationsSliderStepsThePreview() {
        scene()->selectNode(QStringLiteral("grow"));
        waitForPreview();
        GrammarEditor* g = bench()->grammar();
        const QByteArray original = document().serialized();
        const int steps = document().undoStack()->index();
        const std::size_t full = bench()->preview()->result().skeleton->segmentCount();
        QSlider* slider = g->stepSlider();
        QVERIFY(slider->maximum() >= 10);
        slider->setValue(3);
        QTRY_VERIFY_WITH_TIMEOUT(bench()->preview()->isBusy(), 2000);
        waitForPreview();
        const std::size_t early = bench()->preview()->result().skeleton->segmentCount();
        QVERIFY2(early < full / 4, qPrintable(QStringLiteral("%1 vs %2").arg(early).arg(full)));
        QCOMPARE(document().serialized(), original); // a view, not an edit
        QCOMPARE(document().undoStack()->index(), steps);
        slider->setValue(slider->maximum());
        QTRY_VERIFY_WITH_TIMEOUT(bench()->preview()->isBusy(), 2000);
        waitForPreview();
        QCOMPARE(bench()->preview()->result().skeleton->segmentCount(), full);
    }

    /// A click on a branch in the preview selects the node that grew it.
    void clickInThePreviewSelectsTheNode() {
        waitForPreview();
        scene()->selectNode(QStringLiteral("mesh"));
        Viewport* v = bench()->previewViewport();
        // The trunk: the middle of the tree's base, projected into the preview.
        const std::shared_ptr<const mesh::Mesh> m = bench()->preview()->result().mesh;
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const glm::vec3& p : m->positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const auto at = v->project(glm::vec3(0.0f, lo.y + 0.12f * (hi.y - lo.y), 0.0f));
        QVERIFY(at.has_value());
        QCOMPARE(bench()->selectNodeAt(*at), QStringLiteral("grow"));
        QCOMPARE(scene()->selectedNodeIds(), QStringList{QStringLiteral("grow")});
        // The same by a mouse click (a press and a release without moving).
        scene()->selectNode(QStringLiteral("mesh"));
        QTest::mouseClick(v, Qt::LeftButton, {}, at->toPoint());
        QCOMPARE(scene()->selectedNodeIds(), QStringList{QStringLiteral("grow")});
        // The sky selects nothing new.
        QCOMPARE(bench()->selectNodeAt(QPointF(3, 3)), QString());
    }

    /// A click on an L-system branch highlights the rule that wrote it: a trunk from one rule,
    /// a side branch from another, at places known from the grammar (step 1, angle 90°).
    void clickOnABranchHighlightsItsRule() {
        waitForPreview();
        const QByteArray original = document().serialized();
        document().setGrammar("alder", "grow", kTwoRuleGrammar, true);
        QTRY_VERIFY_WITH_TIMEOUT(bench()->preview()->isBusy(), 2000);
        waitForPreview();
        QCOMPARE(bench()->preview()->result().skeleton->segmentCount(), std::size_t(7));
        bench()->previewViewport()->frameScene();
        QTest::qWait(50);
        Viewport* v = bench()->previewViewport();
        GrammarEditor* g = bench()->grammar();
        // The trunk (0, 0..4, 0) comes from line 5, the branch (0..-3, 4, 0) from line 7.
        const auto trunk = v->project(glm::vec3(0.0f, 2.0f, 0.0f));
        const auto branch = v->project(glm::vec3(-2.0f, 4.0f, 0.0f));
        QVERIFY(trunk && branch);
        QTest::mouseClick(v, Qt::LeftButton, {}, trunk->toPoint());
        QCOMPARE(scene()->selectedNodeIds(), QStringList{QStringLiteral("grow")});
        QCOMPARE(g->node(), QStringLiteral("grow"));
        QCOMPARE(g->highlightedLine(), 5);
        QCOMPARE(g->textEdit()->textCursor().blockNumber(), 4);
        QTest::mouseClick(v, Qt::LeftButton, {}, branch->toPoint());
        QCOMPARE(g->highlightedLine(), 7);
        // The band is drawn as an extra selection on that line, not as an edit.
        bool banded = false;
        for (const QTextEdit::ExtraSelection& e : g->textEdit()->extraSelections())
            banded |= e.format.property(QTextFormat::FullWidthSelection).toBool() &&
                      e.cursor.blockNumber() == 6;
        QVERIFY(banded);
        QTest::qWait(50);
        mWindow->grab().save(outputPath(QStringLiteral("species-rule-highlight.png")));
        // Typing removes the band (its line may have moved).
        g->textEdit()->setFocus();
        QTest::keyClick(g->textEdit(), Qt::Key_End);
        QTest::keyClicks(g->textEdit(), QStringLiteral(" "));
        QCOMPARE(g->highlightedLine(), 0);
        g->commitBurst();
        while (document().serialized() != original && document().undoStack()->canUndo())
            document().undoStack()->undo();
        QCOMPARE(document().serialized(), original);
        waitForPreview();
    }

    /// With the species editor open, a click on a hand-placed tree in the scene grows that tree
    /// in the preview, selects its generator and marks the rule behind the branch clicked.
    void clickOnATreeInTheSceneMarksItsRule() {
        waitForPreview();
        const QByteArray original = document().serialized();
        document().setGrammar("alder", "grow", kTwoRuleGrammar, true);
        QVERIFY(mWindow->waitForGeneration(kTimeoutMs));
        waitForPreview();
        doc::TreeId id = 0;
        for (const doc::TreeId t : document().treeIds())
            if (document().tree(t).species == "alder") id = t;
        QVERIFY(id != 0);
        Viewport* v = mWindow->viewport();
        glm::mat4 transform(1.0f);
        int index = -1;
        for (std::size_t i = 0; i < v->trees().size(); ++i)
            if (v->trees()[i].id == id) {
                transform = v->trees()[i].transform;
                index = int(i);
            }
        QVERIFY(index >= 0);
        // Look at that tree closely, so that no other stands in front.
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const glm::vec3& p : v->trees()[std::size_t(index)].mesh->positions) {
            const glm::vec3 w(transform * glm::vec4(p, 1.0f));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
        v->frameBox(lo, hi);
        v->update();
        QTest::qWait(50);
        auto screenOf = [&](const glm::vec3& local) {
            const auto at = v->project(glm::vec3(transform * glm::vec4(local, 1.0f)));
            return at ? at->toPoint() : QPoint(-1, -1);
        };
        mWindow->tools().setTool(ToolController::Tool::Select);
        GrammarEditor* g = bench()->grammar();
        scene()->selectNode(QStringLiteral("mesh"));
        // The trunk (line 5), then the side branch (line 7), as the grammar places them.
        const QPoint trunk = screenOf({0.0f, 2.0f, 0.0f});
        QCOMPARE(v->treeAt(trunk), index);
        QTest::mouseClick(v, Qt::LeftButton, {}, trunk);
        QTRY_COMPARE(g->highlightedLine(), 5);
        QCOMPARE(scene()->selectedNodeIds(), QStringList{QStringLiteral("grow")});
        QCOMPARE(document().selectedTrees(), QList<doc::TreeId>{id});
        // From above, where the other trees' trunks do not hide it; the first point along the
        // branch that this tree's own triangles are hit at.
        const glm::vec3 top(transform * glm::vec4(-1.5f, 4.0f, 0.0f, 1.0f));
        v->camera().lookFrom(top + glm::vec3(0.0f, 12.0f, 0.5f), top);
        v->update();
        QTest::qWait(50);
        QPoint branch(-1, -1);
        for (float x = 0.4f; x < 2.9f && branch.x() < 0; x += 0.1f)
            if (const QPoint p = screenOf({-x, 4.0f, 0.0f}); v->treeAt(p) == index) branch = p;
        QVERIFY(branch.x() >= 0);
        QTest::mouseClick(v, Qt::LeftButton, {}, branch);
        QTRY_COMPARE(g->highlightedLine(), 7);
        mWindow->grab().save(outputPath(QStringLiteral("species-scene-click-rule.png")));
        document().selectTrees({});
        while (document().serialized() != original && document().undoStack()->canUndo())
            document().undoStack()->undo();
        QCOMPARE(document().serialized(), original);
        QVERIFY(mWindow->waitForGeneration(kTimeoutMs));
        waitForPreview();
    }

    /// A crown envelope's profile is drawn and edited as a curve: start from a Weber-Penn shape,
    /// drag a point (one undo step), double-click to add, right-click and Delete to remove; undo
    /// of all of it gives back the exact document.
    void envelopeProfileIsEditedAsACurve() {
        waitForPreview();
        const QByteArray original = document().serialized();
        const QString presets = doc::PresetLibrary::directory();
        auto* dock = mWindow->findChild<QDockWidget*>(QStringLiteral("parametersDock"));
        QVERIFY(dock);
        dock->raise(); // tabified with the statistics: the panel must be on top to be used
        // A named profile (a string) is shown with the engine's own samples.
        document().applyPreset("alder", QDir(presets).filePath("italian-cypress.json"));
        scene()->selectNode(QStringLiteral("grow"));
        QWidget* env = bench()->parameters()->editor(QStringLiteral("envelope"));
        QVERIFY(env);
        auto* curve = env->findChild<CurveEditor*>(QStringLiteral("curve"));
        QVERIFY(curve);
        QTRY_VERIFY(curve->isVisible());
        QCOMPARE(curve->points().size(), std::size_t(33));

        // A sphere has no curve until it becomes a profile of the same place and size.
        document().applyPreset("alder", QDir(presets).filePath("sc-round.json"));
        scene()->selectNode(QStringLiteral("crown"));
        env = bench()->parameters()->editor(QStringLiteral("envelope"));
        curve = env->findChild<CurveEditor*>(QStringLiteral("curve"));
        auto* shapes = env->findChild<QComboBox*>(QStringLiteral("profileShape"));
        QVERIFY(curve && shapes);
        QVERIFY(!curve->isVisible());
        const int steps = document().undoStack()->index();
        // Open the list and click "flame", as a user would.
        const int flameRow = shapes->findData(QStringLiteral("flame"));
        QVERIFY(flameRow > 0);
        shapes->showPopup();
        QAbstractItemView* list = shapes->view();
        QTRY_VERIFY(list->isVisible());
        const QRect item = list->visualRect(list->model()->index(flameRow, 0));
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, item.center());
        QTRY_VERIFY(!list->isVisible());
        QCOMPARE(document().undoStack()->index(), steps + 1);
        auto envelope = [this] {
            const graph::SpeciesGraph g = document().engineSpecies("alder");
            return g.findNode("crown")->params.find("envelope")->toJson();
        };
        const std::string flame = envelope();
        // The sphere of radius 4.5 at (0, 6, 0): base 4.5 lower, 9 high.
        QVERIFY2(flame.find("\"center\":[0,1.5,0]") != std::string::npos, flame.c_str());
        QVERIFY2(flame.find("\"height\":9") != std::string::npos, flame.c_str());
        QVERIFY2(flame.find("\"radius\":4.5") != std::string::npos, flame.c_str());
        QTRY_VERIFY(curve->isVisible());
        QCOMPARE(curve->points().size(), std::size_t(9));
        QCOMPARE(curve->points().front().x(), 0.0);
        QCOMPARE(curve->points().back().x(), 1.0);
        QTest::qWait(20);

        // Drag the middle point 25 px outwards: wider there, as one undo step.
        const QPointF middle = curve->points()[4];
        const QPoint from = curve->toScreen(middle).toPoint();
        test::dragThrough(curve, {from, from + QPoint(25, 0)});
        QCOMPARE(document().undoStack()->index(), steps + 2);
        QVERIFY(curve->points()[4].y() > middle.y() + 0.05);
        QVERIFY(std::abs(curve->points()[4].x() - middle.x()) < 0.02);
        const sylva::Value dragged = sylva::Value::parseJson(envelope());
        const sylva::Value::Array& profile = dragged.find("profile")->toArray();
        QCOMPARE(profile.size(), std::size_t(9));
        QCOMPARE(profile[4].toArray()[1].toNumber(), curve->points()[4].y());
        waitForPreview();
        bench()->previewViewport()->frameScene(); // an earlier test zoomed in by hand
        QTest::qWait(50);
        mWindow->grab().save(outputPath(QStringLiteral("ui_species_curve.png")));
        env->parentWidget()->grab().save(outputPath(QStringLiteral("ui_species_curve_panel.png")));

        // Double-click between two points adds one; right-click removes it; Delete too.
        const QPointF a = curve->toScreen(curve->points()[1]),
                      b = curve->toScreen(curve->points()[2]);
        const QPoint between = ((a + b) / 2.0).toPoint() + QPoint(0, 0);
        QTest::mouseDClick(curve, Qt::LeftButton, {}, between);
        QCOMPARE(curve->points().size(), std::size_t(10));
        QCOMPARE(document().undoStack()->index(), steps + 3);
        QTest::mouseClick(curve, Qt::RightButton, {}, between);
        QCOMPARE(curve->points().size(), std::size_t(9));
        QCOMPARE(document().undoStack()->index(), steps + 4);
        QTest::mouseClick(curve, Qt::LeftButton, {}, curve->toScreen(curve->points()[6]).toPoint());
        QCOMPARE(curve->selected(), 6);
        QTest::keyClick(curve, Qt::Key_Delete);
        QCOMPARE(curve->points().size(), std::size_t(8));
        // The first and last points stay (t = 0 and t = 1).
        QTest::mouseClick(curve, Qt::RightButton, {},
                          curve->toScreen(curve->points()[0]).toPoint());
        QCOMPARE(curve->points().size(), std::size_t(8));
        QCOMPARE(document().undoStack()->index(), steps + 5);

        while (document().serialized() != original && document().undoStack()->canUndo())
            document().undoStack()->undo();
        QCOMPARE(document().serialized(), original);
        scene()->selectNode(QStringLiteral("grow"));
        waitForPreview();
    }

    void parameterChangeRerunsOnlyDownstream() {
        waitForPreview();
        SpeciesPreview* preview = bench()->preview();
        const auto before = preview->evaluationCounts();
        const std::size_t vertices = preview->result().mesh->vertexCount();
        scene()->selectNode(QStringLiteral("mesh"));
        QCOMPARE(bench()->parameters()->node(), QStringLiteral("mesh"));
        auto* resolution =
            qobject_cast<QSpinBox*>(bench()->parameters()->editor(QStringLiteral("resolution")));
        QVERIFY(resolution);
        QCOMPARE(resolution->value(), 8);
        resolution->setValue(5);
        QCOMPARE(document().param("alder", "mesh.resolution").toNumber(), 5.0);
        QTRY_VERIFY_WITH_TIMEOUT(preview->isBusy() || preview->evaluationCounts() != before,
                                 kTimeoutMs);
        waitForPreview();
        auto after = preview->evaluationCounts();
        QCOMPARE(after["mesh"], before.at("mesh") + 1);
        QCOMPARE(after["grow"], before.at("grow")); // upstream: kept
        QVERIFY(preview->result().mesh->vertexCount() < vertices);
        // The vertices to upload come made by the worker, for this mesh.
        QVERIFY(preview->result().vertices);
        QCOMPARE(preview->result().vertices->size(), preview->result().mesh->vertexCount());
        QVERIFY(preview->editToResultMs() > 0.0);
        QVERIFY(document().param("alder", "mesh.resolution").toNumber() == 5.0);
        document().undoStack()->undo();
        waitForPreview();
        QCOMPARE(resolution->value(), 8);
        // An upstream parameter re-runs both.
        const auto mid = preview->evaluationCounts();
        document().setParam("alder", "grow.angle", 30.0);
        QTRY_VERIFY_WITH_TIMEOUT(preview->evaluationCounts()["grow"] == mid.at("grow") + 1,
                                 kTimeoutMs);
        waitForPreview();
        QCOMPARE(preview->evaluationCounts()["mesh"], mid.at("mesh") + 1);
        document().undoStack()->undo();
        waitForPreview();
    }

    void sliderDragIsOneUndoStep() {
        scene()->selectNode(QStringLiteral("mesh"));
        QWidget* editor = bench()->parameters()->editor(QStringLiteral("radius_scale"));
        QVERIFY(editor);
        auto* slider = editor->findChild<QSlider*>(QStringLiteral("slider"));
        QVERIFY(slider);
        mWindow->findChild<QDockWidget*>(QStringLiteral("parametersDock"))->raise();
        QTRY_VERIFY(slider->isVisible());
        const int steps = document().undoStack()->index();
        const QByteArray original = document().serialized();
        // Drag the handle with the mouse from its place to the right.
        const int x0 = QStyle::sliderPositionFromValue(slider->minimum(), slider->maximum(),
                                                       slider->value(), slider->width() - 10) +
                       5;
        const QPoint from(x0, slider->height() / 2);
        test::dragThrough(slider, {from, from + QPoint(40, 0)});
        QVERIFY(document().param("alder", "mesh.radius_scale").isNumber());
        QVERIFY(document().param("alder", "mesh.radius_scale").toNumber() > 1.0);
        QCOMPARE(document().undoStack()->index(), steps + 1);
        document().undoStack()->undo();
        QCOMPARE(document().serialized(), original);
        // Reset to default removes the value.
        document().setParam("alder", "mesh.radius_scale", 2.0);
        // The reset button beside the editor (in the same row).
        auto* reset = bench()
                          ->parameters()
                          ->editor(QStringLiteral("radius_scale"))
                          ->parentWidget()
                          ->findChild<QWidget*>(QStringLiteral("reset_radius_scale"));
        QVERIFY(reset && reset->isEnabled());
        QTest::mouseClick(reset, Qt::LeftButton);
        QVERIFY(document().param("alder", "mesh.radius_scale").isNull());
        // The spin box offers the metadata's range only.
        auto* resolution =
            qobject_cast<QSpinBox*>(bench()->parameters()->editor(QStringLiteral("resolution")));
        QVERIFY(resolution->maximum() == 64 && resolution->minimum() == 3);
        // A value that cannot be read is refused with the reason and changes nothing.
        const QByteArray beforeBad = document().serialized();
        QWidget* bands = bench()->parameters()->editor(QStringLiteral("lod_bands"));
        bands->findChild<QPlainTextEdit*>(QStringLiteral("json"))
            ->setPlainText(QStringLiteral("[[60, 3"));
        QTest::mouseClick(bands->findChild<QPushButton*>(), Qt::LeftButton);
        QVERIFY(!bench()->parameters()->errorText().isEmpty());
        QCOMPARE(document().serialized(), beforeBad);
        document().undoStack()->setIndex(steps);
        waitForPreview();
    }

    /// The preset browser: every preset with a thumbnail drawn by Sylva; a double click
    /// applies one to the species (one undo step), undo gives the species back.
    void presetBrowserAppliesAPreset() {
        PresetBrowser* browser = mWindow->presetBrowser();
        mWindow->findChild<QDockWidget*>(QStringLiteral("presetBrowserDock"))->raise();
        QTRY_VERIFY(browser->isVisible());
        QCOMPARE(browser->targetSpecies(), QStringLiteral("alder"));
        QListWidget* list = browser->list();
        QVERIFY(list->count() >= 12);
        QTRY_VERIFY_WITH_TIMEOUT(browser->pendingThumbnails() == 0, kTimeoutMs);
        // Thumbnails are drawings of the trees: not blank, not uniform.
        for (int i = 0; i < list->count(); ++i) {
            const QImage image =
                list->item(i)->icon().pixmap(PresetBrowser::kThumbnailSize).toImage();
            QSet<QRgb> colours;
            for (int y = 0; y < image.height(); y += 4)
                for (int x = 0; x < image.width(); x += 4)
                    colours.insert(image.pixel(x, y));
            QVERIFY2(colours.size() > 8, qPrintable(list->item(i)->text()));
        }
        const QByteArray original = document().serialized();
        QListWidgetItem* ternary = nullptr;
        for (int i = 0; i < list->count(); ++i)
            if (list->item(i)
                    ->data(Qt::UserRole)
                    .toString()
                    .endsWith(QStringLiteral("ternary-tree.json")))
                ternary = list->item(i);
        QVERIFY(ternary);
        list->setCurrentItem(ternary);
        list->scrollToItem(ternary);
        QApplication::processEvents();
        QSignalSpy failures(browser, &PresetBrowser::failed);
        // A double click as the mouse makes it: press, release, then the double-click press.
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {},
                          list->visualItemRect(ternary).center());
        QTest::mouseDClick(list->viewport(), Qt::LeftButton, {},
                           list->visualItemRect(ternary).center());
        QVERIFY2(failures.isEmpty(),
                 failures.isEmpty() ? "" : qPrintable(failures.front().front().toString()));
        QCOMPARE(document().undoStack()->undoText(), QStringLiteral("Apply preset ternary-tree"));
        QTRY_VERIFY(scene()->node(QStringLiteral("grow")));
        QVERIFY(document().grammar("alder", "grow").find("Ternary") != std::string::npos ||
                document().grammar("alder", "grow").find("ternary") != std::string::npos);
        waitForPreview();
        document().undoStack()->undo();
        QCOMPARE(document().serialized(), original);
        waitForPreview();
        const QImage shot = browser->grab().toImage();
        QVERIFY(shot.save(outputPath(QStringLiteral("ui_species_presets.png"))));
    }

    void screenshots() {
        scene()->selectNode(QStringLiteral("grow"));
        view()->frameAll();
        waitForPreview();
        QTest::qWait(200);
        QVERIFY(mWindow->saveWindowScreenshot(outputPath(QStringLiteral("ui_species_window.png"))));
        QVERIFY(view()->grab().save(outputPath(QStringLiteral("ui_species_graph.png"))));
        QVERIFY(
            bench()->grammar()->grab().save(outputPath(QStringLiteral("ui_species_grammar.png"))));
        scene()->selectNode(QStringLiteral("mesh"));
        QTest::qWait(200); // the new editors are laid out by the event loop
        QVERIFY(bench()->parameters()->grab().save(
            outputPath(QStringLiteral("ui_species_parameters.png"))));
    }
};

QTEST_MAIN(TestSpecies)

#include "test_species.moc"
