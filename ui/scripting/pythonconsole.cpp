#include "ui/scripting/pythonconsole.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QVBoxLayout>

#include "ui/scripting/pythonhost.h"

namespace sylva::ui {

PythonConsole::PythonConsole(QWidget* parent) : QWidget(parent) {
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    mOutput = new QPlainTextEdit(this);
    mOutput->setObjectName(QStringLiteral("consoleOutput"));
    mOutput->setReadOnly(true);
    mOutput->setFont(mono);
    mOutput->setPlaceholderText(
        tr("Python %1: sylva and doc = sylva.document() are ready. Try doc.trees(), "
           "doc.species() or doc.add_tree(doc.species()[0], (0, 0, 0)).")
            .arg(PythonHost::version()));
    layout->addWidget(mOutput);
    auto* row = new QHBoxLayout;
    mPrompt = new QLabel(QStringLiteral(">>>"), this);
    mPrompt->setFont(mono);
    mInput = new QLineEdit(this);
    mInput->setObjectName(QStringLiteral("consoleInput"));
    mInput->setFont(mono);
    mInput->installEventFilter(this);
    row->addWidget(mPrompt);
    row->addWidget(mInput);
    layout->addLayout(row);
    connect(mInput, &QLineEdit::returnPressed, this, [this] {
        const QString line = mInput->text();
        mInput->clear();
        submit(line);
    });
}

void PythonConsole::append(const QString& text, const QString& colour) {
    if (text.isEmpty()) return;
    QString body = text;
    if (body.endsWith(QLatin1Char('\n'))) body.chop(1);
    if (colour.isEmpty()) {
        mOutput->appendPlainText(body);
    } else {
        mOutput->appendHtml(QStringLiteral("<pre style=\"color:%1; margin:0\">%2</pre>")
                                .arg(colour, body.toHtmlEscaped()));
    }
}

void PythonConsole::submit(const QString& line) {
    if (mBusy) return; // a statement that waits runs the event loop: no second one meanwhile
    mBusy = true;
    mInput->setEnabled(false);
    append(mPrompt->text() + QLatin1Char(' ') + line);
    if (!line.trimmed().isEmpty() && (mHistory.isEmpty() || mHistory.last() != line))
        mHistory << line;
    mHistoryPos = mHistory.size();
    const PythonHost::ConsoleReply reply = PythonHost::pushConsoleLine(line);
    append(reply.output);
    append(reply.errors, QStringLiteral("#b00020"));
    mPrompt->setText(reply.more ? QStringLiteral("...") : QStringLiteral(">>>"));
    mInput->setEnabled(true);
    mInput->setFocus();
    mBusy = false;
    if (reply.quitRequested) Q_EMIT quitRequested(reply.exitCode);
}

QString PythonConsole::transcript() const {
    return mOutput->toPlainText();
}

bool PythonConsole::eventFilter(QObject* watched, QEvent* event) {
    if (watched == mInput && event->type() == QEvent::KeyPress) {
        const auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Up && mHistoryPos > 0) {
            mInput->setText(mHistory[--mHistoryPos]);
            return true;
        }
        if (key->key() == Qt::Key_Down && mHistoryPos < mHistory.size()) {
            ++mHistoryPos;
            mInput->setText(mHistoryPos < mHistory.size() ? mHistory[mHistoryPos] : QString());
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace sylva::ui
