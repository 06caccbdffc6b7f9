#include "ui/document/messagespanel.h"

#include <QAction>
#include <QApplication>
#include <QListWidget>
#include <QStyle>
#include <QTime>
#include <QVBoxLayout>

namespace sylva::ui {

MessagesPanel::MessagesPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    mList = new QListWidget(this);
    mList->setObjectName(QStringLiteral("messagesList"));
    mList->setWordWrap(true);
    mList->setContextMenuPolicy(Qt::ActionsContextMenu);
    auto* clear = new QAction(tr("Clear"), mList);
    connect(clear, &QAction::triggered, mList, &QListWidget::clear);
    mList->addAction(clear);
    layout->addWidget(mList);
}

void MessagesPanel::add(Severity severity, const QString& message) {
    QStyle::StandardPixmap icon = QStyle::SP_MessageBoxInformation;
    if (severity == Severity::Warning) icon = QStyle::SP_MessageBoxWarning;
    if (severity == Severity::Error) icon = QStyle::SP_MessageBoxCritical;
    auto* item = new QListWidgetItem(style()->standardIcon(icon),
                                     QTime::currentTime().toString(QStringLiteral("HH:mm:ss")) +
                                         QStringLiteral("  ") + message);
    item->setData(Qt::UserRole, message);
    mList->addItem(item);
    mList->scrollToBottom();
    if (severity == Severity::Error) Q_EMIT errorAdded(message);
}

int MessagesPanel::count() const {
    return mList->count();
}

QString MessagesPanel::message(int row) const {
    const QListWidgetItem* item = mList->item(row);
    return item ? item->data(Qt::UserRole).toString() : QString();
}

} // namespace sylva::ui
