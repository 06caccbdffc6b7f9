// Smoke test of the editor window under a real X server (xvfb-run): the default preset is
// generated through the real pipeline, drawn with OpenGL, grabbed to PNG and inspected.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenu>
#include <QMenuBar>
#include <QMouseEvent>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QWheelEvent>

#include "document/presetlibrary.h"
#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "ui/document/messagespanel.h"
#include "ui/document/statspanel.h"
#include "ui/generation/treegenerator.h"
#include "ui/mainwindow.h"
#include "ui/viewport/orbitcamera.h"
#include "ui/viewport/viewport.h"
#include "uitest.h"

using namespace sylva::ui;
using sylva::doc::PresetLibrary;

namespace {

constexpr int kGenerationTimeoutMs = 120000;
const QSize kViewportSize(640, 480);

using sylva::ui::test::outputPath;

/// Bark is a warm brown (red > green > blue, green about half way between); leaves are green
/// dominant. Neither the blue-grey background, the neutral grid nor its red and blue axis
/// lines are either.
bool isBark(QRgb c) {
    const int r = qRed(c), g = qGreen(c), b = qBlue(c);
    return r > g && g > b && r - b >= 25 && 4 * (g - b) >= r - b;
}
bool isLeaf(QRgb c) {
    const int r = qRed(c), g = qGreen(c), b = qBlue(c);
    return g > r + 10 && g > b + 10;
}
bool isTree(QRgb c) {
    return isBark(c) || isLeaf(c);
}

int channelDifference(QRgb a, QRgb b) {
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                     std::abs(qBlue(a) - qBlue(b))});
}

struct TreePixels {
    qint64 tree = 0;     ///< bark- or leaf-coloured pixels
    qint64 changed = 0;  ///< pixels that differ from the empty scene
    qint64 onBorder = 0; ///< tree pixels in the outermost two rows / columns
    QRect box;           ///< bounds of the changed pixels
};

TreePixels analyse(const QImage& tree, const QImage& empty) {
    TreePixels result;
    int x0 = tree.width(), y0 = tree.height(), x1 = -1, y1 = -1;
    for (int y = 0; y < tree.height(); ++y) {
        for (int x = 0; x < tree.width(); ++x) {
            const QRgb c = tree.pixel(x, y);
            if (isTree(c)) {
                ++result.tree;
                if (x < 2 || y < 2 || x >= tree.width() - 2 || y >= tree.height() - 2)
                    ++result.onBorder;
            }
            if (channelDifference(c, empty.pixel(x, y)) > 24) {
                ++result.changed;
                x0 = std::min(x0, x);
                y0 = std::min(y0, y);
                x1 = std::max(x1, x);
                y1 = std::max(y1, y);
            }
        }
    }
    if (x1 >= 0) result.box = QRect(QPoint(x0, y0), QPoint(x1, y1));
    return result;
}

void sendMouse(QWidget* widget, QEvent::Type type, QPoint pos, Qt::MouseButton button,
               Qt::MouseButtons buttons) {
    QMouseEvent event(type, QPointF(pos), widget->mapToGlobal(QPointF(pos)), button, buttons,
                      Qt::NoModifier);
    QApplication::sendEvent(widget, &event);
}

void drag(QWidget* widget, Qt::MouseButton button, QPoint from, QPoint delta) {
    sendMouse(widget, QEvent::MouseButtonPress, from, button, button);
    // Two moves: the camera must accumulate deltas, not jump to the last position.
    sendMouse(widget, QEvent::MouseMove, from + delta / 2, Qt::NoButton, button);
    sendMouse(widget, QEvent::MouseMove, from + delta, Qt::NoButton, button);
    sendMouse(widget, QEvent::MouseButtonRelease, from + delta, button, Qt::NoButton);
}

/// Runs sylva-cli with \p args; true when it exits with 0.
bool runCli(const QStringList& args) {
    QProcess cli;
    cli.start(QStringLiteral(SYLVA_CLI_PATH), args);
    if (!cli.waitForFinished(kGenerationTimeoutMs)) return false;
    if (cli.exitStatus() != QProcess::NormalExit || cli.exitCode() != 0) {
        qWarning("sylva-cli %s: %s", qPrintable(args.join(QLatin1Char(' '))),
                 cli.readAllStandardError().constData());
        return false;
    }
    return true;
}

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/// The editor's File ▸ Export of what is open and sylva-cli \p command on \p source write the
/// same bytes, for every extension in \p extensions (same file names in two folders: an OBJ
/// names its MTL after itself).
void exportEqualsCli(MainWindow& window, const QString& command, const QString& source,
                     const QStringList& extensions) {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("editor")));
    QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("cli")));
    for (const QString& ext : extensions) {
        const QString name = QStringLiteral("export.") + ext;
        const QString ours = dir.filePath(QStringLiteral("editor/") + name);
        const QString theirs = dir.filePath(QStringLiteral("cli/") + name);
        QVERIFY2(window.exportTo(ours), qPrintable(window.lastError()));
        QVERIFY(runCli({command, source, QStringLiteral("-o"), theirs}));
        const QByteArray a = readAll(ours), b = readAll(theirs);
        QVERIFY2(a.size() > 1000, qPrintable(ours));
        QVERIFY2(a == b, qPrintable(name + QStringLiteral(" differs from sylva-cli's")));
        if (ext == QStringLiteral("obj"))
            QCOMPARE(readAll(dir.filePath(QStringLiteral("editor/export.mtl"))),
                     readAll(dir.filePath(QStringLiteral("cli/export.mtl"))));
    }
}

