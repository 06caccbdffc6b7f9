#include "ui/filedialogs.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>

#include "document/presetlibrary.h"
#include "engine/export/formats.h"

namespace sylva::ui {

QString FileDialogs::open(QWidget* parent, const QString& shown) {
    const QString dir =
        shown.isEmpty() ? doc::PresetLibrary::directory() : QFileInfo(shown).absolutePath();
    return QFileDialog::getOpenFileName(
        parent, tr("Open species or project"), dir,
        tr("Species, grammars and projects (*.json *.lsys *.txt *.sylva);;Projects (*.sylva);;"
           "All files (*)"));
}

QString FileDialogs::saveProject(QWidget* parent, const QString& current) {
    QString path = QFileDialog::getSaveFileName(
        parent, tr("Save project as"), current.isEmpty() ? QStringLiteral("forest.sylva") : current,
        tr("Sylva projects (*.sylva)"));
    if (!path.isEmpty() && QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".sylva");
    return path;
}

QString FileDialogs::exportFile(QWidget* parent, const QString& shown) {
    QString filter;
    const QString path = QFileDialog::getSaveFileName(
        parent, tr("Export"),
        suggestedName(shown, QStringLiteral("forest"),
                      QString::fromLatin1(exporter::formatTable().front().extension)),
        // The format table's rows (engine/export/formats.h): a new format appears here.
        QString::fromStdString(exporter::dialogFilter()), &filter);
    return path.isEmpty() ? path : withFilterExtension(path, filter);
}

QString FileDialogs::screenshot(QWidget* parent, const QString& shown) {
    return QFileDialog::getSaveFileName(
        parent, tr("Save screenshot"),
        suggestedName(shown, QStringLiteral("sylva"), QStringLiteral(".png")),
        tr("Images (*.png *.jpg *.bmp)"));
}

QString FileDialogs::withFilterExtension(const QString& path, const QString& filter) {
    if (!QFileInfo(path).suffix().isEmpty()) return path;
    const qsizetype star = filter.indexOf(QStringLiteral("*."));
    return path + filter.mid(star + 1, filter.indexOf(QLatin1Char(')'), star) - star - 1);
}

QString FileDialogs::startFolder(const QString& shown) {
    return shown.isEmpty() ? QDir::homePath() : QFileInfo(shown).absolutePath();
}

QString FileDialogs::suggestedName(const QString& shown, const QString& fallback,
                                   const QString& extension) {
    return QDir(startFolder(shown))
        .filePath(QFileInfo(shown.isEmpty() ? fallback : shown).completeBaseName() + extension);
}

} // namespace sylva::ui
