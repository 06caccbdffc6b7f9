#include "ui/grammar/grammareditor.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPainter>
#include <QPushButton>
#include <QSlider>
#include <QTextBlock>
#include <QToolButton>
#include <QVBoxLayout>

#include "document/errormessage.h"
#include "engine/lsystem/grammar.h"
#include "ui/grammar/grammarhighlighter.h"

namespace sylva::ui {

namespace {

class LineNumberArea : public QWidget {
public:
    explicit LineNumberArea(CodeEdit* edit) : QWidget(edit), mEdit(edit) {}
    QSize sizeHint() const override { return QSize(mEdit->lineNumberAreaWidth(), 0); }

protected:
    void paintEvent(QPaintEvent* event) override { mEdit->paintLineNumbers(event); }

private:
    CodeEdit* mEdit;
};

} // namespace

// ---- CodeEdit -------------------------------------------------------------------------------

CodeEdit::CodeEdit(QWidget* parent)
    : QPlainTextEdit(parent), mLineNumbers(new LineNumberArea(this)) {
    QFont mono(QStringLiteral("Monospace"));
    mono.setStyleHint(QFont::TypeWriter);
    setFont(mono);
    setLineWrapMode(QPlainTextEdit::NoWrap);
    setTabStopDistance(fontMetrics().horizontalAdvance(QLatin1Char(' ')) * 4);
    connect(this, &QPlainTextEdit::blockCountChanged, this,
            [this] { setViewportMargins(lineNumberAreaWidth(), 0, 0, 0); });
    connect(this, &QPlainTextEdit::updateRequest, this, [this](const QRect& rect, int dy) {
        if (dy)
            mLineNumbers->scroll(0, dy);
        else
            mLineNumbers->update(0, rect.y(), mLineNumbers->width(), rect.height());
    });
    setViewportMargins(lineNumberAreaWidth(), 0, 0, 0);
}

int CodeEdit::lineNumberAreaWidth() const {
    int digits = 1;
    for (int max = std::max(1, blockCount()); max >= 10; max /= 10)
        ++digits;
    return 10 + fontMetrics().horizontalAdvance(QLatin1Char('9')) * std::max(digits, 2);
}

void CodeEdit::resizeEvent(QResizeEvent* event) {
    QPlainTextEdit::resizeEvent(event);
    const QRect cr = contentsRect();
    mLineNumbers->setGeometry(QRect(cr.left(), cr.top(), lineNumberAreaWidth(), cr.height()));
}

void CodeEdit::focusOutEvent(QFocusEvent* event) {
    QPlainTextEdit::focusOutEvent(event);
    Q_EMIT focusLost();
}

void CodeEdit::paintLineNumbers(QPaintEvent* event) {
    QPainter p(mLineNumbers);
    p.fillRect(event->rect(), palette().color(QPalette::AlternateBase));
    QTextBlock block = firstVisibleBlock();
    int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
    int bottom = top + qRound(blockBoundingRect(block).height());
    p.setPen(palette().color(QPalette::PlaceholderText));
    while (block.isValid() && top <= event->rect().bottom()) {
        if (block.isVisible() && bottom >= event->rect().top())
            p.drawText(0, top, mLineNumbers->width() - 4, fontMetrics().height(), Qt::AlignRight,
                       QString::number(block.blockNumber() + 1));
        block = block.next();
        top = bottom;
        bottom = top + qRound(blockBoundingRect(block).height());
    }
}

// ---- GrammarEditor --------------------------------------------------------------------------

GrammarEditor::GrammarEditor(doc::Document& document, QWidget* parent)
    : QWidget(parent), mDocument(document) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    mHeader = new QLabel(this);
    mHeader->setWordWrap(true);
    layout->addWidget(mHeader);
    mEdit = new CodeEdit(this);
    mEdit->setObjectName(QStringLiteral("grammarText"));
    mHighlighter = new GrammarHighlighter(mEdit->document());
    layout->addWidget(mEdit, 3);

