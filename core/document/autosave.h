#pragma once

#include <optional>

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QTimer>

namespace sylva::doc {

class Document;

/// Keeps a recovery copy of the open document: every `interval` (2 minutes by default) and a
/// few seconds after the last edit, while the document has unsaved edits, the project is
/// written atomically to `<folder>/autosave.sylva` with a small `autosave.json` beside it (the
/// document's own file and folder, so relative paths still resolve). Never over the user's
/// file. A clean document (saved, or edits undone to the saved state) removes the copy. After
/// a crash the next start finds it with pending() and puts it back with restore().
class Autosave : public QObject {
    Q_OBJECT

public:
    /// The recovery folder beside the user's settings
    /// (QStandardPaths::AppConfigLocation/recovery).
    static QString defaultFolder();

    Autosave(Document& document, const QString& folder = defaultFolder(),
             QObject* parent = nullptr);

    /// Time between autosaves while edits are pending, milliseconds (>= 1000).
    void setInterval(int ms);
    int interval() const { return mPeriodic.interval(); }
    /// Quiet time after an edit before it is saved, milliseconds (>= 0).
    void setIdleDelay(int ms) { mIdle.setInterval(ms); }

    QString folder() const { return mFolder; }
    QString recoveryFile() const;

    /// A recovery copy left by an earlier run.
    struct Recovery {
        QString documentPath; ///< the file the edits belong to; empty for an untitled document
        QString baseDir;      ///< the folder its relative paths resolve against
        QDateTime saved;
    };
    std::optional<Recovery> pending() const;
    /// Loads the recovery copy into the document (modified, with its own file as path).
    /// \throw InvalidInput / IoError when the copy is unreadable (the document is untouched).
    void restore();
    /// Removes the recovery copy.
    void discard();
    /// Writes the copy now if the document has unsaved edits; false when there was nothing to
    /// save or writing failed (lastError()).
    bool saveNow();
    QString lastError() const { return mError; }

Q_SIGNALS:
    void saved(const QString& file);

private:
    void onEdit();

    Document& mDocument;
    QString mFolder;
    QTimer mPeriodic, mIdle;
    QString mError;
    bool mWrote = false; ///< this run wrote the copy (an earlier run's copy is the user's call)
};

} // namespace sylva::doc