/// Writes \p text to \p path in place (truncate and write).
bool writeFile(const QString& path, const QByteArray& text) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(text) == text.size();
}

/// A grammar of the bush (5^n segments after n generations).
QByteArray bushGrammar(int generations) {
    return "generations: " + QByteArray::number(generations) +
           "\nangle: 25.7\nstep: 0.5\nwidth: 0.08\naxiom: F\nF -> F[+F]F[-F]F\n";
}

bool near(float a, float b, float tolerance = 1e-4f) {
    return std::abs(a - b) <= tolerance * std::max(1.0f, std::abs(b));
}

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        // Settings, recent files and the autosave copy go to a test folder, not the user's.
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY2(!qEnvironmentVariableIsEmpty("SYLVA_PRESETS_DIR"),
                 "run through ctest, which points SYLVA_PRESETS_DIR at presets/");
        QVERIFY2(QFileInfo::exists(PresetLibrary::defaultPreset()),
                 qPrintable(QStringLiteral("no default preset in ") + PresetLibrary::directory()));

        mWindow = std::make_unique<MainWindow>();
        mWindow->viewport()->setFixedSize(kViewportSize);
        mWindow->show();
        QVERIFY(QTest::qWaitForWindowExposed(mWindow.get()));
        QSignalSpy finished(mWindow.get(), &MainWindow::generationFinished);
        QVERIFY(mWindow->openDefaultPreset());
        QVERIFY(mWindow->isGenerating() || finished.count() == 1);
        QVERIFY(finished.count() == 1 || finished.wait(kGenerationTimeoutMs));
        QCOMPARE(finished.count(), 1);
        QVERIFY2(finished.first().first().toBool(), qPrintable(mWindow->lastError()));
        QVERIFY2(mWindow->viewport()->glError().isEmpty(),
                 qPrintable(mWindow->viewport()->glError()));
        qInfo("GL: %s", qPrintable(mWindow->viewport()->glInfo()));
    }

    void cleanupTestCase() { mWindow.reset(); }

    /// No two of the window's actions share a shortcut: Qt fires neither of an ambiguous pair
    /// (Export and Edit species both had Ctrl+E, and the keys did nothing).
    void everyShortcutIsUnique() {
        std::map<QString, QString> owner;
        for (const QAction* a : mWindow->findChildren<QAction*>()) {
            for (const QKeySequence& k : a->shortcuts()) {
                const QString key = k.toString(QKeySequence::PortableText);
                const auto [it, fresh] = owner.emplace(key, a->text());
                QVERIFY2(fresh || it->second == a->text(),
                         qPrintable(QStringLiteral("%1 is both '%2' and '%3'")
                                        .arg(key, it->second, a->text())));
            }
        }
        QVERIFY(owner.count(QStringLiteral("Ctrl+Shift+E")) == 1);
    }

    /// The tree is drawn: compared with the same view without the mesh, many pixels change,
    /// they are bark/leaf coloured, centred, tall (framed) and not cut by the border.
    void defaultPresetIsDrawn() {
        Viewport* viewport = mWindow->viewport();
        viewport->frameScene();
        const QImage tree = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        QCOMPARE(tree.size(), kViewportSize * viewport->devicePixelRatio());
        QVERIFY(tree.save(outputPath(QStringLiteral("ui_smoke_tree.png"))));

        const auto mesh = viewport->mesh();
        QVERIFY(mesh && !mesh->empty());
        viewport->setMesh(nullptr, false);
        const QImage empty = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        viewport->setMesh(mesh, false);
        QVERIFY(empty.save(outputPath(QStringLiteral("ui_smoke_empty.png"))));

        // The empty scene is the gradient, not one clear colour: the renderer works at all.
        QVERIFY(channelDifference(empty.pixel(5, 5), empty.pixel(5, empty.height() - 5)) > 40);
        qint64 treeInEmpty = 0;
        for (int y = 0; y < empty.height(); ++y)
            for (int x = 0; x < empty.width(); ++x)
                treeInEmpty += isTree(empty.pixel(x, y));
        QCOMPARE(treeInEmpty, qint64(0)); // the classifier does not fire on background or grid

        const TreePixels px = analyse(tree, empty);
        const qint64 total = qint64(tree.width()) * tree.height();
        qInfo("tree pixels %lld, changed %lld of %lld, box %d,%d %dx%d", px.tree, px.changed, total,
              px.box.x(), px.box.y(), px.box.width(), px.box.height());
        QVERIFY2(px.tree > total / 100, "fewer than 1% of the pixels are bark or leaf coloured");
        QVERIFY(px.changed >= px.tree / 2);
        QCOMPARE(px.onBorder, qint64(0)); // framed, not clipped
        const QPointF centre = QRectF(px.box).center();
        QVERIFY2(std::abs(centre.x() - tree.width() / 2.0) < 0.2 * tree.width(),
                 "the tree is not centred horizontally");
        QVERIFY2(std::abs(centre.y() - tree.height() / 2.0) < 0.2 * tree.height(),
                 "the tree is not centred vertically");
        QVERIFY2(px.box.height() > tree.height() / 2, "the tree is not framed (too small)");
    }

    /// The bark's back faces are culled (issue 19: a third of a software renderer's frame) and
    /// the picture does not change; what may be seen from behind is never culled.
    void backFacesOfTheBarkAreCulled() {
        Viewport* viewport = mWindow->viewport();
        viewport->frameScene();
        QVERIFY(viewport->backFaceCulling()); // the default
        const QImage culled = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        viewport->setBackFaceCulling(false);
        const QImage all = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        qint64 differ = 0;
        for (int y = 0; y < culled.height(); ++y)
            for (int x = 0; x < culled.width(); ++x)
                differ += channelDifference(culled.pixel(x, y), all.pixel(x, y)) > 24;
        qInfo("pixels that differ with and without culling: %lld", differ);
        QVERIFY2(differ * 1000 < qint64(culled.width()) * culled.height(),
                 "culling the bark's back faces changed the picture");

        // A square at the view's centre, wound clockwise as the camera sees it: its back face.
        const std::shared_ptr<const sylva::mesh::Mesh> tree = viewport->mesh();
        const OrbitCamera& cam = viewport->camera();
        const float half = 0.2f * glm::length(cam.eye() - cam.target());
        const glm::vec3 t = cam.target(), r = half * cam.right(), u = half * cam.up();
        auto square = [&](const std::string& material, bool ribbons) {
            auto m = std::make_shared<sylva::mesh::Mesh>();
            m->positions = {t - r - u, t + r - u, t + r + u, t - r + u};
            m->normals.assign(4, -cam.forward());
            m->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            m->indices = {0, 2, 1, 0, 3, 2};
            m->submeshes.push_back({material, 0, 6});
            m->cameraRibbons = ribbons;
            return m;
        };
        viewport->setMesh(std::make_shared<sylva::mesh::Mesh>(), false);
        const QImage empty = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        auto drawnPixels = [&](const std::string& material, bool ribbons) {
            viewport->setMesh(square(material, ribbons), false);
            const QImage image = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
            qint64 n = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x)
                    n += channelDifference(image.pixel(x, y), empty.pixel(x, y)) > 24;
            return n;
        };
        const qint64 whole = drawnPixels("bark", false); // culling off: drawn
        QVERIFY2(whole > 10000, qPrintable(QString::number(whole)));
        viewport->setBackFaceCulling(true);
        QCOMPARE(drawnPixels("bark", false), qint64(0)); // a tube's back face: culled
        QCOMPARE(drawnPixels("bark", true), whole);      // camera ribbons: two-sided
        QVERIFY(drawnPixels("leaf", false) > whole / 2); // leaf cards (cut out): two-sided
        // A user's mesh (grey: a few pixels are as dark as the sky there): two-sided.
        QVERIFY(drawnPixels("obstacle", false) > whole * 9 / 10);
        viewport->setMesh(tree, false);
    }

    /// A leaf texture whose header declares 20000 × 20000 pixels (a few bytes on disk): the
    /// leaves are drawn without it, nothing is decoded, and the status bar and the Messages
    /// panel say why.
    void oversizedTextureIsReportedAndDrawnWithout() {
        Viewport* viewport = mWindow->viewport();
        const std::shared_ptr<const sylva::mesh::Mesh> tree = viewport->mesh();
        const QString huge = outputPath(QStringLiteral("ui_smoke_huge_leaf.ppm"));
        QFile file(huge);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("P6\n20000 20000\n255\n");
        file.write(QByteArray(30, '\x7f'));
        file.close();
        const OrbitCamera& cam = viewport->camera();
        const float half = 0.2f * glm::length(cam.eye() - cam.target());
        const glm::vec3 t = cam.target(), r = half * cam.right(), u = half * cam.up();
        auto m = std::make_shared<sylva::mesh::Mesh>();
        m->positions = {t - r - u, t + r - u, t + r + u, t - r + u};
        m->normals.assign(4, -cam.forward());
        m->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        m->indices = {0, 1, 2, 0, 2, 3};
        m->submeshes.push_back({"leaf", 0, 6, huge.toStdString()});
        const QStringList before = viewport->textureProblems();
        viewport->setMesh(m, false);
        const QImage image = viewport->grabFramebuffer();
        QVERIFY(!image.isNull());
        const QStringList problems = viewport->textureProblems();
        QCOMPARE(problems.size(), before.size() + 1);
        QVERIFY2(problems.last().contains(QStringLiteral("ui_smoke_huge_leaf.ppm is 20000 × 20000 "
                                                         "pixels")),
                 qPrintable(problems.last()));
        QTRY_VERIFY(mWindow->statusBar()->currentMessage().contains(
            QStringLiteral("ui_smoke_huge_leaf.ppm")));
        MessagesPanel* messages = mWindow->messages();
        QVERIFY(messages->count() > 0);
        QVERIFY2(messages->message(messages->count() - 1).contains(QStringLiteral("20000 × 20000")),
                 qPrintable(messages->message(messages->count() - 1)));
        // Asked again (the next frame): the file is not read again, nor reported twice.
        viewport->grabFramebuffer();
        QCOMPARE(viewport->textureProblems().size(), before.size() + 1);
        viewport->setMesh(tree, false);
    }

    void statsShowTheGeneratedTree() {
        const GenerationResult& result = mWindow->lastResult();
        QVERIFY(result.ok());
        QCOMPARE(QFileInfo(result.path), QFileInfo(PresetLibrary::defaultPreset()));
        StatsPanel* stats = mWindow->statsPanel();
        QCOMPARE(stats->value(QStringLiteral("statVertices")),
                 QString::number(result.mesh->vertexCount()));
        QCOMPARE(stats->value(QStringLiteral("statTriangles")),
                 QString::number(result.mesh->indices.size() / 3));
        QVERIFY(result.mesh->vertexCount() > 100);
        QVERIFY(stats->value(QStringLiteral("statSegments")).toLongLong() > 0);
        QVERIFY(stats->value(QStringLiteral("statSpecies")) == result.speciesName);
        QVERIFY(!result.speciesName.isEmpty());
        QVERIFY(result.height() > 0.0);
        QVERIFY(mWindow->windowTitle().contains(result.speciesName));
    }

    void leftDragOrbits() {
        Viewport* viewport = mWindow->viewport();
        viewport->frameScene();
        const QImage before = viewport->grabFramebuffer();
        const OrbitCamera start = viewport->camera();
        QSignalSpy changed(viewport, &Viewport::cameraChanged);
        drag(viewport, Qt::LeftButton, QPoint(300, 200), QPoint(80, -30));
        const OrbitCamera& cam = viewport->camera();
        QVERIFY(near(cam.yaw(), start.yaw() - 80.0f * OrbitCamera::kRadiansPerPixel));
        QVERIFY(near(cam.pitch(), start.pitch() - 30.0f * OrbitCamera::kRadiansPerPixel));
        QVERIFY(glm::length(cam.target() - start.target()) < 1e-6f);
        QCOMPARE(changed.count(), 2);
        const QImage after = viewport->grabFramebuffer();
        QVERIFY(after != before);
        QVERIFY(after.save(outputPath(QStringLiteral("ui_smoke_orbited.png"))));
    }

    void rightDragPansAndWheelZooms() {
        Viewport* viewport = mWindow->viewport();
        viewport->frameScene();
        const OrbitCamera start = viewport->camera();
        drag(viewport, Qt::RightButton, QPoint(300, 200), QPoint(40, 0));
        const OrbitCamera& cam = viewport->camera();
        const float worldPerPixel =
            2.0f * start.distance() * std::tan(0.5f * start.fovY()) / float(viewport->height());
        // The target slides left along the camera's right vector: the scene follows the mouse.
        const glm::vec3 moved = cam.target() - start.target();
        QVERIFY(glm::length(moved + start.right() * 40.0f * worldPerPixel) <
                1e-4f * start.distance());
        QCOMPARE(cam.yaw(), start.yaw());

        QWheelEvent wheel(QPointF(320, 240), viewport->mapToGlobal(QPointF(320, 240)), QPoint(),
                          QPoint(0, 240), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(viewport, &wheel);
        QVERIFY(near(cam.distance(),
                     start.distance() * OrbitCamera::kZoomPerStep * OrbitCamera::kZoomPerStep));

        // F frames the tree again: back to the framed target and distance.
        viewport->setFocus();
        QTest::keyClick(viewport, Qt::Key_F);
        QVERIFY(near(cam.distance(), start.distance()));
        QVERIFY(glm::length(cam.target() - start.target()) < 1e-4f * start.distance());
    }

    void brokenFileKeepsTheTreeAndReportsTheError() {
        const auto mesh = mWindow->viewport()->mesh();
        const QString missing = outputPath(QStringLiteral("no-such-species.json"));
        QSignalSpy finished(mWindow.get(), &MainWindow::generationFinished);
        mWindow->openSpecies(missing);
        QVERIFY(finished.wait(kGenerationTimeoutMs));
        QCOMPARE(finished.first().first().toBool(), false);
        QVERIFY(mWindow->lastError().contains(QStringLiteral("no-such-species.json")));
        QVERIFY(mWindow->statusBar()->currentMessage().contains(
            QStringLiteral("no-such-species.json")));
        QCOMPARE(mWindow->viewport()->mesh(), mesh); // the last good tree stays
    }

    void presetsMenuListsThePresetsFolder() {
        const QDir dir(qEnvironmentVariable("SYLVA_PRESETS_DIR"));
        const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files);
        QVERIFY(!files.isEmpty());
        Q_EMIT mWindow->presetsMenu()->aboutToShow();
        const QList<QAction*> actions = mWindow->presetsMenu()->actions();
        QCOMPARE(actions.size(), files.size());
        QStringList paths;
        for (QAction* action : actions)
            paths << QFileInfo(action->data().toString()).fileName();
        paths.sort();
        QStringList expected = files;
        expected.sort();
        QCOMPARE(paths, expected);
    }

    void screenshotWritesThePng() {
        const QString path = outputPath(QStringLiteral("ui_smoke_screenshot.png"));
        QFile::remove(path);
        QVERIFY(mWindow->saveScreenshot(path));
        const QImage image(path);
        QCOMPARE(image.size(), kViewportSize * mWindow->viewport()->devicePixelRatio());
        QVERIFY(!mWindow->saveScreenshot(QStringLiteral("/nonexistent-dir/shot.png")));
    }

    /// File ▸ Export writes exactly what sylva-cli tree writes for the same species (OBJ + MTL
    /// and GLB), and fails with a message on an unwritable path or an unknown extension.
    void exportWritesWhatTheCliWrites() {
        exportEqualsCli(*mWindow, QStringLiteral("tree"), PresetLibrary::defaultPreset(),
                        {QStringLiteral("obj"), QStringLiteral("glb")});
        QVERIFY(!mWindow->exportTo(QStringLiteral("/proc/no-such-dir/tree.obj")));
        QVERIFY(!mWindow->lastError().isEmpty());
        QVERIFY(!mWindow->exportTo(QDir::temp().filePath(QStringLiteral("tree.xyz"))));
        QVERIFY2(mWindow->lastError().contains(QStringLiteral(".xyz")),
                 qPrintable(mWindow->lastError()));
        QVERIFY(!QFileInfo::exists(QDir::temp().filePath(QStringLiteral("tree.xyz"))));
    }

    /// Issue #42: File ▸ Export of a project is the export sylva-cli forest makes (one use case,
    /// doc::exportProject): for a project with a wind, the OBJ (with its wind table), the GLB
    /// with its rig and clip, and the USD (which the editor did not offer) are the CLI's bytes,
    /// the project's wind being the default of both; on a worker with a progress dialog.
    void projectExportWritesWhatTheCliWrites() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QFile small(QStringLiteral(SYLVA_TEST_DATA_DIR "/projects/small.sylva"));
        QVERIFY(small.open(QIODevice::ReadOnly));
        QJsonObject project = QJsonDocument::fromJson(small.readAll()).object();
        const QDir base(QStringLiteral(SYLVA_TEST_DATA_DIR "/projects"));
        for (const QString& key : {QStringLiteral("species"), QStringLiteral("obstacles")}) {
            QJsonArray list = project.value(key).toArray();
            for (qsizetype i = 0; i < list.size(); ++i) {
                QJsonObject o = list[i].toObject();
                o[QStringLiteral("file")] =
                    QFileInfo(base.filePath(o.value(QStringLiteral("file")).toString()))
                        .canonicalFilePath();
                list[i] = o;
            }
            project[key] = list;
        }
        project[QStringLiteral("wind")] =
            QJsonObject{{QStringLiteral("direction"), QJsonArray{0.6, 0, 0.8}},
                        {QStringLiteral("strength"), 1.3},
                        {QStringLiteral("gustiness"), 0.7},
                        {QStringLiteral("frequency"), 0.9}};
        const QString path = dir.filePath(QStringLiteral("windy.sylva"));
        QVERIFY(writeFile(path, QJsonDocument(project).toJson()));
        QSignalSpy finished(mWindow.get(), &MainWindow::generationFinished);
        mWindow->openSpecies(path);
        QVERIFY(finished.wait(kGenerationTimeoutMs));
        QVERIFY2(finished.first().first().toBool(), qPrintable(mWindow->lastError()));
        exportEqualsCli(*mWindow, QStringLiteral("forest"), path,
                        {QStringLiteral("obj"), QStringLiteral("glb"), QStringLiteral("usda")});
        mWindow->openDefaultPreset();
        QVERIFY(finished.wait(kGenerationTimeoutMs));
    }

    /// File ▸ Reload automatically: editing the species' grammar file on disk regenerates the
    /// tree, whether the editor writes in place or writes a new file and renames it over the old
    /// one; a broken or missing grammar reports its error and fixing or creating it reloads
    /// again; off, nothing happens.
    void editsOnDiskReloadTheTree() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString grammar = dir.filePath(QStringLiteral("bush.lsys"));
        const QString species = dir.filePath(QStringLiteral("bush.json"));
        QVERIFY(writeFile(grammar, bushGrammar(2)));
        QVERIFY(writeFile(species, R"({"format": "sylva-species", "format_version": 1,
            "name": "Watched bush", "graph": {"nodes": [
              {"id": "grow", "type": "lsystem", "params": {"grammar_file": "bush.lsys"}},
              {"id": "mesh", "type": "tube_mesh", "inputs": ["grow"], "params": {}}],
            "output": "mesh"}})"));
        QVERIFY(mWindow->autoReload());
        QSignalSpy finished(mWindow.get(), &MainWindow::generationFinished);
        auto segments = [&] {
            return mWindow->statsPanel()->value(QStringLiteral("statSegments")).toInt();
        };
        auto nextGeneration = [&](bool wantOk) {
            finished.clear();
            if (!finished.wait(10000)) return false;
            return finished.first().first().toBool() == wantOk;
        };
        mWindow->openSpecies(species);
        QVERIFY(nextGeneration(true));
        QCOMPARE(segments(), 25);
        QVERIFY(mWindow->watchedFiles().contains(QFileInfo(grammar).absoluteFilePath()));
        QVERIFY(mWindow->watchedFiles().contains(QFileInfo(species).absoluteFilePath()));

        // Saved in place.
        QVERIFY(writeFile(grammar, bushGrammar(3)));
        QVERIFY(nextGeneration(true));
        QCOMPARE(segments(), 125);
        // Saved by rename (the watch on the old file goes with it).
        const QString temporary = grammar + QStringLiteral(".tmp");
        QVERIFY(writeFile(temporary, bushGrammar(1)));
        QVERIFY(std::rename(temporary.toLocal8Bit().constData(),
                            grammar.toLocal8Bit().constData()) == 0);
        QVERIFY(nextGeneration(true));
        QCOMPARE(segments(), 5);
        // A broken grammar: the error, the tree kept; fixed: reloaded.
        QVERIFY(writeFile(grammar, "generations: 2\naxiom: F\nF -> F[+F\n"));
        QVERIFY(nextGeneration(false));
        QVERIFY2(mWindow->lastError().contains(QStringLiteral("bush.lsys")),
                 qPrintable(mWindow->lastError()));
        QCOMPARE(segments(), 5);
        QVERIFY(writeFile(grammar, bushGrammar(2)));
        QVERIFY(nextGeneration(true));
        QCOMPARE(segments(), 25);
        // A grammar that is missing, then created (only the folder's watch sees it appear).
        QVERIFY(QFile::remove(grammar));
        QVERIFY(nextGeneration(false));
        QVERIFY(writeFile(grammar, bushGrammar(1)));
        QVERIFY(nextGeneration(true));
        QCOMPARE(segments(), 5);
        // Off: a change is ignored.
        mWindow->setAutoReload(false);
        finished.clear();
        QVERIFY(writeFile(grammar, bushGrammar(3)));
        QVERIFY(!finished.wait(1500));
        mWindow->setAutoReload(true);

        QVERIFY(mWindow->openDefaultPreset());
        QVERIFY(nextGeneration(true));
    }

    void germanTranslationLoads() {
        QTranslator translator;
        QVERIFY(translator.load(QStringLiteral(":/i18n/sylva_de.qm")));
        QVERIFY(QApplication::installTranslator(&translator));
        MainWindow german;
        QStringList titles;
        for (QAction* action : german.menuBar()->actions())
            titles << action->text();
        QApplication::removeTranslator(&translator);
        QCOMPARE(titles.value(0), QStringLiteral("&Datei"));
        QCOMPARE(titles.value(1), QStringLiteral("&Bearbeiten"));
        QCOMPARE(titles.value(2), QStringLiteral("&Szene"));
        QCOMPARE(titles.value(3), QStringLiteral("&Vorlagen"));
        QCOMPARE(titles.value(4), QStringLiteral("&Ansicht"));
        QCOMPARE(titles.value(5), QStringLiteral("&Hilfe"));
    }

    /// The bundled demo project (what ./run.sh opens): its whole forest with the wall and the
    /// boulder, built as sylva-cli forest builds it; the dock counts the trees; colouring by node
    /// attributes is off (a forest has no one skeleton). Then the default preset again.
    void demoProjectShowsTheForestAndObstacles() {
        const QString project =
            QDir(PresetLibrary::directory()).filePath("../resources/demo/alder-reference.sylva");
        QVERIFY2(QFileInfo::exists(project), qPrintable(project));
        QSignalSpy finished(mWindow.get(), &MainWindow::generationFinished);
        mWindow->openSpecies(project);
        QVERIFY(finished.wait(kGenerationTimeoutMs));
        QVERIFY2(finished.first().first().toBool(), qPrintable(mWindow->lastError()));
        QCOMPARE(mWindow->statsPanel()->value(QStringLiteral("statTrees")), QStringLiteral("42"));
        // Issue #40: a forest's segments and leaves are counted (they showed "–"): the sums of
        // its trees' skeletons.
        {
            qlonglong segments = 0, leaves = 0;
            for (const DrawnTree& t : mWindow->lastResult().trees) {
                QVERIFY(t.lod.skeleton);
                segments += qlonglong(t.lod.skeleton->segmentCount());
                leaves += qlonglong(t.lod.skeleton->leaves.size());
            }
            QVERIFY(segments > 0);
            QCOMPARE(mWindow->statsPanel()->value(QStringLiteral("statSegments")).toLongLong(),
                     segments);
            QCOMPARE(mWindow->statsPanel()->value(QStringLiteral("statLeaves")).toLongLong(),
                     leaves);
        }
        // The scene's CO2 in tonnes (57.4 t for the demo, as sylva-cli stats sums it).
        QCOMPARE(mWindow->statsPanel()->value(QStringLiteral("statCo2")),
                 QStringLiteral("%1 t").arg(mWindow->lastResult().stats.at("co2_kg") / 1000.0, 0,
                                            'f', 1));
        QVERIFY(mWindow->lastResult().stats.at("co2_kg") > 10000.0);
        QVERIFY2(
            mWindow->windowTitle().contains(QStringLiteral("alder-reference.sylva (42 trees)")),
            qPrintable(mWindow->windowTitle()));
        // Each tree drawn on its own (its identity kept); the obstacles in the static mesh.
        QCOMPARE(mWindow->viewport()->trees().size(), std::size_t(42));
        QCOMPARE(mWindow->viewport()->trees().front().id, 1u); // the hand-placed tree
        QCOMPARE(mWindow->viewport()->trees().back().id, 0u);  // a domain's
        const sylva::mesh::Mesh& m = *mWindow->viewport()->mesh();
        QStringList materials;
        for (const sylva::mesh::Submesh& s : m.submeshes)
            materials << QString::fromStdString(s.material);
        QCOMPARE(materials.join(QLatin1Char(',')), QStringLiteral("obstacle"));
        QMenu* colours = mWindow->findChild<QMenu*>(QStringLiteral("colorMenu"));
        QVERIFY(colours);
        for (QAction* action : colours->actions())
            QCOMPARE(action->isEnabled(), action == colours->actions().first());

        // The view starts at the project's camera (its LOD reference); F frames the forest.
        Viewport* viewport = mWindow->viewport();
        QVERIFY(glm::length(viewport->camera().eye() - glm::vec3(0, 25, 70)) < 1e-3f);
        QVERIFY(glm::length(viewport->camera().target() - glm::vec3(0, 5, 0)) < 1e-3f);
        viewport->setGridVisible(false);
        viewport->frameScene();
        QVERIFY(glm::length(viewport->camera().eye() - glm::vec3(0, 25, 70)) > 1.0f);
        // The three pictures compared are final, sharp frames: the view just moved (a software
        // renderer draws moving frames with the trees' motion levels at reduced resolution) and
        // the trees' coarser levels and impostors are made in the background; a tree drawn at
        // one level in one picture and another in the next showed its leaves as "obstacle".
        QTRY_VERIFY_WITH_TIMEOUT(viewport->lodPending() == 0, kGenerationTimeoutMs);
        const QImage image = viewport->grabSharp().convertToFormat(QImage::Format_RGB32);
        QVERIFY(image.save(outputPath(QStringLiteral("ui_demo_project.png"))));
        // The same view without the obstacles, and empty: where only the sky was behind them,
        // the pixels that the obstacles change are the wall and the boulder in grey.
        const std::shared_ptr<const sylva::mesh::Mesh> full = viewport->mesh();
        const std::vector<ViewTree> allTrees = viewport->trees();
        viewport->setGridVisible(false);
        viewport->setMesh(std::make_shared<sylva::mesh::Mesh>(), false);
        QTRY_VERIFY_WITH_TIMEOUT(viewport->lodPending() == 0, kGenerationTimeoutMs);
        const QImage trees = viewport->grabSharp().convertToFormat(QImage::Format_RGB32);
        viewport->setTrees({});
        const QImage empty = viewport->grabSharp().convertToFormat(QImage::Format_RGB32);
        viewport->setTrees(allTrees);
        viewport->setMesh(full, false);
        viewport->setGridVisible(true);
        qint64 changed = 0, grey = 0, tree = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QRgb c = image.pixel(x, y);
                tree += isTree(c);
                // Only where nothing but the sky was without the obstacles (no leaf in front).
                if (c == trees.pixel(x, y) || trees.pixel(x, y) != empty.pixel(x, y)) continue;
                ++changed;
                // Grey, tinted a little by the sky and ground ambient.
                const int hi = std::max({qRed(c), qGreen(c), qBlue(c)});
                const int lo = std::min({qRed(c), qGreen(c), qBlue(c)});
                grey += hi - lo < 40 && !isTree(c);
            }
        qInfo("demo project: %lld sky pixels covered by the obstacles, %lld of them grey; %lld "
              "tree pixels",
              changed, grey, tree);
        QVERIFY2(changed > 500, "the wall and the boulder are not drawn");
        QVERIFY2(grey > changed * 9 / 10, "the obstacles are not grey");
        QVERIFY2(tree > 2000, "the trees are not drawn");

        // File ▸ Export of the forest: the bytes sylva-cli forest writes for the project.
        exportEqualsCli(*mWindow, QStringLiteral("forest"), project, {QStringLiteral("obj")});

        QSignalSpy again(mWindow.get(), &MainWindow::generationFinished);
        QVERIFY(mWindow->openDefaultPreset());
        QVERIFY(again.wait(kGenerationTimeoutMs));
        QVERIFY(again.first().first().toBool());
        QCOMPARE(mWindow->statsPanel()->value(QStringLiteral("statTrees")), QStringLiteral("1"));
    }

    /// View ▸ Colour by: an L-system tree offers only branch order; a self-organizing tree
    /// shows its light per internode on the ramp (dark blue → yellow), and Material brings the
    /// bark and leaf colours back. Runs last: it changes the open species.
    void colourByNodeAttributes() {
        QMenu* menu = mWindow->findChild<QMenu*>(QStringLiteral("colorMenu"));
        QVERIFY(menu);
        const QList<QAction*> actions = menu->actions();
        QCOMPARE(actions.size(), 5);
        QVERIFY(!actions[1]->isEnabled()); // light: the ternary tree is an L-system
        QVERIFY(!actions[2]->isEnabled());
        QVERIFY(!actions[3]->isEnabled());
        QVERIFY(actions[4]->isEnabled()); // branch order
        mWindow->setColorBy(ColorBy::BranchOrder);
        QVERIFY(mWindow->viewport()->usesVertexColors());
        QVERIFY(actions[4]->isChecked());

        QSignalSpy finished(mWindow.get(), &MainWindow::generationFinished);
        mWindow->openSpecies(QDir(PresetLibrary::directory()).filePath("so-broadleaf.json"));
        QVERIFY(finished.wait(kGenerationTimeoutMs));
        QVERIFY2(finished.first().first().toBool(), qPrintable(mWindow->lastError()));
        QVERIFY(actions[1]->isEnabled() && actions[2]->isEnabled() && actions[3]->isEnabled());
        QVERIFY(mWindow->viewport()->usesVertexColors()); // the mode stays across trees
        mWindow->setColorBy(ColorBy::Light);
        QVERIFY(mWindow->viewport()->usesVertexColors());
        QVERIFY(mWindow->statusBar()->currentMessage().contains(QStringLiteral("Light")));
        Viewport* viewport = mWindow->viewport();
        viewport->frameScene();
        const QImage light = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        QVERIFY(light.save(outputPath(QStringLiteral("ui_colour_by_light.png"))));
        auto isRed = [](QRgb c) {
            return qRed(c) > 2 * qGreen(c) + 40 && qRed(c) > 2 * qBlue(c) + 40;
        };
        qint64 blue = 0, yellow = 0, material = 0, red = 0;
        for (int y = 0; y < light.height(); ++y)
            for (int x = 0; x < light.width(); ++x) {
                const QRgb c = light.pixel(x, y);
                const int r = qRed(c), g = qGreen(c), b = qBlue(c);
                blue += b > r + 25 && b > g && b < 170; // the ramp's dark end, not the sky
                yellow += r > b + 60 && g > b + 60;
                material += isBark(c);
                red += isRed(c);
            }
        qInfo("colour by light: %lld dark blue, %lld yellow, %lld red, %lld bark pixels", blue,
              yellow, red, material);
        QVERIFY2(blue > 200, "no shaded (low light) branches on the ramp's dark end");
        QVERIFY2(yellow > 200, "no lit twigs on the ramp's bright end");
        // The branches the next cycle would shed are red (the ramp has no red; the grid's red
        // axis is in both pictures), and the legend says how many and below which threshold.
        const QString legend = mWindow->statusBar()->currentMessage();
        QVERIFY2(legend.contains(QStringLiteral("shed at the next cycle")), qPrintable(legend));
        mWindow->setColorBy(ColorBy::Age);
        const QImage age = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        qint64 redOutsideLight = 0;
        for (int y = 0; y < age.height(); ++y)
            for (int x = 0; x < age.width(); ++x)
                redOutsideLight += isRed(age.pixel(x, y));
        qInfo("red pixels: %lld coloured by light, %lld by age", red, redOutsideLight);
        QVERIFY2(red > redOutsideLight + 300, "no starved branches drawn in red");

        mWindow->setColorBy(ColorBy::Material);
        QVERIFY(!viewport->usesVertexColors());
        const QImage plain = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        qint64 tree = 0;
        for (int y = 0; y < plain.height(); ++y)
            for (int x = 0; x < plain.width(); ++x)
                tree += isTree(plain.pixel(x, y));
        QVERIFY(tree > qint64(plain.width()) * plain.height() / 100);
    }

private:
    std::unique_ptr<MainWindow> mWindow;
};

int main(int argc, char* argv[]) {
    Viewport::installDefaultSurfaceFormat();
    QApplication app(argc, argv);
    TestMainWindow test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_mainwindow.moc"
