#pragma once

#include <QList>
#include <QString>

namespace sylva::doc {

/// One species file of the presets folder.
struct PresetInfo {
    QString name; ///< the species' "name", or the file's base name
    QString path; ///< absolute path of the .json file
};

/// Finds and lists the shipped species presets.
class PresetLibrary {
public:
    /// File name of the preset the editor opens at start.
    static constexpr const char* kDefaultPresetFile = "ternary-tree.json";

    /// The presets folder: $SYLVA_PRESETS_DIR if set, else `<prefix>/share/sylva/presets` next
    /// to an installed executable, else a `presets` folder in the executable's folder or up to
    /// four levels above it (the source tree when running from a build folder), else the
    /// source tree's folder recorded at build time. Empty when none exists.
    static QString directory();

    /// The species files (*.json) in \p directory, sorted by file name.
    static QList<PresetInfo> list(const QString& directory);

    /// The default preset in directory(), or the first preset there, or empty.
    static QString defaultPreset();
};

} // namespace sylva::doc
