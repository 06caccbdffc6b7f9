#pragma once

#include <functional>
#include <map>
#include <string>

#include <QWidget>

#include "document/document.h"
#include "engine/graph/graph.h"

class QFormLayout;
class QLabel;
class QPlainTextEdit;
class QVBoxLayout;

namespace sylva::ui {

/// The parameters of one node of a species, as typed editors built from the node type's
/// metadata: spin boxes and sliders with their ranges and units, check boxes, choices, vectors,
/// file pickers, JSON for structured values; each with its one-line meaning as tooltip and a
/// reset-to-default button. Every change is a Document command; a slider drag is one undo step.
/// A value the engine refuses is shown with its message and changes nothing.
class ParameterPanel : public QWidget {
    Q_OBJECT

public:
    explicit ParameterPanel(doc::Document& document, QWidget* parent = nullptr);

    /// Shows \p node of \p species ("" for none).
    void setNode(const QString& species, const QString& node);
    const QString& species() const { return mSpecies; }
    const QString& node() const { return mNode; }
    /// The editor widget of a parameter (for tests and scripts), or nullptr.
    QWidget* editor(const QString& param) const;
    /// The last refusal shown ("" when the last edit was accepted).
    QString errorText() const;

Q_SIGNALS:
    /// The user asked to edit an lsystem node's grammar (the grammar editor shows it).
    void editGrammarRequested(const QString& species, const QString& node);

private:
    void rebuild();
    void refreshValues();
    bool apply(const std::string& param, const sylva::Value& value, bool commit = true);
    QWidget* makeEditor(const graph::ParamSpec& spec);
    /// Adds a curve editor under an object's (or a curve's) JSON: a Curve parameter's points, or
    /// a crown envelope's profile with the Weber-Penn shapes to start from.
    void addProfileEditor(const graph::ParamSpec& spec, QWidget* box, QVBoxLayout* layout,
                          QPlainTextEdit* json);

    doc::Document& mDocument;
    QString mSpecies, mNode;
    QVBoxLayout* mLayout = nullptr;
    QWidget* mBody = nullptr;
    QLabel* mHeader = nullptr;
    QLabel* mError = nullptr;
    std::map<std::string, QWidget*> mEditors;
    /// Per parameter: puts the document's value (or the default when unset) into its editor.
    std::map<std::string, std::function<void(const sylva::Value&)>> mShow;
    std::map<std::string, QWidget*> mResetButtons;
    bool mApplying = false;
};

} // namespace sylva::ui