    auto* stepRow = new QHBoxLayout;
    mStepLabel = new QLabel(this);
    mStep = new QSlider(Qt::Horizontal, this);
    mStep->setObjectName(QStringLiteral("generationsSlider"));
    mStep->setMinimumWidth(120);
    mStep->setToolTip(tr("Step through the derivation: the preview shows the tree after this "
                         "many generations (the grammar keeps its own count)"));
    mAnimate = new QPushButton(tr("Animate"), this);
    mAnimate->setCheckable(true);
    mAnimate->setToolTip(tr("Play the derivation from the axiom to the last generation"));
    mSymbolsButton = new QToolButton(this);
    mSymbolsButton->setText(tr("Symbols"));
    mSymbolsButton->setCheckable(true);
    stepRow->addWidget(new QLabel(tr("Generations:"), this));
    stepRow->addWidget(mStep, 1);
    stepRow->addWidget(mStepLabel);
    stepRow->addWidget(mAnimate);
    stepRow->addWidget(mSymbolsButton);
    layout->addLayout(stepRow);

    mSymbols = new QLabel(this);
    mSymbols->setTextFormat(Qt::RichText);
    mSymbols->setWordWrap(true);
    mSymbols->setText(
        tr("<table cellspacing=4>"
           "<tr><td><b>F</b> f</td><td>move forward drawing / without drawing (length, m)</td></tr>"
           "<tr><td><b>+ -</b></td><td>turn left / right (angle, °)</td></tr>"
           "<tr><td><b>&amp; ^</b></td><td>pitch down / up (°)</td></tr>"
           "<tr><td><b>\\ /</b></td><td>roll left / right (°)</td></tr>"
           "<tr><td><b>|</b></td><td>turn around</td></tr>"
           "<tr><td><b>[ ]</b></td><td>start / end a branch</td></tr>"
           "<tr><td><b>!</b></td><td>width: set (diameter, m) or multiply by width_factor</td></tr>"
           "<tr><td><b>$</b> <b>%</b></td><td>roll left horizontal / cut the branch</td></tr>"
           "<tr><td><b>J</b></td><td>a leaf (size, m)</td></tr>"
           "<tr><td>A B X …</td><td>other modules: state for the rules</td></tr>"
           "<tr><td>a &lt; B &gt; c</td><td>context; <b>: cond</b> before -&gt;, <b>: weight</b> "
           "after the successor</td></tr></table>"));
    mSymbols->hide();
    layout->addWidget(mSymbols);

    mList = new QListWidget(this);
    mList->setObjectName(QStringLiteral("grammarDiagnostics"));
    mList->setMaximumHeight(90);
    mList->setToolTip(tr("Errors in the grammar: click one to jump to it"));
    layout->addWidget(mList, 1);

    mDebounce.setObjectName(QStringLiteral("diagnosticsTimer"));
    mDebounce.setParent(this); // findable (it is a member, deleted with the editor)
    mDebounce.setSingleShot(true);
    mDebounce.setInterval(kDiagnosticsDelayMs);
    mBurst.setSingleShot(true);
    mBurst.setInterval(kBurstMs);
    mAnimation.setInterval(600);
    connect(&mDebounce, &QTimer::timeout, this, &GrammarEditor::checkNow);
    connect(&mBurst, &QTimer::timeout, this, &GrammarEditor::commitBurst);
    connect(mEdit, &CodeEdit::focusLost, this, &GrammarEditor::commitBurst);
    connect(mEdit, &QPlainTextEdit::textChanged, this, [this] {
        if (mLoading) return;
        mDirty = true;
        mHighlightedLine = 0; // the lines move; the next check redraws the marks without it
        mDebounce.start();
        mBurst.start();
    });
    connect(mList, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        jumpTo(item->data(Qt::UserRole).toInt(), item->data(Qt::UserRole + 1).toInt());
    });
    connect(mStep, &QSlider::valueChanged, this, [this](int v) {
        mStepLabel->setText(tr("%1 / %2").arg(v).arg(mGenerations));
        Q_EMIT stepChanged(mSpecies, mNode, v == mGenerations ? -1 : v);
    });
    connect(mAnimate, &QPushButton::toggled, this, [this](bool on) {
        if (on) {
            mStep->setValue(0);
            mAnimation.start();
        } else {
            mAnimation.stop();
        }
    });
    connect(&mAnimation, &QTimer::timeout, this, [this] {
        if (mStep->value() >= mGenerations) {
            mAnimate->setChecked(false);
            return;
        }
        mStep->setValue(mStep->value() + 1);
    });
    connect(mSymbolsButton, &QToolButton::toggled, mSymbols, &QWidget::setVisible);
    connect(&mDocument, &doc::Document::changed, this, [this](const doc::DocumentChange& c) {
        if (mPushing) return;
        if (c.what & doc::DocumentChange::Reset) {
            setNode({}, {});
            return;
        }
        if ((c.what & doc::DocumentChange::Species) && c.species == mSpecies)
            loadFromDocument(true);
    });
    setNode({}, {});
}

