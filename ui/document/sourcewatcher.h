#pragma once

#include <map>

#include <QDateTime>
#include <QObject>
#include <QStringList>

class QFileSystemWatcher;
class QTimer;

namespace sylva::ui {

/// Watches the files a shown result was read from (a project, its species, grammars, meshes)
/// and reports which of them changed on disk, as Tiled's `FileSystemWatcher` does. An editor's
/// several writes of one save make one report (the changes settle for a short while first), and
/// a save by rename (the file replaced, which shows as a change of its folder) is seen too.
/// What to do about a change (reload, or ask first) is the window's policy, not this class's.
class SourceWatcher : public QObject {
    Q_OBJECT

public:
    explicit SourceWatcher(QObject* parent = nullptr);

    /// Watches \p sources instead of the files watched so far. \p stamps[i] is the modification
    /// time \p sources[i] had when it was read (none: the time it has now); a file changed since
    /// it was read is reported at once.
    void watch(const QStringList& sources, const QList<QDateTime>& stamps);
    /// The files watched (duplicates and empty names dropped).
    QStringList files() const { return mSources; }
    /// While disabled, changes are not looked at (and not marked seen): enabling again reports
    /// at the next change of any watched file what changed meanwhile.
    void setEnabled(bool on) { mEnabled = on; }
    bool isEnabled() const { return mEnabled; }
    /// How long changes settle before they are looked at, milliseconds (250 by default).
    void setSettleMs(int ms);

Q_SIGNALS:
    /// Files whose modification time differs from the one last seen (or that appeared or went);
    /// they count as seen from now on.
    void changed(const QStringList& files);

private:
    void onTouched();

    QFileSystemWatcher* mWatcher = nullptr;
    QTimer* mSettle = nullptr;
    QStringList mSources;
    std::map<QString, QDateTime> mStamps; ///< each file's time when read or last seen
    bool mEnabled = true;
};

/// Each of \p files' modification time now (invalid: missing).
QList<QDateTime> modificationTimes(const QStringList& files);

/// Lists the project file \p projectFile (absolute) once, last in \p sources, with \p stamp:
/// the time it had when it was opened or saved (or last seen changed), so that a change made
/// while a generation ran is still noticed. A generation lists the file too, stamped when it
/// started (it reads the document, not the file): that stamp would hide an edit made on disk
/// before it started (a flaky test under load found it), so it goes.
void listProjectFileLast(QStringList& sources, QList<QDateTime>& stamps, const QString& projectFile,
                         const QDateTime& stamp);

} // namespace sylva::ui
