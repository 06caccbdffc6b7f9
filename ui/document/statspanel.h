#pragma once

#include <QWidget>

class QLabel;

namespace sylva::doc {
class Document;
}

namespace sylva::ui {

struct GenerationResult;

/// The "Tree" dock: species (or project) name and statistics of the generated tree or forest. Each
/// value label has an object name ("statVertices", ...) so that tests and style sheets can find it.
class StatsPanel : public QWidget {
    Q_OBJECT

public:
    explicit StatsPanel(QWidget* parent = nullptr);

    /// Shows the numbers of a successful run.
    void showResult(const GenerationResult& result);
    /// Marks the panel as busy while \p name is being generated.
    void showGenerating(const QString& name);
    /// Shows an error under the last good statistics.
    void showError(const QString& message);
    /// Shows a warning of the last load (e.g. a project from a newer Sylva) under the statistics.
    void showWarning(const QString& message);

    /// The selected trees of the document: how many, and their height, DBH, wood volume,
    /// biomass and CO2 from \p result (the last generation).
    void showSelection(const doc::Document& document, const GenerationResult& result);

    /// The text of a value label by object name (for tests); empty if there is none.
    QString value(const QString& objectName) const;

private:
    QLabel* mSpecies = nullptr;
    QLabel* mFile = nullptr;
    QLabel* mTrees = nullptr;
    QLabel* mVertices = nullptr;
    QLabel* mTriangles = nullptr;
    QLabel* mSegments = nullptr;
    QLabel* mLeaves = nullptr;
    QLabel* mHeight = nullptr;
    QLabel* mTime = nullptr;
    QLabel* mCo2 = nullptr;
    QLabel* mWood = nullptr;
    QLabel* mStatus = nullptr;
    QLabel* mSelection = nullptr;
};

} // namespace sylva::ui
