// The window's small menus on their own: Open recent, Presets, Colour by, Language, Help.
#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

#include "document/presetlibrary.h"
#include "ui/document/presetsmenu.h"
#include "ui/helpmenu.h"
#include "ui/languagemenu.h"
#include "ui/recentfilesmenu.h"
#include "ui/viewport/colorbymenu.h"

using namespace sylva;
using namespace sylva::ui;

class TestMenus : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // the settings of a test, not the user's
        QCoreApplication::setOrganizationName(QStringLiteral("SylvaTests"));
        QCoreApplication::setApplicationName(QStringLiteral("test_menus"));
        QSettings().clear();
    }

    void recentFilesNewestFirstAndBounded() {
        RecentFilesMenu menu;
        QCOMPARE(menu.objectName(), QStringLiteral("recentMenu"));
        QCOMPARE(menu.actions().size(), 1); // "No recent files"
        QVERIFY(!menu.actions().front()->isEnabled());
        for (int i = 0; i < RecentFilesMenu::kMaxFiles + 2; ++i)
            RecentFilesMenu::add(QStringLiteral("/tmp/f%1.sylva").arg(i));
        RecentFilesMenu::add(QStringLiteral("/tmp/f5.sylva")); // again: moves to the top
        const QStringList files = RecentFilesMenu::files();
        QCOMPARE(files.size(), RecentFilesMenu::kMaxFiles);
        QCOMPARE(files.front(), QStringLiteral("/tmp/f5.sylva"));
        QCOMPARE(files.count(QStringLiteral("/tmp/f5.sylva")), 1);
        QVERIFY(!files.contains(QStringLiteral("/tmp/f0.sylva")));
        Q_EMIT menu.aboutToShow();
        QCOMPARE(menu.actions().size(), RecentFilesMenu::kMaxFiles);
        QSignalSpy open(&menu, &RecentFilesMenu::openRequested);
        menu.actions().front()->trigger();
        QCOMPARE(open.front().front().toString(), QStringLiteral("/tmp/f5.sylva"));
    }

    void presetsListTheFolderAndCheckThePreview() {
        const QList<doc::PresetInfo> presets =
            doc::PresetLibrary::list(doc::PresetLibrary::directory());
        QVERIFY(presets.size() > 1);
        QString previewed = presets[1].path;
        PresetsMenu menu([&previewed] { return previewed; });
        QCOMPARE(menu.objectName(), QStringLiteral("presetsMenu"));
        QCOMPARE(menu.actions().size(), presets.size());
        QVERIFY(menu.actions()[1]->isChecked());
        QVERIFY(!menu.actions()[0]->isChecked());
        previewed.clear(); // the document is shown: none checked when the menu opens again
        Q_EMIT menu.aboutToShow();
        for (QAction* a : menu.actions())
            QVERIFY(!a->isChecked());
        QSignalSpy open(&menu, &PresetsMenu::openRequested);
        menu.actions()[0]->trigger();
        QCOMPARE(open.front().front().toString(), presets[0].path);
    }

    void colourByGreysOutWhatTheTreeLacks() {
        ColorByMenu menu(ColorBy::Age);
        QCOMPARE(menu.objectName(), QStringLiteral("colorMenu"));
        const QList<QAction*> actions = menu.actions();
        QCOMPARE(actions.size(), 5);
        QVERIFY(actions[3]->isChecked()); // Age
        menu.enableFor(nullptr, true);    // a forest: materials only
        for (QAction* a : actions)
            QCOMPARE(a->isEnabled(), a == actions.front());
        menu.enableFor(nullptr, false); // nothing shown yet: every mode
        for (QAction* a : actions)
            QVERIFY(a->isEnabled());
        QSignalSpy chosen(&menu, &ColorByMenu::chosen);
        actions[4]->trigger();
        QCOMPARE(chosen.front().front().value<ColorBy>(), ColorBy::BranchOrder);
        menu.setMode(ColorBy::Material);
        QVERIFY(actions[0]->isChecked());
        QVERIFY(!actions[4]->isChecked());
    }

    void languageChecksTheChosenOne() {
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("de"));
        QWidget window;
        LanguageMenu menu(&window);
        QCOMPARE(menu.objectName(), QStringLiteral("languageMenu"));
        QCOMPARE(menu.actions().size(), 4);
        QVERIFY(menu.actions()[2]->isChecked());
        QCOMPARE(menu.actions()[2]->text(), QStringLiteral("Deutsch"));
    }

    void helpFindsTheDocumentation() {
        QWidget window;
        HelpMenu menu(&window);
        QCOMPARE(menu.objectName(), QStringLiteral("helpMenu"));
        QCOMPARE(menu.actions().size(), 2);
        // Run from the source tree: docs/ beside presets/.
        QVERIFY(QFileInfo::exists(QDir(HelpMenu::documentationFolder()).filePath("editor.md")));
    }
};

QTEST_MAIN(TestMenus)
#include "test_menus.moc"
