#include "ui/nodes/curveeditor.h"

#include <algorithm>
#include <cmath>

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

namespace sylva::ui {

namespace {

constexpr double kGrab = 7.0;    ///< pixels: how close a press must be to take a point
constexpr double kMinGap = 0.01; ///< smallest t between neighbouring points

} // namespace

CurveEditor::CurveEditor(QWidget* parent) : QWidget(parent) {
    setFocusPolicy(Qt::ClickFocus);
    setMouseTracking(true);
    setToolTip(tr("Drag a point to shape the curve; double-click to add a point; right-click or "
                  "Delete removes one"));
    mPoints = {{0.0, 1.0}, {1.0, 1.0}};
}

void CurveEditor::setPoints(std::vector<QPointF> points) {
    if (mDragging) return;
    for (QPointF& p : points)
        p = {std::clamp(p.x(), 0.0, 1.0), std::clamp(p.y(), 0.0, 1.0)};
    std::stable_sort(points.begin(), points.end(),
                     [](const QPointF& a, const QPointF& b) { return a.x() < b.x(); });
    mPoints = std::move(points);
    if (mSelected >= int(mPoints.size())) mSelected = -1;
    update();
}

void CurveEditor::setOrientation(Orientation orientation) {
    mOrientation = orientation;
    update();
}

void CurveEditor::setAxisLabels(const QString& t, const QString& value) {
    mTLabel = t;
    mValueLabel = value;
    update();
}

QSize CurveEditor::sizeHint() const {
    return {220, 170};
}

QSize CurveEditor::minimumSizeHint() const {
    return {140, 110};
}

QRectF CurveEditor::plotRect() const {
    const QFontMetrics fm(font());
    // Room for the labels: the t axis below, the value axis on the left.
    return QRectF(rect()).adjusted(fm.height() + 10, 8, -10, -(fm.height() + 10));
}

QPointF CurveEditor::toScreen(const QPointF& p) const {
    const QRectF r = plotRect();
    if (mOrientation == Orientation::Silhouette)
        return {r.center().x() + p.y() * r.width() / 2.0, r.bottom() - p.x() * r.height()};
    return {r.left() + p.x() * r.width(), r.bottom() - p.y() * r.height()};
}

QPointF CurveEditor::fromScreen(const QPointF& s) const {
    const QRectF r = plotRect();
    if (mOrientation == Orientation::Silhouette)
        return {(r.bottom() - s.y()) / r.height(),
                std::abs(s.x() - r.center().x()) / (r.width() / 2.0)};
    return {(s.x() - r.left()) / r.width(), (r.bottom() - s.y()) / r.height()};
}

int CurveEditor::pointAt(const QPointF& pixel) const {
    int best = -1;
    double bestDistance = kGrab;
    for (int i = 0; i < int(mPoints.size()); ++i) {
        QPointF s = toScreen(mPoints[std::size_t(i)]);
        // A silhouette point can be taken on either side of the centre line.
        if (mOrientation == Orientation::Silhouette && pixel.x() < plotRect().center().x())
            s.setX(2.0 * plotRect().center().x() - s.x());
        const double d = std::hypot(s.x() - pixel.x(), s.y() - pixel.y());
        if (d <= bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    return best;
}

void CurveEditor::moveSelected(const QPointF& pixel) {
    if (mSelected < 0) return;
    const auto i = std::size_t(mSelected);
    QPointF p = fromScreen(pixel);
    double t = p.x();
    if (i == 0)
        t = 0.0;
    else if (i + 1 == mPoints.size())
        t = 1.0;
    else
        t = std::clamp(t, mPoints[i - 1].x() + kMinGap, mPoints[i + 1].x() - kMinGap);
    // Three decimals: what a person can place, and a clean file.
    auto round3 = [](double v) { return std::round(v * 1000.0) / 1000.0; };
    mPoints[i] = {round3(t), round3(std::clamp(p.y(), 0.0, 1.0))};
    update();
}

bool CurveEditor::removeSelected() {
    if (mSelected <= 0 || mSelected + 1 >= int(mPoints.size())) return false;
    mPoints.erase(mPoints.begin() + mSelected);
    mSelected = -1;
    update();
    Q_EMIT edited(true);
    return true;
}

void CurveEditor::mousePressEvent(QMouseEvent* event) {
    mSelected = pointAt(event->position());
    if (event->button() == Qt::RightButton) {
        removeSelected();
        return;
    }
    if (event->button() == Qt::LeftButton && mSelected >= 0) {
        mDragging = true;
        mMoved = false;
    }
    update();
}

void CurveEditor::mouseMoveEvent(QMouseEvent* event) {
    if (!mDragging) {
        setCursor(pointAt(event->position()) >= 0 ? Qt::SizeAllCursor : Qt::CrossCursor);
        return;
    }
    moveSelected(event->position());
    mMoved = true;
    Q_EMIT edited(false);
}

void CurveEditor::mouseReleaseEvent(QMouseEvent* event) {
    if (!mDragging || event->button() != Qt::LeftButton) return;
    mDragging = false;
    if (mMoved) {
        moveSelected(event->position());
        Q_EMIT edited(true);
    }
}

void CurveEditor::mouseDoubleClickEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton || pointAt(event->position()) >= 0) return;
    const QPointF p = fromScreen(event->position());
    if (p.x() <= 0.0 || p.x() >= 1.0) return;
    auto at = std::upper_bound(mPoints.begin(), mPoints.end(), p.x(),
                               [](double t, const QPointF& q) { return t < q.x(); });
    const double t = std::round(p.x() * 1000.0) / 1000.0;
    if ((at != mPoints.end() && at->x() - t < kMinGap) ||
        (at != mPoints.begin() && t - (at - 1)->x() < kMinGap))
        return;
    at = mPoints.insert(at, {t, std::round(std::clamp(p.y(), 0.0, 1.0) * 1000.0) / 1000.0});
    mSelected = int(at - mPoints.begin());
    update();
    Q_EMIT edited(true);
}

bool CurveEditor::event(QEvent* event) {
    // Delete removes the selected point here, not what the window's Delete shortcut removes.
    if (event->type() == QEvent::ShortcutOverride && mSelected >= 0) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Delete || key == Qt::Key_Backspace) {
            event->accept();
            return true;
        }
    }
    return QWidget::event(event);
}

