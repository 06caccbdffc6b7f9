// FileDialogs: the names they suggest and the extension they add when none was typed.
#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include "ui/filedialogs.h"

using namespace sylva::ui;

namespace {
// Answers the next file dialog as a user would: types \p name, picks \p filter, accepts.
void answerNextDialog(const QString& dir, const QString& name, const QString& filter = {}) {
    QTimer::singleShot(100, [=] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog) return answerNextDialog(dir, name, filter); // not shown yet
        dialog->setDirectory(dir);
        if (!filter.isEmpty()) dialog->selectNameFilter(filter);
        if (auto* edit = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit")))
            edit->setText(name);
        dialog->selectFile(name);
        static_cast<QDialog*>(dialog)->done(QDialog::Accepted); // the caller reads the files
    });
}
} // namespace

class TestFileDialogs : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QApplication::setAttribute(Qt::AA_DontUseNativeDialogs); }

    void addsTheFiltersExtensionWhenNoneWasTyped() {
        const QString obj = QStringLiteral("Wavefront OBJ (*.obj)");
        QCOMPARE(FileDialogs::withFilterExtension(QStringLiteral("/t/forest"), obj),
                 QStringLiteral("/t/forest.obj"));
        QCOMPARE(FileDialogs::withFilterExtension(QStringLiteral("/t/forest"),
                                                  QStringLiteral("glTF binary (*.glb)")),
                 QStringLiteral("/t/forest.glb"));
        QCOMPARE(FileDialogs::withFilterExtension(QStringLiteral("/t/forest.fbx"), obj),
                 QStringLiteral("/t/forest.fbx")); // typed: kept
    }

    void suggestsTheShownFilesName() {
        QCOMPARE(FileDialogs::suggestedName(QStringLiteral("/p/alder.species.json"),
                                            QStringLiteral("forest"), QStringLiteral(".obj")),
                 QStringLiteral("/p/alder.species.obj"));
        QCOMPARE(FileDialogs::suggestedName({}, QStringLiteral("sylva"), QStringLiteral(".png")),
                 QDir::home().filePath(QStringLiteral("sylva.png")));
        // Issue #40: Export opened in the working folder, Export LOD chain in the home folder;
        // both start where the project is.
        QCOMPARE(FileDialogs::startFolder(QStringLiteral("/p/forest.sylva")), QStringLiteral("/p"));
        QCOMPARE(FileDialogs::startFolder({}), QDir::homePath());
    }

    void dialogsAddTheirExtension() {
        QTemporaryDir dir;
        answerNextDialog(dir.path(), QStringLiteral("copy"));
        QCOMPARE(FileDialogs::saveProject(nullptr, {}), dir.filePath(QStringLiteral("copy.sylva")));
        answerNextDialog(dir.path(), QStringLiteral("trees"),
                         QStringLiteral("glTF binary (*.glb)"));
        QCOMPARE(FileDialogs::exportFile(nullptr, QStringLiteral("/p/alder.json")),
                 dir.filePath(QStringLiteral("trees.glb")));
    }
};

QTEST_MAIN(TestFileDialogs)
#include "test_filedialogs.moc"
