#pragma once

#include <QCoreApplication>
#include <QString>

class QWidget;

namespace sylva::ui {

/// The editor's file dialogs: what each suggests, its filters, and the extension it adds when
/// none was typed. Each returns the path chosen, or an empty string when cancelled.
class FileDialogs {
    Q_DECLARE_TR_FUNCTIONS(sylva::ui::FileDialogs)

public:
    /// File ▸ Open: a species, grammar or project, starting beside \p shown (the file shown
    /// now), or in the presets folder.
    static QString open(QWidget* parent, const QString& shown);
    /// File ▸ Save As: a project file, \p current suggested (forest.sylva when none); ".sylva"
    /// added when no extension was typed.
    static QString saveProject(QWidget* parent, const QString& current);
    /// File ▸ Export: \p shown's name as .obj suggested; the chosen filter's extension added
    /// when no extension was typed.
    static QString exportFile(QWidget* parent, const QString& shown);
    /// File ▸ Save screenshot: \p shown's name as .png suggested.
    static QString screenshot(QWidget* parent, const QString& shown);

    /// \p path with the first extension of \p filter ("glTF binary (*.glb)" adds ".glb") when it
    /// has none.
    static QString withFilterExtension(const QString& path, const QString& filter);
    /// Where the export dialogs open: the folder of \p shown (the project or species file),
    /// else the home folder; Export and Export LOD chain… start at the same place.
    static QString startFolder(const QString& shown);
    /// \p shown's base name (\p fallback when none) with \p extension (".obj"), in
    /// startFolder(\p shown).
    static QString suggestedName(const QString& shown, const QString& fallback,
                                 const QString& extension);
};

} // namespace sylva::ui
