#pragma once

#include <QWidget>

class QListWidget;

namespace sylva::ui {

/// The Messages dock: every error, warning and note of the session with its time, newest last
/// (the status bar shows only the latest line).
class MessagesPanel : public QWidget {
    Q_OBJECT

public:
    enum class Severity { Info, Warning, Error };
    explicit MessagesPanel(QWidget* parent = nullptr);

    void add(Severity severity, const QString& message);
    int count() const;
    /// The text of message \p row (without its time), for tests.
    QString message(int row) const;

Q_SIGNALS:
    void errorAdded(const QString& message);

private:
    QListWidget* mList = nullptr;
};

} // namespace sylva::ui
