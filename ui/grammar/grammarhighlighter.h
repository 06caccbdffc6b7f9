#pragma once

#include <QSyntaxHighlighter>
#include <QTextCharFormat>

namespace sylva::ui {

/// Colours the grammar language (docs/grammar.md): comments, header settings and defines, the
/// rule arrow, contexts (< >), conditions and probabilities after ':', turtle modules, other
/// modules, and parameter lists.
class GrammarHighlighter : public QSyntaxHighlighter {
    Q_OBJECT

public:
    explicit GrammarHighlighter(QTextDocument* document);

    /// The format given to a kind of token (for tests): "comment", "setting", "define",
    /// "arrow", "context", "condition", "turtle", "module", "parameter".
    QTextCharFormat formatOf(const QString& kind) const;

protected:
    void highlightBlock(const QString& text) override;

private:
    QTextCharFormat mComment, mSetting, mDefine, mArrow, mContext, mCondition, mTurtle, mModule,
        mParameter;
};

} // namespace sylva::ui
