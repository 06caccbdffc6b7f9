#pragma once

#include <vector>

#include <QPlainTextEdit>
#include <QTimer>
#include <QWidget>

#include "document/document.h"
#include "engine/util/error.h"

class QLabel;
class QListWidget;
class QPushButton;
class QSlider;
class QToolButton;

namespace sylva::lsys {
struct GrammarCheck;
}

namespace sylva::ui {

class GrammarHighlighter;

/// A plain-text editor with line numbers in the margin (the grammar editor's text).
class CodeEdit : public QPlainTextEdit {
    Q_OBJECT

public:
    explicit CodeEdit(QWidget* parent = nullptr);
    int lineNumberAreaWidth() const;
    void paintLineNumbers(QPaintEvent* event);

protected:
    void resizeEvent(QResizeEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

Q_SIGNALS:
    void focusLost();

private:
    QWidget* mLineNumbers;
};

/// The grammar editor of an lsystem node: highlighting, diagnostics while typing (200 ms after
/// typing stops: a squiggle under each error with its message as tooltip, and a list that jumps
/// to the error on click), drawn as extra selections, never as edits of the text. The text goes
/// to the Document as the user types (the live preview follows); a burst of typing is one undo
/// step (it is committed after a second without typing, or when the editor loses focus). A
/// generations slider steps through the derivation in the preview (L-Py's Step / Animate), and a
/// symbol reference lists what the turtle reads.
class GrammarEditor : public QWidget {
    Q_OBJECT

public:
    static constexpr int kDiagnosticsDelayMs = 200;
    static constexpr int kBurstMs = 1000;

    explicit GrammarEditor(doc::Document& document, QWidget* parent = nullptr);

    /// Edits the grammar of \p node (an lsystem node) of \p species; "" for none.
    void setNode(const QString& species, const QString& node);
    const QString& species() const { return mSpecies; }
    const QString& node() const { return mNode; }
    CodeEdit* textEdit() const { return mEdit; }
    QListWidget* diagnosticsList() const { return mList; }
    QSlider* stepSlider() const { return mStep; }
    /// The diagnostics shown now (after the last check).
    const std::vector<Diagnostic>& diagnostics() const { return mDiagnostics; }
    /// Checks the text now (what the debounce timer does) and pushes it to the document.
    void checkNow();
    /// Ends the current burst of typing: the next keystroke starts a new undo step.
    void commitBurst();
    /// Marks \p line (1-based; a rule the user clicked in the preview) with a full-width band and
    /// scrolls to it; 0 removes the mark. Typing removes it too (the lines move).
    void highlightLine(int line);
    int highlightedLine() const { return mHighlightedLine; }

Q_SIGNALS:
    /// The generations slider moved: the preview derives \p generations steps (-1: the
    /// grammar's own count).
    void stepChanged(const QString& species, const QString& node, int generations);
    /// Diagnostics were updated (count of errors).
    void checked(int errors);

private:
    void loadFromDocument(bool keepCursor);
    /// Sets the generations slider's range (and puts it at the end when \p reset or changed).
    void updateGenerations(const lsys::GrammarCheck& check, bool reset);
    void showDiagnostics();
    void jumpTo(int line, int column);

    doc::Document& mDocument;
    QString mSpecies, mNode;
    QLabel* mHeader;
    CodeEdit* mEdit;
    GrammarHighlighter* mHighlighter;
    QListWidget* mList;
    QSlider* mStep;
    QLabel* mStepLabel;
    QPushButton* mAnimate;
    QToolButton* mSymbolsButton;
    QLabel* mSymbols;
    QTimer mDebounce, mBurst, mAnimation;
    std::vector<Diagnostic> mDiagnostics;
    bool mLoading = false;
    bool mPushing = false;
    bool mDirty = false; ///< typed since the last push to the document
    bool mOpenBurst = false;
    int mGenerations = 0;
    int mHighlightedLine = 0;
};

} // namespace sylva::ui
