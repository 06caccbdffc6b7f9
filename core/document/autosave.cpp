#include "document/autosave.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>

#include "document/document.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

namespace sylva::doc {

namespace {
constexpr auto kMeta = "autosave.json";
constexpr auto kCopy = "autosave.sylva";

void write(const QString& path, const QByteArray& bytes) {
    writeFileAtomically(
        path.toStdString(),
        std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
}
} // namespace

QString Autosave::defaultFolder() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppConfigLocation))
        .filePath(QStringLiteral("recovery"));
}

Autosave::Autosave(Document& document, const QString& folder, QObject* parent)
    : QObject(parent), mDocument(document), mFolder(folder) {
    mPeriodic.setInterval(2 * 60 * 1000);
    mIdle.setInterval(3000);
    mIdle.setSingleShot(true);
    connect(&mPeriodic, &QTimer::timeout, this, &Autosave::saveNow);
    connect(&mIdle, &QTimer::timeout, this, &Autosave::saveNow);
    connect(&document, &Document::changed, this, &Autosave::onEdit);
    connect(&document, &Document::titleChanged, this, [this] {
        // Saved, or undone back to the saved state: nothing to recover any more.
        // A copy left by an earlier run stays until the user decides (restore or discard).
        if (!mDocument.isModified()) {
            mIdle.stop();
            mPeriodic.stop();
            if (mWrote) discard();
        }
    });
    mPeriodic.start();
}

void Autosave::setInterval(int ms) {
    mPeriodic.setInterval(std::max(ms, 1000));
}

QString Autosave::recoveryFile() const {
    return QDir(mFolder).filePath(QString::fromLatin1(kCopy));
}

void Autosave::onEdit() {
    // Not gated on isModified(): an edit's change signal comes from its command's redo(),
    // before the undo stack moves its index, so the first edit after opening or saving still
    // reads as unmodified here. saveNow() asks again when the timer fires.
    mIdle.start();
    if (!mPeriodic.isActive()) mPeriodic.start();
}

bool Autosave::saveNow() {
    if (!mDocument.isModified()) return false;
    try {
        if (!QDir().mkpath(mFolder))
            throw IoError("cannot create the recovery folder " + mFolder.toStdString());
        QJsonObject meta;
        meta[QStringLiteral("document")] = mDocument.path();
        meta[QStringLiteral("base_dir")] = mDocument.project().baseDir;
        meta[QStringLiteral("saved")] = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
        // The copy first: a crash between the two leaves a copy whose meta is the older one,
        // which still names the same document.
        write(recoveryFile(), mDocument.serialized());
        write(QDir(mFolder).filePath(QString::fromLatin1(kMeta)), QJsonDocument(meta).toJson());
        mError.clear();
        mWrote = true;
        Q_EMIT saved(recoveryFile());
        return true;
    } catch (const std::exception& e) {
        mError = QString::fromUtf8(e.what());
        return false;
    }
}

std::optional<Autosave::Recovery> Autosave::pending() const {
    QFile meta(QDir(mFolder).filePath(QString::fromLatin1(kMeta)));
    if (!QFileInfo::exists(recoveryFile()) || !meta.open(QIODevice::ReadOnly)) return std::nullopt;
    const QJsonObject o = QJsonDocument::fromJson(meta.readAll()).object();
    Recovery r;
    r.documentPath = o.value(QStringLiteral("document")).toString();
    r.baseDir = o.value(QStringLiteral("base_dir")).toString();
    r.saved = QDateTime::fromString(o.value(QStringLiteral("saved")).toString(), Qt::ISODateWithMs);
    return r;
}

void Autosave::restore() {
    const std::optional<Recovery> r = pending();
    if (!r) throw IoError("there is no autosaved document in " + mFolder.toStdString());
    QFile file(recoveryFile());
    if (!file.open(QIODevice::ReadOnly))
        throw IoError("cannot read " + recoveryFile().toStdString() + ": " +
                      file.errorString().toStdString());
    Project p = parseProject(file.readAll(), recoveryFile());
    p.baseDir = r->baseDir;
    mDocument.restore(std::move(p), r->documentPath);
}

void Autosave::discard() {
    mWrote = false;
    QFile::remove(recoveryFile());
    QFile::remove(QDir(mFolder).filePath(QString::fromLatin1(kMeta)));
}

} // namespace sylva::doc
