#pragma once

#include <QStringList>
#include <QWidget>

class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace sylva::ui {

/// The Python Console dock: a prompt with history (Up/Down), multi-line statements (a line that
/// opens a block continues at "..." until an empty line), output and tracebacks in the pane
/// above. `sylva` and `doc` (sylva.document()) are ready to use.
class PythonConsole : public QWidget {
    Q_OBJECT

public:
    explicit PythonConsole(QWidget* parent = nullptr);

    /// Runs one line as if typed (for tests and the window's menu).
    void submit(const QString& line);
    QString transcript() const;
    QLineEdit* input() const { return mInput; }

Q_SIGNALS:
    void quitRequested(int code);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void append(const QString& text, const QString& colour = {});

    QPlainTextEdit* mOutput = nullptr;
    QLabel* mPrompt = nullptr;
    QLineEdit* mInput = nullptr;
    QStringList mHistory;
    qsizetype mHistoryPos = 0;
    bool mBusy = false;
};

} // namespace sylva::ui
