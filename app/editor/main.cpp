// sylva: the editor. `sylva [species.json|project.sylva]` opens the main window on a species
// (default: the ternary tree preset) or a project's forest; `sylva --screenshot out.png [--size
// WxH] [species.json]` renders the viewport to a PNG and exits (needs an X server; use xvfb-run on
// a headless machine);
// `--color-by light|vigour|age|order` colours the tree by a node attribute (View ▸ Colour by);
// `sylva --script file.py [project]` runs a Python script in the window and exits with its
// status; `--restore` / `--discard-autosave` answer the crash-recovery question without asking.

#include <cstdio>
#include <memory>
#include <utility>

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QLocale>
#include <QRegularExpression>
#include <QSettings>
#include <QTimer>
#include <QTranslator>

#include "document/autosave.h"
#include "engine/util/memorypolicy.h"
#include "ui/mainwindow.h"
#include "ui/scripting/pythonhost.h"
#include "ui/viewport/viewport.h"

namespace {

void installTranslators(QCoreApplication& app) {
    // View ▸ Language overrides the system locale.
    const QString chosen = QSettings().value(QStringLiteral("language")).toString();
    const QLocale locale = chosen.isEmpty() ? QLocale() : QLocale(chosen);
    // Both translators are parented to the application, which outlives every window.
    auto* qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    auto* sylva = new QTranslator(&app);
    if (sylva->load(locale, QStringLiteral("sylva"), QStringLiteral("_"), QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(sylva);
}

bool parseSize(const QString& text, QSize& size) {
    static const QRegularExpression pattern(QStringLiteral("^(\\d{2,5})[xX](\\d{2,5})$"));
    const QRegularExpressionMatch match = pattern.match(text);
    if (!match.hasMatch()) return false;
    size = QSize(match.captured(1).toInt(), match.captured(2).toInt());
    return size.width() >= 16 && size.height() >= 16 && size.width() <= 8192 &&
           size.height() <= 8192;
}

// The View ▸ Colour by mode named on the command line; false for an unknown name.
bool parseColorBy(const QString& text, sylva::ui::ColorBy& mode) {
    using sylva::ui::ColorBy;
    static const std::pair<const char*, ColorBy> kNames[] = {{"material", ColorBy::Material},
                                                             {"light", ColorBy::Light},
                                                             {"vigour", ColorBy::Vigour},
                                                             {"age", ColorBy::Age},
                                                             {"order", ColorBy::BranchOrder}};
    for (const auto& [name, value] : kNames)
        if (text == QLatin1String(name)) {
            mode = value;
            return true;
        }
    return false;
}

// Lets the window be shown and laid out before a script looks at it.
void waitUntilShown(QWidget& window) {
    QElapsedTimer clock;
    clock.start();
    while (!window.isVisible() && clock.elapsed() < 5000)
        QApplication::processEvents(QEventLoop::AllEvents, 50);
    QApplication::processEvents();
}

void fail(const QString& message) {
    std::fprintf(stderr, "sylva: %s\n", message.toLocal8Bit().constData());
}

/// The name, organisation (settings) and version of the running application.
void nameApplication() {
    QCoreApplication::setApplicationName(QStringLiteral("Sylva"));
    QCoreApplication::setOrganizationName(QStringLiteral("Sylva"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SYLVA_VERSION));
}

/// The editor's command line; made once the application exists (its texts are translated).
struct EditorOptions {
    explicit EditorOptions(QCommandLineParser& parser) {
        parser.setApplicationDescription(
            QCoreApplication::translate("main", "Sylva, the procedural tree editor."));
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addPositionalArgument(
            QStringLiteral("species"),
            QCoreApplication::translate(
                "main", "Species or project (.sylva) to open (default: the ternary tree)."),
            QStringLiteral("[species.json|project.sylva]"));
        for (const QCommandLineOption* o :
             {&script, &restore, &discard, &screenshot, &size, &colorBy})
            parser.addOption(*o);
    }
    const QCommandLineOption screenshot{
        QStringLiteral("screenshot"),
        QCoreApplication::translate("main", "Render the viewport to <file> (PNG) and exit."),
        QStringLiteral("file")};
    const QCommandLineOption size{
        QStringLiteral("size"),
        QCoreApplication::translate("main", "Viewport size in pixels, e.g. 1024x768."),
        QStringLiteral("WxH")};
    const QCommandLineOption colorBy{
        QStringLiteral("color-by"),
        QCoreApplication::translate(
            "main", "Colour the tree by <mode>: material, light, vigour, age or order."),
        QStringLiteral("mode")};
    const QCommandLineOption script{
        QStringLiteral("script"),
        QCoreApplication::translate("main",
                                    "Run the Python script <file> in the editor (after opening "
                                    "the project, if one is given) and exit with its status."),
        QStringLiteral("file")};
    const QCommandLineOption restore{
        QStringLiteral("restore"),
        QCoreApplication::translate("main",
                                    "Restore edits autosaved before a crash without asking.")};
    const QCommandLineOption discard{
        QStringLiteral("discard-autosave"),
        QCoreApplication::translate("main",
                                    "Discard edits autosaved before a crash without asking.")};
};

/// Whether the command line only asks for text (--help, --version): then it is answered
/// without a window system, so that `sylva --help` works on a machine with no display.
/// (--help-all lists the window system's options too, so it goes through QApplication.)
bool answeredWithoutDisplay(int argc, char* argv[]) {
    bool textOnly = false;
    for (int i = 1; i < argc; ++i) {
        const QByteArray a(argv[i]);
        if (a == "--") break;
        if (a == "-h" || a == "--help" || a == "-?" || a == "-v" || a == "--version")
            textOnly = true;
    }
    if (!textOnly) return false;
    QCoreApplication app(argc, argv);
    nameApplication();
    installTranslators(app);
    QCommandLineParser parser;
    const EditorOptions options(parser);
    parser.process(app); // prints the help or the version (or the error) and exits
    return true;
}

} // namespace

int main(int argc, char* argv[]) {
    if (answeredWithoutDisplay(argc, argv)) return 0;
    sylva::keepFreedMemory(); // re-generation on every edit reuses the previous tree's pages
    sylva::ui::Viewport::installDefaultSurfaceFormat();
    QApplication app(argc, argv);
    nameApplication();
    sylva::ui::Viewport::applySamplesPreference();
    installTranslators(app);

    QCommandLineParser parser;
    const EditorOptions options(parser);
    parser.process(app);

    const QStringList positional = parser.positionalArguments();
    if (positional.size() > 1) {
        fail(QApplication::translate("main", "expected at most one species or project file"));
        return 2;
    }
    const bool screenshotMode = parser.isSet(options.screenshot);
    QSize size = screenshotMode ? QSize(960, 720) : QSize();
    if (parser.isSet(options.size) && !parseSize(parser.value(options.size), size)) {
        fail(QApplication::translate("main", "--size expects WxH between 16 and 8192, got '%1'")
                 .arg(parser.value(options.size)));
        return 2;
    }

    sylva::ui::ColorBy colorBy = sylva::ui::ColorBy::Material;
    if (parser.isSet(options.colorBy) && !parseColorBy(parser.value(options.colorBy), colorBy)) {
        fail(QApplication::translate(
                 "main", "--color-by expects material, light, vigour, age or order, got '%1'")
                 .arg(parser.value(options.colorBy)));
        return 2;
    }

    sylva::ui::MainWindow window;
    window.setColorBy(colorBy);
    if (size.isValid()) window.viewport()->setFixedSize(size);
    window.show();
    if (size.isValid() && !screenshotMode) {
        // Only the first layout uses the requested size; afterwards the user may resize.
        QTimer::singleShot(0, &window, [&window] {
            window.viewport()->setMinimumSize(160, 120);
            window.viewport()->setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
        });
    }

    const bool scriptMode = parser.isSet(options.script);
    // A crash left autosaved edits: restore them (asked, or as the options say) before
    // anything else is opened.
    bool restored = false;
    if (parser.isSet(options.discard))
        window.autosave().discard();
    else if (!screenshotMode && (parser.isSet(options.restore) || !scriptMode))
        restored = window.offerRecovery(parser.isSet(options.restore));

    if (!positional.isEmpty())
        window.openSpecies(QFileInfo(positional.first()).absoluteFilePath());
    else if (!restored && !scriptMode)
        window.openDefaultPreset();

    if (scriptMode) {
        const QString script = QFileInfo(parser.value(options.script)).absoluteFilePath();
        // Scripts decide for themselves: no dialog waits for a person.
        window.setAskHandler([](const QString&, bool canSave) {
            return canSave ? sylva::ui::MainWindow::Answer::Discard
                           : sylva::ui::MainWindow::Answer::Yes;
        });
        QTimer::singleShot(0, &window, [&window, script] {
            waitUntilShown(window);
            window.waitForGeneration();
            QApplication::exit(sylva::ui::PythonHost::runScript(script));
        });
    }

    if (screenshotMode) {
        // The same picture every time, also with View ▸ Wind left on: the wind clock stands
        // at 0 s (the trees bent by the mean wind, as a clip's first frame).
        window.setWindTime(0.0);
        const QString output = QFileInfo(parser.value(options.screenshot)).absoluteFilePath();
        QObject::connect(&window, &sylva::ui::MainWindow::generationFinished, &app,
                         [&window, output](bool ok) {
                             if (!ok) {
                                 fail(window.lastError());
                                 QApplication::exit(1);
                                 return;
                             }
                             // Give the window a few event loop turns to be exposed.
                             auto* timer = new QTimer(&window);
                             auto clock = std::make_shared<QElapsedTimer>();
                             clock->start();
                             QObject::connect(timer, &QTimer::timeout, &window, [=, &window] {
                                 if (!window.viewport()->grabFramebuffer().isNull() ||
                                     clock->elapsed() > 20000) {
                                     timer->stop();
                                     const bool saved = window.saveScreenshot(output);
                                     if (!saved)
                                         fail(window.lastError());
                                     else
                                         std::printf("%s\n", output.toLocal8Bit().constData());
                                     QApplication::exit(saved ? 0 : 1);
                                 }
                             });
                             timer->start(50);
                         });
    }
    const int status = QApplication::exec();
    // A normal end: the autosave copy is only for crashes.
    window.autosave().discard();
    return status;
}
