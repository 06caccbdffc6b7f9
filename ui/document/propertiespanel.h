#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <QWidget>

#include "document/document.h"

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLineEdit;
class QLabel;

namespace sylva::doc {
struct SettingSpec;
}

namespace sylva::ui {

struct GenerationResult;

/// The Properties dock: typed editors for the selected tree, obstacle, domain, species, the
/// camera and the light, or the project's own settings when nothing is selected. Every change
/// goes through the document's edit functions (one undo step each); a value the document
/// refuses is reported (failed()) and the editor shows the document's value again.
class PropertiesPanel : public QWidget {
    Q_OBJECT

public:
    explicit PropertiesPanel(doc::Document& document, QWidget* parent = nullptr);
    /// The shown generation (a selected branch's lock keeps the geometry shown).
    void setResult(std::function<const GenerationResult&()> result) { mResult = std::move(result); }

    /// The item shown, or none for the project.
    std::optional<doc::ItemRef> item() const { return mItem; }

Q_SIGNALS:
    void failed(const QString& message);

private:
    void rebuild();
    void refresh();
    void apply(const std::function<void()>& edit);
    /// Adds a row of \p count spin boxes (x, y, z) with \p suffix; returns their index in
    /// mSpins.
    int addSpins(const QString& label, int count, double lo, double hi, double step, int decimals,
                 const QString& suffix, const QString& tooltip);
    /// A row of one spin box for a project setting: its label, range, step, decimals, unit and
    /// help from its spec (core/document/projectsettings.h); returns its index in mSpins.
    int addSetting(const doc::SettingSpec& spec);
    double spin(int i) const;
    glm::vec3 vec3At(int first) const;
    /// A Season row: \p unset names what an empty season means (the species' own, or the
    /// project's); the item data are the names the document takes ("" for unset).
    void addSeasonCombo(const QString& unset, const QString& tooltip);
    void showSeason(const std::string& season);

    doc::Document& mDocument;
    std::optional<doc::ItemRef> mItem;
    QLabel* mTitle = nullptr;
    QWidget* mBody = nullptr;
    QFormLayout* mForm = nullptr;
    std::vector<QDoubleSpinBox*> mSpins;
    QComboBox* mSpecies = nullptr;
    QComboBox* mSeason = nullptr;
    QLineEdit* mSeed = nullptr;
    QLabel* mInfo = nullptr;
    std::function<void()> mRefresh; ///< puts the document's values into the editors
    bool mUpdating = false;
    std::function<const GenerationResult&()> mResult;
};

} // namespace sylva::ui
