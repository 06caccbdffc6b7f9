#include "ui/grammar/grammarhighlighter.h"

#include <QRegularExpression>

namespace sylva::ui {

namespace {

QTextCharFormat makeFormat(const QColor& color, bool bold = false, bool italic = false) {
    QTextCharFormat f;
    f.setForeground(color);
    if (bold) f.setFontWeight(QFont::Bold);
    f.setFontItalic(italic);
    return f;
}

bool isTurtle(QChar c) {
    return QStringLiteral("Ff+-&^\\/|[]!$%J").contains(c);
}

} // namespace

GrammarHighlighter::GrammarHighlighter(QTextDocument* document)
    : QSyntaxHighlighter(document), mComment(makeFormat(QColor(110, 140, 110), false, true)),
      mSetting(makeFormat(QColor(190, 120, 220), true)),
      mDefine(makeFormat(QColor(220, 150, 80), true)),
      mArrow(makeFormat(QColor(230, 200, 90), true)),
      mContext(makeFormat(QColor(90, 190, 220), true)),
      mCondition(makeFormat(QColor(220, 110, 110))),
      mTurtle(makeFormat(QColor(120, 200, 120), true)),
      mModule(makeFormat(QColor(120, 170, 240), true)),
      mParameter(makeFormat(QColor(180, 180, 180))) {}

QTextCharFormat GrammarHighlighter::formatOf(const QString& kind) const {
    if (kind == QLatin1String("comment")) return mComment;
    if (kind == QLatin1String("setting")) return mSetting;
    if (kind == QLatin1String("define")) return mDefine;
    if (kind == QLatin1String("arrow")) return mArrow;
    if (kind == QLatin1String("context")) return mContext;
    if (kind == QLatin1String("condition")) return mCondition;
    if (kind == QLatin1String("turtle")) return mTurtle;
    if (kind == QLatin1String("module")) return mModule;
    return mParameter;
}

void GrammarHighlighter::highlightBlock(const QString& text) {
    int end = text.size();
    if (const int hash = text.indexOf(QLatin1Char('#')); hash >= 0) {
        setFormat(hash, text.size() - hash, mComment);
        end = hash;
    }
    const QString code = text.left(end);
    static const QRegularExpression setting(
        QStringLiteral("^\\s*(generations|angle|step|width|width_factor|seed|ignore|axiom)\\s*:"));
    static const QRegularExpression define(QStringLiteral("^\\s*define\\s*:"));
    int from = 0;
    if (const auto m = setting.match(code); m.hasMatch()) {
        setFormat(m.capturedStart(), m.capturedLength(), mSetting);
        from = m.capturedEnd();
        if (m.captured(1) != QLatin1String("axiom")) return; // a value, not modules
    } else if (const auto d = define.match(code); d.hasMatch()) {
        setFormat(d.capturedStart(), d.capturedLength(), mDefine);
        return;
    }
    const int arrow = code.indexOf(QStringLiteral("->"), from);
    if (arrow >= 0) setFormat(arrow, 2, mArrow);
    // Before the arrow: contexts and a condition after ':'. After it: a weight after ':'.
    int depth = 0;
    bool inCondition = false;
    for (int i = from; i < code.size(); ++i) {
        if (arrow >= 0 && (i == arrow || i == arrow + 1)) {
            inCondition = false;
            continue;
        }
        const QChar c = code[i];
        if (c == QLatin1Char('(')) {
            ++depth;
            setFormat(i, 1, mParameter);
            continue;
        }
        if (c == QLatin1Char(')')) {
            depth = std::max(0, depth - 1);
            setFormat(i, 1, mParameter);
            continue;
        }
        if (depth > 0) {
            setFormat(i, 1, inCondition ? mCondition : mParameter);
            continue;
        }
        if (c == QLatin1Char(':')) {
            inCondition = true;
            setFormat(i, 1, mCondition);
            continue;
        }
        if (inCondition) {
            setFormat(i, 1, mCondition);
            continue;
        }
        if (arrow > 0 && i < arrow && (c == QLatin1Char('<') || c == QLatin1Char('>'))) {
            setFormat(i, 1, mContext);
            continue;
        }
        if (c.isSpace()) continue;
        setFormat(i, 1, isTurtle(c) ? mTurtle : mModule);
    }
}

} // namespace sylva::ui
