// The performance gate's viewport case (issue #41, ctest label `perf`; the harness, how a figure
// is made and compared: perfharness.h): the editor's window with the 1,000-tree benchmark
// forest (resources/demo/bench-1000.sylva), its levels of detail and impostors made, frames
// drawn from the project camera while the view orbits, as `forest_scale.py` measures them
// (docs/performance.md). Run under Xvfb (Mesa llvmpipe): the process CPU time of a frame
// includes the software renderer's threads, so the figure is the frame's whole cost.
//
//   perf_gate_viewport viewport-1000 [options of perfharness.h]
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include <QApplication>
#include <QElapsedTimer>
#include <QTest>

#include "document/document.h"
#include "engine/util/memorypolicy.h"
#include "perfharness.h"
#include "ui/mainwindow.h"
#include "ui/viewport/framemeter.h"
#include "ui/viewport/viewport.h"

using namespace sylva;

namespace {

// Runs the event loop until \p done or \p seconds have passed; whether done.
bool pumpUntil(double seconds, const std::function<bool()>& done) {
    QElapsedTimer clock;
    clock.start();
    while (!done() && clock.elapsed() < static_cast<qint64>(seconds * 1000.0))
        QApplication::processEvents(QEventLoop::AllEvents, 20);
    return done();
}

constexpr int kFrames = 20; ///< frames a repetition (forest_scale.py's window)

} // namespace

int main(int argc, char** argv) {
    keepFreedMemory();
    ui::Viewport::installDefaultSurfaceFormat();
    QApplication app(argc, argv);
    // Its own settings (never the editor's saved view settings, View > Wind among them), and
    // the editor's choice of samples: none on a software renderer.
    QCoreApplication::setOrganizationName(QStringLiteral("Sylva"));
    QCoreApplication::setApplicationName(QStringLiteral("SylvaPerfGate"));
    ui::Viewport::applySamplesPreference();
    ui::MainWindow window;
    std::map<std::string, perf::Case> cases;
    perf::Case c;
    c.what = "1,000-tree forest (resources/demo/bench-1000.sylva) in the editor's viewport from "
             "the project camera, orbiting 4 degrees a frame, 1400 x 900 window, llvmpipe";
    c.unit = "frame";
    c.reps = 5;
    c.prepare = [&window] {
        window.resize(1400, 900);
        window.show();
        if (!QTest::qWaitForWindowExposed(&window)) throw std::runtime_error("no window shown");
        const std::filesystem::path project =
            std::filesystem::path(SYLVA_SOURCE_DIR) / "resources/demo/bench-1000.sylva";
        if (!window.openProject(QString::fromStdString(project.string())))
            throw std::runtime_error("cannot open " + project.string());
        if (!pumpUntil(600.0, [&window] { return !window.isGenerating(); }))
            throw std::runtime_error("the forest did not generate in 10 minutes");
        ui::Viewport& view = *window.viewport();
        const doc::Project& p = window.document().project();
        view.camera().lookFrom(p.cameraPosition, p.cameraTarget);
        view.update();
        if (!pumpUntil(600.0, [&view] { return view.lodPending() == 0; }))
            throw std::runtime_error("the view's levels of detail were not made in 10 minutes");
        ui::FrameMeter(view).measure(3); // the first frames upload what they draw
    };
    c.run = [&window]() -> std::size_t {
        // Each repetition draws the same frames: from the project camera, orbiting.
        ui::Viewport& view = *window.viewport();
        const doc::Project& p = window.document().project();
        view.camera().lookFrom(p.cameraPosition, p.cameraTarget);
        const ui::FrameStats stats = ui::FrameMeter(view).measure(kFrames);
        perf::sink(stats.trianglesDrawn);
        return kFrames;
    };
    cases["viewport-1000"] = c;
    try {
        return perf::runGate(argc, argv, cases);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "perf_gate_viewport: %s\n", e.what());
        return 2;
    }
}
