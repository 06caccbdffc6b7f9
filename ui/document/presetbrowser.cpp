#include "ui/document/presetbrowser.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QStandardPaths>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "document/errormessage.h"
#include "document/presetlibrary.h"
#include "ui/generation/thumbnail.h"

namespace sylva::ui {

namespace {
constexpr int kPathRole = Qt::UserRole;
constexpr int kDrawnRole = Qt::UserRole + 1;
} // namespace

PresetBrowser::PresetBrowser(doc::Document& document, QWidget* parent)
    : QWidget(parent), mDocument(document) {
    mPool.setMaxThreadCount(1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    mList = new QListWidget(this);
    mList->setObjectName(QStringLiteral("presetList"));
    mList->setViewMode(QListView::IconMode);
    mList->setIconSize(QSize(kThumbnailSize, kThumbnailSize));
    mList->setGridSize(QSize(kThumbnailSize + 34, kThumbnailSize + 40));
    mList->setResizeMode(QListView::Adjust);
    mList->setMovement(QListView::Static);
    mList->setWordWrap(true);
    mList->setToolTip(tr("Double-click a preset to apply it to the species"));
    layout->addWidget(mList, 1);
    mTargetLabel = new QLabel(this);
    mTargetLabel->setWordWrap(true);
    layout->addWidget(mTargetLabel);
    auto* buttons = new QHBoxLayout;
    mApply = new QPushButton(tr("Apply"), this);
    mApply->setObjectName(QStringLiteral("applyPreset"));
    mSave = new QPushButton(tr("Save species as preset…"), this);
    mSave->setObjectName(QStringLiteral("savePreset"));
    buttons->addWidget(mApply);
    buttons->addWidget(mSave);
    layout->addLayout(buttons);
    connect(mApply, &QPushButton::clicked, this, &PresetBrowser::applySelected);
    connect(mList, &QListWidget::itemDoubleClicked, this, [this] { applySelected(); });
    connect(mSave, &QPushButton::clicked, this, [this] {
        const QString dir = userPresetsDirectory();
        QDir().mkpath(dir);
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Save species as preset"),
            QDir(dir).filePath(targetSpecies() + QStringLiteral(".json")), tr("Species (*.json)"));
        if (!path.isEmpty()) saveTargetAs(path);
    });
    connect(&mDocument, &doc::Document::changed, this, [this](const doc::DocumentChange& c) {
        if (c.what & (doc::DocumentChange::Reset | doc::DocumentChange::Species))
            setTargetSpecies(mTarget);
    });
    refresh();
    setTargetSpecies({});
}

PresetBrowser::~PresetBrowser() {
    mPool.clear();
    mPool.waitForDone();
}

QString PresetBrowser::userPresetsDirectory() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("presets"));
}

QString PresetBrowser::thumbnailCacheDirectory() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::CacheLocation))
        .filePath(QStringLiteral("thumbnails"));
}

void PresetBrowser::setTargetSpecies(const QString& species) {
    QString target = species;
    if (mDocument.speciesIndex(target.toStdString()) < 0)
        target = mDocument.project().species.empty()
                     ? QString()
                     : QString::fromStdString(mDocument.project().species.front().name);
    mTarget = target;
    mTargetLabel->setText(target.isEmpty()
                              ? tr("The project has no species to apply a preset to.")
                              : tr("Apply replaces the graph of species <b>%1</b> (undoable).")
                                    .arg(target.toHtmlEscaped()));
    mApply->setEnabled(!target.isEmpty());
    mSave->setEnabled(!target.isEmpty());
}

QString PresetBrowser::targetSpecies() const {
    return mTarget;
}

void PresetBrowser::refresh() {
    mList->clear();
    QList<doc::PresetInfo> presets = doc::PresetLibrary::list(doc::PresetLibrary::directory());
    presets += doc::PresetLibrary::list(userPresetsDirectory());
    for (const doc::PresetInfo& p : presets) {
        auto* item = new QListWidgetItem(p.name, mList);
        item->setData(kPathRole, p.path);
        item->setToolTip(QDir::toNativeSeparators(p.path));
        QPixmap blank(kThumbnailSize, kThumbnailSize);
        blank.fill(QColor(60, 60, 64));
        item->setIcon(QIcon(blank));
    }
    mStarted = false;
    if (isVisible()) startThumbnails();
}

void PresetBrowser::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (!mStarted) startThumbnails();
}

void PresetBrowser::startThumbnails() {
    mStarted = true;
    const QString cache = thumbnailCacheDirectory();
    for (int i = 0; i < mList->count(); ++i) {
        QListWidgetItem* item = mList->item(i);
        if (item->data(kDrawnRole).toBool()) continue;
        const QString path = item->data(kPathRole).toString();
        ++mPending;
        auto* watcher = new QFutureWatcher<QImage>(this);
        connect(watcher, &QFutureWatcher<QImage>::finished, this, [this, watcher, path] {
            --mPending;
            const QImage image = watcher->result();
            watcher->deleteLater();
            for (int k = 0; k < mList->count(); ++k) {
                QListWidgetItem* it = mList->item(k);
                if (it->data(kPathRole).toString() != path) continue;
                it->setData(kDrawnRole, true);
                if (!image.isNull()) it->setIcon(QIcon(QPixmap::fromImage(image)));
            }
        });
        watcher->setFuture(QtConcurrent::run(
            &mPool, [path, cache] { return speciesThumbnail(path, kThumbnailSize, cache); }));
    }
}

bool PresetBrowser::applySelected() {
    QListWidgetItem* item = mList->currentItem();
    if (!item || mTarget.isEmpty()) return false;
    try {
        mDocument.applyPreset(mTarget.toStdString(), item->data(kPathRole).toString());
        Q_EMIT status(tr("Applied %1 to %2").arg(item->text(), mTarget), 4000);
        return true;
    } catch (...) {
        Q_EMIT failed(QString::fromStdString(
            doc::describeError(std::current_exception(), mTarget.toStdString()).message));
        return false;
    }
}

bool PresetBrowser::saveTargetAs(const QString& path) {
    try {
        mDocument.saveSpeciesAs(mTarget.toStdString(), path);
        Q_EMIT status(tr("Saved %1 as %2").arg(mTarget, QDir::toNativeSeparators(path)), 4000);
        refresh();
        return true;
    } catch (...) {
        Q_EMIT failed(QString::fromStdString(
            doc::describeError(std::current_exception(), path.toStdString()).message));
        return false;
    }
}

} // namespace sylva::ui
