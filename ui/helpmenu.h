#pragma once

#include <QMenu>
#include <QString>

namespace sylva::ui {

/// Help: the editor's documentation (docs/editor.md beside the presets in a source tree, else
/// the installed copy) and About Sylva.
class HelpMenu : public QMenu {
    Q_OBJECT

public:
    /// \param parent the window (the About box belongs to it)
    explicit HelpMenu(QWidget* parent);

    /// The documentation folder: `docs` beside the presets folder, else /usr/share/doc/sylva.
    static QString documentationFolder();
};

} // namespace sylva::ui
