#include "ui/helpmenu.h"

#include <QApplication>
#include <QDesktopServices>
#include <QDir>
#include <QMessageBox>
#include <QUrl>

#include "document/presetlibrary.h"

namespace sylva::ui {

HelpMenu::HelpMenu(QWidget* parent) : QMenu(tr("&Help"), parent) {
    setObjectName(QStringLiteral("helpMenu"));
    addAction(tr("&Documentation"), this, [] {
        QDesktopServices::openUrl(
            QUrl::fromLocalFile(QDir(documentationFolder()).filePath("editor.md")));
    });
    addAction(tr("&About Sylva"), this, [this] {
        QMessageBox::about(
            parentWidget(), tr("About Sylva"),
            tr("<h3>Sylva %1</h3><p>Procedural trees and forests for film and games: "
               "L-systems, space colonization and self-organizing trees, forests that react to "
               "the scene they stand in.</p><p>Scripting: Python (the Python Console, or "
               "<tt>sylva --script file.py</tt>).</p>")
                .arg(QApplication::applicationVersion()));
    });
}

QString HelpMenu::documentationFolder() {
    QDir docs(doc::PresetLibrary::directory());
    return docs.cdUp() && docs.cd(QStringLiteral("docs")) ? docs.absolutePath()
                                                          : QStringLiteral("/usr/share/doc/sylva");
}

} // namespace sylva::ui
