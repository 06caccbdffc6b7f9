#pragma once

#include <QDialog>

class QComboBox;
class QSpinBox;

namespace sylva::ui {

/// Edit ▸ Preferences: how often the autosave copy is written and the viewport's antialiasing.
/// It only shows and collects the choices; the window applies them after exec() accepts.
class PreferencesDialog : public QDialog {
    Q_OBJECT

public:
    /// \param autosaveMs the autosave interval now, milliseconds
    /// \param recoveryFolder where the recovery copies go (shown, not editable)
    /// \param samples the antialiasing preference now (Viewport::samplesPreference())
    PreferencesDialog(int autosaveMs, const QString& recoveryFolder, int samples,
                      QWidget* parent = nullptr);

    /// The autosave interval chosen, seconds (whole minutes, 1 to 60).
    int autosaveSeconds() const;
    /// The antialiasing chosen: Viewport::kAutoSamples, 0, 2, 4 or 8.
    int samples() const;

private:
    QSpinBox* mMinutes = nullptr;
    QComboBox* mSamples = nullptr;
};

} // namespace sylva::ui
