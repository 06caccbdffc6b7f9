#pragma once

#include <QMenu>

namespace sylva::ui {

/// View ▸ Language: the language Sylva starts in next time (QSettings "language"; empty: the
/// system's). The translation is loaded at start-up (app/editor), so a choice says so.
class LanguageMenu : public QMenu {
    Q_OBJECT

public:
    /// \param parent the window (the choice's message belongs to it)
    explicit LanguageMenu(QWidget* parent);
};

} // namespace sylva::ui
