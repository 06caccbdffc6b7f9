#include "document/presetlibrary.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>

namespace sylva::doc {

namespace {

bool isPresetsDir(const QString& dir) {
    return !dir.isEmpty() && QFileInfo(dir).isDir() &&
           !QDir(dir).entryList({QStringLiteral("*.json")}, QDir::Files).isEmpty();
}

QString speciesName(const QString& path) {
    QFile file(path);
    // Species files are small; a preset that does not parse still gets listed by file name,
    // and opening it reports the real error.
    if (file.size() < 4 * 1024 * 1024 && file.open(QIODevice::ReadOnly)) {
        const QJsonDocument doc = QJsonDocument::fromJson(file.readAll());
        const QString name = doc.object().value(QStringLiteral("name")).toString();
        if (!name.isEmpty()) return name;
    }
    return QFileInfo(path).completeBaseName();
}

} // namespace

QString PresetLibrary::directory() {
    const QString env = qEnvironmentVariable("SYLVA_PRESETS_DIR");
    if (!env.isEmpty()) return QFileInfo(env).absoluteFilePath();

    const QString appDir = QCoreApplication::applicationDirPath();
    if (!appDir.isEmpty()) {
        const QString installed = QDir(appDir).filePath(QStringLiteral("../share/sylva/presets"));
        if (isPresetsDir(installed)) return QDir(installed).canonicalPath();
        QDir dir(appDir);
        for (int level = 0; level <= 4; ++level) {
            const QString candidate = dir.filePath(QStringLiteral("presets"));
            if (isPresetsDir(candidate)) return QDir(candidate).canonicalPath();
            if (!dir.cdUp()) break;
        }
    }
#ifdef SYLVA_SOURCE_PRESETS_DIR
    if (isPresetsDir(QStringLiteral(SYLVA_SOURCE_PRESETS_DIR)))
        return QStringLiteral(SYLVA_SOURCE_PRESETS_DIR);
#endif
    return {};
}

QList<PresetInfo> PresetLibrary::list(const QString& directory) {
    QList<PresetInfo> presets;
    if (directory.isEmpty()) return presets;
    const QDir dir(directory);
    const QStringList files =
        dir.entryList({QStringLiteral("*.json")}, QDir::Files | QDir::Readable, QDir::Name);
    for (const QString& file : files) {
        const QString path = dir.absoluteFilePath(file);
        presets.append({speciesName(path), path});
    }
    return presets;
}

QString PresetLibrary::defaultPreset() {
    const QString dir = directory();
    if (dir.isEmpty()) return {};
    const QString preferred = QDir(dir).absoluteFilePath(QString::fromLatin1(kDefaultPresetFile));
    if (QFileInfo::exists(preferred)) return preferred;
    const QList<PresetInfo> all = list(dir);
    return all.isEmpty() ? QString() : all.first().path;
}

} // namespace sylva::doc
