#pragma once

#include <functional>

#include <QMenu>

class QActionGroup;

namespace sylva::ui {

/// The Presets menu: the species of the presets folder (PresetLibrary), listed afresh each time
/// the menu opens, the one previewed checked; a missing or empty folder says so.
class PresetsMenu : public QMenu {
    Q_OBJECT

public:
    /// \param previewed the species file shown as a preview now (empty: none)
    explicit PresetsMenu(std::function<QString()> previewed, QWidget* parent = nullptr);

Q_SIGNALS:
    /// A preset was chosen: its species file.
    void openRequested(const QString& path);

private:
    void populate();

    std::function<QString()> mPreviewed;
    QActionGroup* mGroup = nullptr;
};

} // namespace sylva::ui