void CurveEditor::keyPressEvent(QKeyEvent* event) {
    if ((event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) && removeSelected())
        return;
    QWidget::keyPressEvent(event);
}

void CurveEditor::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF r = plotRect();
    p.fillRect(rect(), palette().base());
    // Grid: quarters of both axes.
    p.setPen(QPen(palette().mid().color(), 1, Qt::DotLine));
    for (int k = 1; k < 4; ++k) {
        const double f = k / 4.0;
        p.drawLine(QPointF(r.left() + f * r.width(), r.top()),
                   QPointF(r.left() + f * r.width(), r.bottom()));
        p.drawLine(QPointF(r.left(), r.top() + f * r.height()),
                   QPointF(r.right(), r.top() + f * r.height()));
    }
    p.setPen(QPen(palette().text().color(), 1));
    p.drawRect(r);

    // The curve (and in Silhouette its mirror image, filled: the crown's outline).
    QPainterPath right;
    for (std::size_t i = 0; i < mPoints.size(); ++i) {
        const QPointF s = toScreen(mPoints[i]);
        if (i == 0)
            right.moveTo(s);
        else
            right.lineTo(s);
    }
    const QColor curve(70, 150, 70);
    if (mOrientation == Orientation::Silhouette) {
        QPainterPath outline;
        const double cx = r.center().x();
        outline.moveTo(cx, r.bottom());
        for (const QPointF& q : mPoints)
            outline.lineTo(toScreen(q));
        outline.lineTo(cx, r.top());
        for (auto it = mPoints.rbegin(); it != mPoints.rend(); ++it) {
            const QPointF s = toScreen(*it);
            outline.lineTo(2.0 * cx - s.x(), s.y());
        }
        outline.closeSubpath();
        p.fillPath(outline, QColor(70, 150, 70, 60));
        p.setPen(QPen(curve.lighter(130), 1.5, Qt::DashLine));
        QPainterPath mirror;
        for (std::size_t i = 0; i < mPoints.size(); ++i) {
            const QPointF s = toScreen(mPoints[i]);
            const QPointF m(2.0 * cx - s.x(), s.y());
            if (i == 0)
                mirror.moveTo(m);
            else
                mirror.lineTo(m);
        }
        p.drawPath(mirror);
        p.setPen(QPen(palette().mid().color(), 1));
        p.drawLine(QPointF(cx, r.top()), QPointF(cx, r.bottom()));
    }
    p.setPen(QPen(curve, 2));
    p.drawPath(right);
    for (int i = 0; i < int(mPoints.size()); ++i) {
        const QPointF s = toScreen(mPoints[std::size_t(i)]);
        p.setPen(QPen(palette().text().color(), 1));
        p.setBrush(i == mSelected ? QColor(255, 170, 40) : QColor(240, 240, 240));
        p.drawEllipse(s, 4.5, 4.5);
    }

    // Axis labels.
    p.setPen(palette().text().color());
    const QFontMetrics fm(font());
    const QString below = mOrientation == Orientation::Silhouette ? mValueLabel : mTLabel;
    const QString side = mOrientation == Orientation::Silhouette ? mTLabel : mValueLabel;
    p.drawText(QRectF(r.left(), r.bottom() + 4, r.width(), fm.height() + 2), Qt::AlignCenter,
               below);
    p.save();
    p.translate(r.left() - 6, r.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-r.height() / 2, -fm.height(), r.height(), fm.height()), Qt::AlignCenter,
               side);
    p.restore();
}

} // namespace sylva::ui