void GrammarEditor::setNode(const QString& species, const QString& node) {
    if (mDirty) commitBurst();
    mSpecies = species;
    mNode = node;
    mHighlightedLine = 0;
    loadFromDocument(false);
}

void GrammarEditor::loadFromDocument(bool keepCursor) {
    QString text;
    bool ok = false;
    QString from;
    if (!mSpecies.isEmpty() && !mNode.isEmpty()) {
        try {
            text = QString::fromStdString(
                mDocument.grammar(mSpecies.toStdString(), mNode.toStdString()));
            const sylva::Value file =
                mDocument.param(mSpecies.toStdString(), mNode.toStdString() + ".grammar_file");
            if (file.isString()) from = QString::fromStdString(file.toString());
            ok = true;
        } catch (...) {
            // Not an lsystem node, or gone after an undo.
        }
    }
    setEnabled(ok);
    if (!ok) {
        mHeader->setText(tr("Select an lsystem node to edit its grammar."));
        mLoading = true;
        mEdit->clear();
        mLoading = false;
        mDiagnostics.clear();
        showDiagnostics();
        return;
    }
    mHeader->setText(from.isEmpty()
                         ? tr("Grammar of %1 · %2 (kept in the project)").arg(mNode, mSpecies)
                         : tr("Grammar of %1 · %2, read from %3; your edits are kept in the "
                              "project, the file is not written")
                               .arg(mNode, mSpecies, from));
    if (text != mEdit->toPlainText()) {
        const int position = mEdit->textCursor().position();
        mLoading = true;
        mEdit->setPlainText(text);
        mLoading = false;
        if (keepCursor) {
            QTextCursor c = mEdit->textCursor();
            c.setPosition(std::min(position, int(text.size())));
            mEdit->setTextCursor(c);
        }
        mDirty = false;
    }
    const lsys::GrammarCheck check = lsys::checkGrammar(text.toStdString(), mNode.toStdString());
    mDiagnostics = check.diagnostics;
    updateGenerations(check, true);
    showDiagnostics();
}

void GrammarEditor::updateGenerations(const lsys::GrammarCheck& check, bool reset) {
    // The slider runs to the node's `generations`, else the grammar header's (kept while the
    // grammar does not parse).
    int generations = check.ok() ? check.grammar.generations : mGenerations;
    const sylva::Value n =
        mDocument.param(mSpecies.toStdString(), mNode.toStdString() + ".generations");
    if (n.isNumber()) generations = int(n.toNumber());
    generations = std::clamp(generations, 0, 1000);
    if (!reset && generations == mGenerations) return; // typing keeps the step shown
    mGenerations = generations;
    const QSignalBlocker b(mStep);
    mStep->setRange(0, mGenerations);
    mStep->setValue(mGenerations);
    mStepLabel->setText(tr("%1 / %2").arg(mGenerations).arg(mGenerations));
}

void GrammarEditor::checkNow() {
    mDebounce.stop();
    const std::string text = mEdit->toPlainText().toStdString();
    const lsys::GrammarCheck check = lsys::checkGrammar(text, mNode.toStdString());
    mDiagnostics = check.diagnostics;
    updateGenerations(check, false);
    showDiagnostics();
    if (mDirty && !mSpecies.isEmpty()) {
        // The edit is kept even with errors (the preview reports them), as the user typed it;
        // uncommitted, so that the burst stays one undo step.
        mPushing = true;
        try {
            mDocument.setGrammar(mSpecies.toStdString(), mNode.toStdString(), text, false);
            mOpenBurst = true;
        } catch (...) {
        }
        mPushing = false;
        mDirty = false;
    }
    Q_EMIT checked(int(mDiagnostics.size()));
}

