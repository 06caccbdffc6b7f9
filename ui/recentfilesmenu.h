#pragma once

#include <QMenu>
#include <QStringList>

namespace sylva::ui {

/// File ▸ Open recent: the last files opened or saved (kept in the settings, newest first,
/// at most kMaxFiles), listed afresh each time the menu opens.
class RecentFilesMenu : public QMenu {
    Q_OBJECT

public:
    static constexpr int kMaxFiles = 8;

    explicit RecentFilesMenu(QWidget* parent = nullptr);

    /// The files as listed (absolute paths).
    static QStringList files();
    /// Puts \p path first (once, absolute) and forgets the oldest beyond kMaxFiles.
    static void add(const QString& path);

Q_SIGNALS:
    /// A file was chosen.
    void openRequested(const QString& path);

private:
    void populate();
};

} // namespace sylva::ui
