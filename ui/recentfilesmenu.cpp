#include "ui/recentfilesmenu.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace sylva::ui {

namespace {
const QString kKey = QStringLiteral("recentFiles");
}

RecentFilesMenu::RecentFilesMenu(QWidget* parent) : QMenu(tr("Open &recent"), parent) {
    setObjectName(QStringLiteral("recentMenu"));
    connect(this, &QMenu::aboutToShow, this, &RecentFilesMenu::populate);
    populate();
}

QStringList RecentFilesMenu::files() {
    return QSettings().value(kKey).toStringList();
}

void RecentFilesMenu::add(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(kKey).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    recent.removeAll(absolute);
    recent.prepend(absolute);
    while (recent.size() > kMaxFiles)
        recent.removeLast();
    settings.setValue(kKey, recent);
}

void RecentFilesMenu::populate() {
    clear();
    const QStringList recent = files();
    for (const QString& path : recent) {
        QAction* a = addAction(QDir::toNativeSeparators(path));
        connect(a, &QAction::triggered, this, [this, path] { Q_EMIT openRequested(path); });
    }
    if (recent.isEmpty()) addAction(tr("No recent files"))->setEnabled(false);
}

} // namespace sylva::ui
