#pragma once

#include <vector>

#include <QPointF>
#include <QString>
#include <QWidget>

namespace sylva::ui {

/// A profile curve edited by hand: points (t, value), t from 0 to 1 in increasing order, value in
/// [0, 1], linear between them (as the engine reads profiles). Drag a point to move it (the first
/// and last keep t = 0 and t = 1), double-click to add one, right-click or Delete to remove a
/// point between them. In Silhouette orientation t runs upwards and the value sideways, mirrored,
/// so a crown profile looks like the crown it makes.
class CurveEditor : public QWidget {
    Q_OBJECT

public:
    enum class Orientation {
        Horizontal, ///< t to the right, value upwards
        Silhouette, ///< t upwards, value to both sides of a centre line
    };

    explicit CurveEditor(QWidget* parent = nullptr);

    /// Replaces the points (sorted by t; t and value clamped to [0, 1]). Ignored while the user
    /// drags a point, so the document echoing the drag does not fight the mouse.
    void setPoints(std::vector<QPointF> points);
    const std::vector<QPointF>& points() const { return mPoints; }
    void setOrientation(Orientation orientation);
    /// What t and the value mean, drawn along the axes.
    void setAxisLabels(const QString& t, const QString& value);
    bool isDragging() const { return mDragging; }
    /// The point selected by the last click (-1: none); Delete removes it.
    int selected() const { return mSelected; }
    /// Where a curve point is drawn (widget pixels): for tests and scripts.
    QPointF toScreen(const QPointF& point) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

Q_SIGNALS:
    /// The points changed by hand. \p final is false while a drag goes on and true when it ends,
    /// or when a point was added or removed: a drag is one undo step.
    void edited(bool final);

protected:
    bool event(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    QRectF plotRect() const;
    QPointF fromScreen(const QPointF& pixel) const;
    int pointAt(const QPointF& pixel) const;
    void moveSelected(const QPointF& pixel);
    bool removeSelected();

    std::vector<QPointF> mPoints;
    Orientation mOrientation = Orientation::Horizontal;
    QString mTLabel, mValueLabel;
    int mSelected = -1;
    bool mDragging = false;
    bool mMoved = false;
};

} // namespace sylva::ui