void GrammarEditor::commitBurst() {
    mBurst.stop();
    if (mDirty) checkNow();
    if (!mOpenBurst || mSpecies.isEmpty()) return;
    mOpenBurst = false;
    mPushing = true;
    try {
        // Same text, committed: closes the merge (or vanishes as an obsolete step).
        mDocument.setGrammar(mSpecies.toStdString(), mNode.toStdString(),
                             mEdit->toPlainText().toStdString(), true);
    } catch (...) {
    }
    mPushing = false;
}

void GrammarEditor::showDiagnostics() {
    mList->clear();
    QList<QTextEdit::ExtraSelection> marks;
    QTextDocument* document = mEdit->document();
    for (const Diagnostic& d : mDiagnostics) {
        auto* item = new QListWidgetItem(tr("line %1, column %2: %3")
                                             .arg(d.line)
                                             .arg(d.column)
                                             .arg(QString::fromStdString(d.message)),
                                         mList);
        item->setData(Qt::UserRole, d.line);
        item->setData(Qt::UserRole + 1, d.column);
        item->setForeground(QColor(230, 80, 80));
        const QTextBlock block = document->findBlockByNumber(d.line - 1);
        if (!block.isValid()) continue;
        QTextEdit::ExtraSelection mark;
        mark.cursor = QTextCursor(block);
        const int start = std::clamp(d.column - 1, 0, std::max(0, block.length() - 1));
        mark.cursor.setPosition(block.position() + start);
        // Underline the token the error is at (at least one character).
        int end = start;
        const QString line = block.text();
        while (end < line.size() && !line[end].isSpace() &&
               (end == start || line[end].isLetterOrNumber()))
            ++end;
        end = std::max(end, std::min(start + 1, int(line.size())));
        if (end == start) { // at the end of the line: underline the last character
            mark.cursor.setPosition(block.position() + std::max(0, start - 1));
            end = start;
            mark.cursor.setPosition(block.position() + end, QTextCursor::KeepAnchor);
        } else {
            mark.cursor.setPosition(block.position() + end, QTextCursor::KeepAnchor);
        }
        mark.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
        mark.format.setUnderlineColor(QColor(230, 50, 50));
        mark.format.setToolTip(QString::fromStdString(d.message));
        marks << mark;
    }
    if (mDiagnostics.empty() && isEnabled()) new QListWidgetItem(tr("No errors"), mList);
    if (const QTextBlock block = document->findBlockByNumber(mHighlightedLine - 1);
        mHighlightedLine > 0 && block.isValid()) {
        QTextEdit::ExtraSelection band;
        band.cursor = QTextCursor(block);
        band.format.setBackground(QColor(255, 200, 60, 70));
        band.format.setProperty(QTextFormat::FullWidthSelection, true);
        band.format.setToolTip(tr("The rule that grew the branch you clicked in the preview"));
        marks.prepend(band); // under the squiggles
    }
    mEdit->setExtraSelections(marks);
}

void GrammarEditor::highlightLine(int line) {
    mHighlightedLine = line;
    showDiagnostics();
    if (line <= 0) return;
    const QTextBlock block = mEdit->document()->findBlockByNumber(line - 1);
    if (!block.isValid()) return;
    QTextCursor c(block);
    mEdit->setTextCursor(c);
    mEdit->centerCursor();
}

void GrammarEditor::jumpTo(int line, int column) {
    const QTextBlock block = mEdit->document()->findBlockByNumber(line - 1);
    if (!block.isValid()) return;
    QTextCursor c(block);
    c.setPosition(block.position() + std::clamp(column - 1, 0, std::max(0, block.length() - 1)));
    mEdit->setTextCursor(c);
    mEdit->setFocus();
    mEdit->ensureCursorVisible();
}

} // namespace sylva::ui
