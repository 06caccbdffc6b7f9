#include "ui/document/sourcewatcher.h"

#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QTimer>

namespace sylva::ui {

namespace {
QDateTime modified(const QFileInfo& info) {
    return info.exists() ? info.lastModified() : QDateTime();
}
} // namespace

QList<QDateTime> modificationTimes(const QStringList& files) {
    QList<QDateTime> stamps;
    for (const QString& f : files)
        stamps << modified(QFileInfo(f));
    return stamps;
}

void listProjectFileLast(QStringList& sources, QList<QDateTime>& stamps, const QString& projectFile,
                         const QDateTime& stamp) {
    if (const qsizetype i = sources.indexOf(projectFile); i >= 0) { // listed once
        sources.removeAt(i);
        if (i < stamps.size()) stamps.removeAt(i);
    }
    sources << projectFile;
    stamps << stamp;
}

SourceWatcher::SourceWatcher(QObject* parent) : QObject(parent) {
    // A change (or a save by rename, which shows as a change of the folder) starts a short
    // timer, so that an editor's several writes make one report.
    mWatcher = new QFileSystemWatcher(this);
    mSettle = new QTimer(this);
    mSettle->setSingleShot(true);
    mSettle->setInterval(250);
    connect(mWatcher, &QFileSystemWatcher::fileChanged, this, [this](const QString& path) {
        // A file replaced by a rename (a save) loses its watch when the old file is finally
        // deleted, which can come after the timer has already looked (the old file was still
        // open somewhere): watch the new one at once, or later edits in place go unseen.
        if (!mWatcher->files().contains(path) && QFileInfo::exists(path)) mWatcher->addPath(path);
        mSettle->start();
    });
    connect(mWatcher, &QFileSystemWatcher::directoryChanged, mSettle, qOverload<>(&QTimer::start));
    connect(mSettle, &QTimer::timeout, this, &SourceWatcher::onTouched);
}

void SourceWatcher::setSettleMs(int ms) {
    mSettle->setInterval(ms);
}

void SourceWatcher::watch(const QStringList& sources, const QList<QDateTime>& stamps) {
    if (!mWatcher->files().isEmpty()) mWatcher->removePaths(mWatcher->files());
    if (!mWatcher->directories().isEmpty()) mWatcher->removePaths(mWatcher->directories());
    mSources = sources;
    mSources.removeDuplicates();
    mSources.removeAll(QString());
    mStamps.clear();
    QStringList folders;
    bool changedMeanwhile = false;
    for (qsizetype i = 0; i < mSources.size(); ++i) {
        const QFileInfo info(mSources[i]);
        const QDateTime now = modified(info);
        // The time the file had when it was read; a file changed since is reported at once.
        const qsizetype k = sources.indexOf(mSources[i]);
        const QDateTime read = k >= 0 && k < stamps.size() ? stamps[k] : now;
        mStamps[mSources[i]] = read;
        changedMeanwhile = changedMeanwhile || now != read;
        if (info.exists()) mWatcher->addPath(mSources[i]);
        if (!folders.contains(info.absolutePath())) folders << info.absolutePath();
    }
    for (const QString& folder : folders)
        if (QFileInfo(folder).isDir()) mWatcher->addPath(folder);
    if (changedMeanwhile) mSettle->start();
}

void SourceWatcher::onTouched() {
    if (!mEnabled) return;
    // A folder changes for other files too: report only when one of ours changed, appeared or
    // went (a save by rename replaces the file, and the watch on the old one is gone).
    QStringList changedFiles;
    for (const auto& [file, stamp] : mStamps) {
        const QFileInfo info(file);
        if (modified(info) != stamp) changedFiles << file;
        // A file that came back (saved by rename) is watched again, changed or not.
        if (info.exists() && !mWatcher->files().contains(file)) mWatcher->addPath(file);
    }
    if (changedFiles.isEmpty()) return;
    // Seen: the next change is compared with the files as they are now.
    for (auto& [file, stamp] : mStamps)
        stamp = modified(QFileInfo(file));
    Q_EMIT changed(changedFiles);
}

} // namespace sylva::ui
