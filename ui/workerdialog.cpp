#include "ui/workerdialog.h"

#include <thread>

#include <QEventLoop>
#include <QTimer>

namespace sylva::ui {

WorkerOutcome runWithProgress(QWidget* parent, const QString& title, const QString& label,
                              const QString& objectName, DialogProgress& progress,
                              const std::function<void(Progress&)>& job,
                              QPointer<QProgressDialog>& dialog) {
    WorkerOutcome outcome;
    std::atomic<bool> done{false};
    std::thread worker([&] {
        try {
            job(progress);
        } catch (...) {
            outcome.error = std::current_exception();
        }
        done.store(true);
    });
    dialog = new QProgressDialog(label, QObject::tr("Cancel"), 0, 100, parent);
    dialog->setObjectName(objectName);
    dialog->setWindowTitle(title);
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setMinimumDuration(0);
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    QObject::connect(dialog, &QProgressDialog::canceled, dialog,
                     [&progress] { progress.cancel(); });
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (dialog) dialog->setValue(progress.percent());
        if (done.load()) loop.quit();
    });
    poll.start(50);
    loop.exec();
    worker.join();
    delete dialog;
    outcome.cancelled = progress.isCancelled();
    return outcome;
}

} // namespace sylva::ui
