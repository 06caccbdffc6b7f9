// PreferencesDialog: it shows the current choices and hands back the new ones.
#include <QComboBox>
#include <QLabel>
#include <QSpinBox>
#include <QTest>

#include "ui/preferencesdialog.h"
#include "ui/viewport/viewport.h"

using namespace sylva::ui;

class TestPreferencesDialog : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void showsTheCurrentChoices() {
        PreferencesDialog dialog(5 * 60 * 1000, QStringLiteral("/tmp/recovery"), 4);
        QCOMPARE(dialog.objectName(), QStringLiteral("preferencesDialog"));
        auto* minutes = dialog.findChild<QSpinBox*>(QStringLiteral("autosaveMinutes"));
        auto* samples = dialog.findChild<QComboBox*>(QStringLiteral("viewportSamples"));
        QVERIFY(minutes && samples);
        QCOMPARE(minutes->value(), 5);
        QCOMPARE(dialog.autosaveSeconds(), 300);
        QCOMPARE(dialog.samples(), 4);
        bool folderShown = false;
        for (QLabel* label : dialog.findChildren<QLabel*>())
            folderShown = folderShown || label->text() == QStringLiteral("/tmp/recovery");
        QVERIFY(folderShown);
    }

    void handsBackTheNewChoices() {
        PreferencesDialog dialog(30 * 1000, QString(), Viewport::kAutoSamples);
        auto* minutes = dialog.findChild<QSpinBox*>(QStringLiteral("autosaveMinutes"));
        auto* samples = dialog.findChild<QComboBox*>(QStringLiteral("viewportSamples"));
        QCOMPARE(minutes->value(), 1); // under a minute shows as one
        QCOMPARE(dialog.samples(), Viewport::kAutoSamples);
        minutes->setValue(12);
        samples->setCurrentIndex(samples->findData(0));
        QCOMPARE(dialog.autosaveSeconds(), 12 * 60);
        QCOMPARE(dialog.samples(), 0);
    }

    void anUnknownSampleCountShowsAutomatic() {
        PreferencesDialog dialog(60 * 1000, QString(), 3);
        QCOMPARE(dialog.samples(), Viewport::kAutoSamples);
    }
};

QTEST_MAIN(TestPreferencesDialog)
#include "test_preferencesdialog.moc"
