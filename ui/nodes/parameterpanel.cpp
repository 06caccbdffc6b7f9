#include "ui/nodes/parameterpanel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "document/errormessage.h"
#include "engine/growth/envelope.h"
#include "ui/nodes/curveeditor.h"

namespace sylva::ui {

using graph::ParamKind;
using graph::ParamSpec;
using sylva::Value;

namespace {

/// A profile's points from a Value: a list of [t, value] pairs, or a Weber-Penn shape name.
std::vector<QPointF> profilePoints(const Value* v) {
    std::vector<QPointF> points;
    if (!v) return points;
    try {
        if (v->isString()) {
            for (const glm::vec2& q : growth::Envelope::weberPennProfile(v->toString()))
                points.emplace_back(q.x, q.y);
            return points;
        }
        for (const Value& pair : v->toArray("profile")) {
            const Value::Array& a = pair.toArray("profile point");
            if (a.size() == 2) points.emplace_back(a[0].toNumber("t"), a[1].toNumber("value"));
        }
    } catch (...) {
        points.clear(); // not a profile the curve can show: the JSON above still can
    }
    return points;
}

Value profileValue(const std::vector<QPointF>& points) {
    Value::Array list;
    for (const QPointF& p : points)
        list.push_back(Value(Value::Array{Value(p.x()), Value(p.y())}));
    return Value(std::move(list));
}

/// A Weber-Penn shape sampled at 9 heights: few enough points to drag.
std::vector<QPointF> sampledShape(const std::string& name) {
    const std::vector<glm::vec2> dense = growth::Envelope::weberPennProfile(name);
    std::vector<QPointF> points;
    for (int k = 0; k <= 8; ++k) {
        const float t = float(k) / 8.0f;
        auto hi = std::lower_bound(dense.begin(), dense.end(), t,
                                   [](const glm::vec2& q, float x) { return q.x < x; });
        float v = dense.back().y;
        if (hi == dense.begin())
            v = dense.front().y;
        else if (hi != dense.end()) {
            const glm::vec2 a = *(hi - 1), b = *hi;
            v = b.x > a.x ? a.y + (b.y - a.y) * (t - a.x) / (b.x - a.x) : b.y;
        }
        points.emplace_back(t, std::round(double(v) * 1000.0) / 1000.0);
    }
    return points;
}

/// \p envelope as a profile envelope of the same place and size (a sphere of radius r becomes a
/// profile 2r high from its bottom), with \p points as its profile.
Value asProfileEnvelope(const Value& envelope, const std::vector<QPointF>& points) {
    Value::Object o = envelope.isObject() ? envelope.toObject() : Value::Object{};
    const std::string shape = envelope.isObject() ? envelope.string("shape", "sphere") : "sphere";
    auto vec = [&](const char* key, glm::dvec3 fallback) {
        const Value* v = envelope.isObject() ? envelope.find(key) : nullptr;
        if (v && v->isArray() && v->toArray().size() == 3) {
            const Value::Array& a = v->toArray();
            return glm::dvec3(a[0].toNumber(), a[1].toNumber(), a[2].toNumber());
        }
        return fallback;
    };
    auto num = [&](const char* key, double fallback) {
        return envelope.isObject() ? envelope.number(key, fallback) : fallback;
    };
    glm::dvec3 base = vec("center", {0, 6, 0});
    double radius = 3.0, height = 6.0;
    if (shape == "sphere") {
        radius = num("radius", 4.5);
        base.y -= radius;
        height = 2.0 * radius;
    } else if (shape == "ellipsoid") {
        const glm::dvec3 radii = vec("radii", {4, 3, 4});
        radius = std::max(radii.x, radii.z);
        base.y -= radii.y;
        height = 2.0 * radii.y;
    } else if (shape == "hemisphere") {
        radius = num("radius", 4.5);
        height = radius;
    } else if (shape == "cone" || shape == "cylinder" || shape == "profile") {
        radius = num("radius", shape == "cylinder" ? 2.0 : 3.0);
        height = num("height", 6.0);
    } else { // a mesh: a profile of the default size where the crown usually is
        base = {0, 2, 0};
    }
    auto round3 = [](double v) { return std::round(v * 1000.0) / 1000.0; };
    return Value(Value::Object{
        {"shape", Value("profile")},
        {"center",
         Value(Value::Array{Value(round3(base.x)), Value(round3(base.y)), Value(round3(base.z))})},
        {"radius", Value(round3(radius))},
        {"height", Value(round3(height))},
        {"profile", profileValue(points)}});
}

double clampRange(double v) {
    return std::clamp(v, -1e9, 1e9);
}

int decimalsFor(const ParamSpec& s) {
    const double span = clampRange(s.max) - clampRange(s.min);
    if (span <= 2.0) return 4;
    if (span <= 200.0) return 3;
    return 2;
}

double numberOr(const Value& v, double fallback) {
    return v.isNumber() ? v.toNumber() : fallback;
}

} // namespace

ParameterPanel::ParameterPanel(doc::Document& document, QWidget* parent)
    : QWidget(parent), mDocument(document) {
    mLayout = new QVBoxLayout(this);
    mLayout->setContentsMargins(6, 6, 6, 6);
    mHeader = new QLabel(this);
    mHeader->setWordWrap(true);
    mHeader->setTextFormat(Qt::RichText);
    mLayout->addWidget(mHeader);
    mError = new QLabel(this);
    mError->setObjectName(QStringLiteral("parameterError"));
    mError->setWordWrap(true);
    mError->setStyleSheet(QStringLiteral("color: #e05050"));
    mError->hide();
    mLayout->addWidget(mError);
    connect(&mDocument, &doc::Document::changed, this, [this](const doc::DocumentChange& c) {
        if (mApplying) return;
        if (c.what & doc::DocumentChange::Reset) {
            setNode({}, {});
            return;
        }
        if ((c.what & doc::DocumentChange::Species) &&
            (c.species.isEmpty() || c.species == mSpecies))
            refreshValues();
    });
    rebuild();
}

QWidget* ParameterPanel::editor(const QString& param) const {
    const auto it = mEditors.find(param.toStdString());
    return it == mEditors.end() ? nullptr : it->second;
}

QString ParameterPanel::errorText() const {
    return mError->isVisible() ? mError->text() : QString();
}

void ParameterPanel::setNode(const QString& species, const QString& node) {
    if (species == mSpecies && node == mNode) return;
    mSpecies = species;
    mNode = node;
    rebuild();
}

bool ParameterPanel::apply(const std::string& param, const Value& value, bool commit) {
    mApplying = true;
    bool ok = true;
    try {
        mDocument.setParam(mSpecies.toStdString(), mNode.toStdString() + "." + param, value,
                           commit);
        mError->hide();
    } catch (...) {
        mError->setText(QString::fromStdString(
            doc::describeError(std::current_exception(), mSpecies.toStdString()).message));
        mError->show();
        ok = false;
    }
    mApplying = false;
    refreshValues(); // a refused value springs back to the document's
    return ok;
}

void ParameterPanel::rebuild() {
    if (mBody) {
        // Later: this may run inside one of its editors' signals.
        mBody->hide();
        mLayout->removeWidget(mBody);
        mBody->deleteLater();
        mBody = nullptr;
    }
    mEditors.clear();
    mShow.clear();
    mResetButtons.clear();
    mError->hide();
    std::string type;
    if (!mSpecies.isEmpty() && !mNode.isEmpty()) {
        try {
            const Value g = mDocument.speciesGraph(mSpecies.toStdString());
            for (const Value& n : g.toObject().at("nodes").toArray())
                if (n.string("id", "") == mNode.toStdString()) type = n.string("type", "");
        } catch (...) {
        }
    }
    graph::registerBuiltinNodeTypes();
    const graph::NodeType* t = graph::NodeRegistry::instance().find(type);
    if (!t) {
        mHeader->setText(tr("<i>Select a node in the species graph to edit its parameters.</i>"));
        return;
    }
    mHeader->setText(tr("<b>%1</b> — %2<br><small>%3</small>")
                         .arg(mNode.toHtmlEscaped(), QString::fromStdString(type),
                              QString::fromStdString(t->doc).toHtmlEscaped()));
    mBody = new QWidget(this);
    auto* bodyLayout = new QVBoxLayout(mBody);
    bodyLayout->setContentsMargins(0, 0, 0, 0);
    QGroupBox* group = nullptr;
    QFormLayout* form = nullptr;
    for (const ParamSpec& spec : t->params) {
        if (!group || group->title() != QString::fromStdString(spec.group)) {
            group = new QGroupBox(QString::fromStdString(spec.group), mBody);
            form = new QFormLayout(group);
            form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
            // A narrow dock puts long names above their editors instead of cutting them off.
            form->setRowWrapPolicy(QFormLayout::WrapLongRows);
            bodyLayout->addWidget(group);
        }
        QWidget* editor = makeEditor(spec);
        editor->setObjectName(QStringLiteral("param_") + QString::fromStdString(spec.name));
        mEditors[spec.name] = editor;
        const QString range = QString::fromStdString(spec.rangeText());
        const QString tip =
            tr("%1\n%2 · default %3%4")
                .arg(QString::fromStdString(spec.doc), QString::fromStdString(spec.name),
                     spec.defaultValue.isNull()
                         ? tr("unset")
                         : QString::fromStdString(spec.defaultValue.toJson()),
                     range.isEmpty() ? QString() : tr(" · range %1").arg(range));
        editor->setToolTip(tip);
        auto* row = new QWidget(group);
        auto* rowLayout = new QHBoxLayout(row);
        rowLayout->setContentsMargins(0, 0, 0, 0);
        rowLayout->addWidget(editor, 1);
        auto* reset = new QToolButton(row);
        reset->setText(QStringLiteral("↺"));
        reset->setObjectName(QStringLiteral("reset_") + QString::fromStdString(spec.name));
        reset->setToolTip(tr("Reset %1 to its default (%2)")
                              .arg(QString::fromStdString(spec.name),
                                   spec.defaultValue.isNull()
                                       ? tr("unset")
                                       : QString::fromStdString(spec.defaultValue.toJson())));
        const std::string name = spec.name;
        connect(reset, &QToolButton::clicked, this, [this, name] { apply(name, Value()); });
        rowLayout->addWidget(reset);
        mResetButtons[spec.name] = reset;
        // "Leaf scale (m)"; the tooltip names leaf_scale, what Python and files call it.
        QString label = QString::fromStdString(spec.label());
        if (!spec.unit.empty())
            label += QStringLiteral(" (%1)").arg(QString::fromStdString(spec.unit));
        auto* labelWidget = new QLabel(label, group);
        labelWidget->setToolTip(tip);
        form->addRow(labelWidget, row);
    }
    bodyLayout->addStretch(1);
    mLayout->addWidget(mBody, 1);
    mBody->show();
    refreshValues();
}

void ParameterPanel::refreshValues() {
    if (mSpecies.isEmpty() || mNode.isEmpty() || mEditors.empty()) return;
    Value params;
    try {
        const Value g = mDocument.speciesGraph(mSpecies.toStdString());
        bool found = false;
        for (const Value& n : g.toObject().at("nodes").toArray())
            if (n.string("id", "") == mNode.toStdString()) {
                found = true;
                if (const Value* p = n.find("params")) params = *p;
            }
        if (!found) {
            // The node was deleted (or renamed away by undo).
            mNode.clear();
            rebuild();
            return;
        }
    } catch (...) {
        return;
    }
    for (const auto& [name, show] : mShow) {
        const Value* v = params.find(name);
        show(v ? *v : Value());
        if (QWidget* reset = mResetButtons[name]) reset->setEnabled(v != nullptr);
    }
}

void ParameterPanel::addProfileEditor(const ParamSpec& spec, QWidget* box, QVBoxLayout* layout,
                                      QPlainTextEdit* json) {
    const std::string name = spec.name;
    const bool envelope = spec.kind != ParamKind::Curve;
    auto* curve = new CurveEditor(box);
    curve->setObjectName(QStringLiteral("curve"));
    auto current = std::make_shared<Value>();
    if (envelope) {
        // A crown envelope: its profile drawn as the crown it makes, and the Weber-Penn shapes to
        // start from (any envelope becomes a profile of the same place and size).
        curve->setOrientation(CurveEditor::Orientation::Silhouette);
        curve->setAxisLabels(tr("height, base → top"), tr("radius (× the envelope radius)"));
        auto* row = new QHBoxLayout;
        row->addWidget(new QLabel(tr("Crown profile:"), box));
        auto* shapes = new QComboBox(box);
        shapes->setObjectName(QStringLiteral("profileShape"));
        shapes->setToolTip(tr("Make the envelope a profile (a solid of revolution you can "
                              "draw), starting from one of Weber and Penn's crown shapes"));
        shapes->addItem(tr("start from a shape…"));
        const std::pair<const char*, QString> names[] = {
            {"conical", tr("conical")},
            {"spherical", tr("spherical")},
            {"hemispherical", tr("hemispherical")},
            {"cylindrical", tr("cylindrical")},
            {"tapered_cylindrical", tr("tapered cylindrical")},
            {"flame", tr("flame")},
            {"inverse_conical", tr("inverse conical")},
            {"tend_flame", tr("tend flame")}};
        for (const auto& [id, label] : names)
            shapes->addItem(label, QString::fromLatin1(id));
        row->addWidget(shapes, 1);
        layout->addLayout(row);
        connect(shapes, &QComboBox::activated, this, [this, name, shapes, current](int index) {
            if (index <= 0) return;
            const std::string shape = shapes->itemData(index).toString().toStdString();
            shapes->setCurrentIndex(0);
            apply(name, asProfileEnvelope(*current, sampledShape(shape)));
        });
    } else {
        curve->setAxisLabels(tr("t"), tr("value"));
    }
    layout->addWidget(curve);
    auto* hint =
        new QLabel(tr("Drag points; double-click adds one; right-click removes one."), box);
    hint->setWordWrap(true);
    hint->setStyleSheet(QStringLiteral("color: gray;"));
    layout->addWidget(hint);
    connect(curve, &CurveEditor::edited, this, [this, name, curve, current, envelope](bool final) {
        if (!envelope) {
            apply(name, profileValue(curve->points()), final);
            return;
        }
        Value v = *current;
        if (!v.isObject() || v.string("shape", "") != "profile") {
            v = asProfileEnvelope(v, curve->points());
        } else {
            v.objectRef()["profile"] = profileValue(curve->points());
        }
        apply(name, v, final);
    });
    mShow[name] = [json, curve, hint, current, envelope](const Value& v) {
        *current = v;
        if (!json->hasFocus())
            json->setPlainText(v.isNull() ? QString() : QString::fromStdString(v.toJson()));
        std::vector<QPointF> points;
        if (!envelope)
            points = profilePoints(&v);
        else if (v.isObject() && v.string("shape", "") == "profile")
            points = profilePoints(v.find("profile"));
        curve->setVisible(!points.empty() || !envelope);
        hint->setVisible(curve->isVisible());
        if (!points.empty()) curve->setPoints(std::move(points));
    };
}

QWidget* ParameterPanel::makeEditor(const ParamSpec& spec) {
    const std::string name = spec.name;
    const Value def = spec.defaultValue;
    switch (spec.kind) {
    case ParamKind::Number: {
        auto* w = new QWidget;
        auto* l = new QHBoxLayout(w);
        l->setContentsMargins(0, 0, 0, 0);
        auto* spin = new QDoubleSpinBox(w);
        spin->setObjectName(QStringLiteral("spin"));
        spin->setDecimals(decimalsFor(spec));
        spin->setRange(clampRange(spec.min), clampRange(spec.max));
        // Without a default the node takes the value from elsewhere (the grammar's header):
        // one step below the range reads "unset" and choosing it unsets the parameter.
        const bool unsettable = def.isNull();
        if (unsettable) {
            spin->setMinimum(clampRange(spec.min) - spin->singleStep());
            spin->setSpecialValueText(tr("unset"));
        }
        spin->setKeyboardTracking(false);
        spin->setMinimumWidth(80);
        l->addWidget(spin);
        QSlider* slider = nullptr;
        const double lo = clampRange(spec.min), hi = clampRange(spec.max);
        if (hi - lo <= 1e4 && hi > lo) {
            slider = new QSlider(Qt::Horizontal, w);
            slider->setObjectName(QStringLiteral("slider"));
            slider->setRange(0, 1000);
            slider->setMinimumWidth(50);
            l->addWidget(slider, 1);
            auto toValue = [lo, hi](int s) { return lo + (hi - lo) * s / 1000.0; };
            // A drag is one undo step: uncommitted while the handle moves, committed on release.
            connect(slider, &QSlider::valueChanged, this, [this, name, slider, toValue](int s) {
                if (slider->isSliderDown()) apply(name, Value(toValue(s)), false);
            });
            connect(slider, &QSlider::sliderReleased, this, [this, name, slider, toValue] {
                apply(name, Value(toValue(slider->value())), true);
            });
            connect(slider, &QSlider::actionTriggered, this, [this, name, slider, toValue](int a) {
                if (a != QAbstractSlider::SliderMove)
                    QMetaObject::invokeMethod(
                        this,
                        [this, name, slider, toValue] {
                            apply(name, Value(toValue(slider->value())), true);
                        },
                        Qt::QueuedConnection);
            });
        }
        connect(spin, &QDoubleSpinBox::valueChanged, this,
                [this, name, spin, unsettable](double v) {
                    apply(name, unsettable && v <= spin->minimum() ? Value() : Value(v));
                });
        mShow[name] = [spin, slider, def, lo, hi, unsettable](const Value& v) {
            const double x = numberOr(v, numberOr(def, unsettable ? spin->minimum() : lo));
            const QSignalBlocker b(spin);
            spin->setValue(x);
            QFont f = spin->font();
            f.setItalic(v.isNull());
            spin->setFont(f);
            if (slider && !slider->isSliderDown()) {
                const QSignalBlocker bs(slider);
                slider->setValue(int(std::lround((x - lo) / (hi - lo) * 1000.0)));
            }
        };
        return w;
    }
    case ParamKind::Integer: {
        auto* spin = new QSpinBox;
        spin->setRange(int(std::max(clampRange(spec.min), -2e9)),
                       int(std::min(clampRange(spec.max), 2e9)));
        spin->setKeyboardTracking(false);
        const bool unsettable = def.isNull();
        if (unsettable) {
            spin->setMinimum(spin->minimum() - 1);
            spin->setSpecialValueText(tr("unset"));
        }
        connect(spin, &QSpinBox::valueChanged, this, [this, name, spin, unsettable](int v) {
            apply(name, unsettable && v == spin->minimum() ? Value() : Value(v));
        });
        mShow[name] = [spin, def](const Value& v) {
            const QSignalBlocker b(spin);
            spin->setValue(int(numberOr(v, numberOr(def, spin->minimum()))));
            QFont f = spin->font();
            f.setItalic(v.isNull());
            spin->setFont(f);
        };
        return spin;
    }
    case ParamKind::Bool: {
        auto* box = new QCheckBox;
        connect(box, &QCheckBox::toggled, this, [this, name](bool on) { apply(name, Value(on)); });
        mShow[name] = [box, def](const Value& v) {
            const QSignalBlocker b(box);
            box->setChecked(v.isBool() ? v.toBool() : (def.isBool() && def.toBool()));
        };
        return box;
    }
    case ParamKind::Enum: {
        auto* combo = new QComboBox;
        for (const std::string& c : spec.choices)
            combo->addItem(QString::fromStdString(c));
        connect(combo, &QComboBox::activated, this, [this, name, combo](int) {
            apply(name, Value(combo->currentText().toStdString()));
        });
        mShow[name] = [combo, def](const Value& v) {
            const QSignalBlocker b(combo);
            combo->setCurrentText(QString::fromStdString(
                v.isString() ? v.toString() : (def.isString() ? def.toString() : std::string())));
        };
        return combo;
    }
    case ParamKind::Vector: {
        auto* w = new QWidget;
        auto* l = new QHBoxLayout(w);
        l->setContentsMargins(0, 0, 0, 0);
        std::vector<QDoubleSpinBox*> spins;
        for (int k = 0; k < 3; ++k) {
            auto* s = new QDoubleSpinBox(w);
            s->setObjectName(QStringLiteral("xyz").mid(k, 1));
            s->setDecimals(3);
            s->setRange(std::max(clampRange(spec.min), -1e6), std::min(clampRange(spec.max), 1e6));
            s->setKeyboardTracking(false);
            s->setPrefix(QStringLiteral("xyz").mid(k, 1) + QStringLiteral(" "));
            // Sized for the values people type, not for the widest of the range (±1e6 made
            // the panel scroll sideways): the three share the row.
            s->setMinimumWidth(64);
            s->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
            l->addWidget(s, 1);
            spins.push_back(s);
        }
        for (QDoubleSpinBox* s : spins)
            connect(s, &QDoubleSpinBox::valueChanged, this, [this, name, spins](double) {
                apply(name,
                      Value(Value::Array{spins[0]->value(), spins[1]->value(), spins[2]->value()}));
            });
        mShow[name] = [spins, def](const Value& v) {
            const Value& use = v.isArray() ? v : def;
            for (int k = 0; k < 3; ++k) {
                const QSignalBlocker b(spins[std::size_t(k)]);
                double x = 0.0;
                if (use.isArray() && use.toArray().size() == 3)
                    x = use.toArray()[std::size_t(k)].toNumber();
                else if (use.isNumber())
                    x = use.toNumber();
                spins[std::size_t(k)]->setValue(x);
            }
        };
        return w;
    }
    case ParamKind::File: {
        auto* w = new QWidget;
        auto* l = new QHBoxLayout(w);
        l->setContentsMargins(0, 0, 0, 0);
        auto* edit = new QLineEdit(w);
        edit->setPlaceholderText(tr("relative to the project"));
        auto* browse = new QToolButton(w);
        browse->setText(QStringLiteral("…"));
        l->addWidget(edit, 1);
        l->addWidget(browse);
        connect(edit, &QLineEdit::editingFinished, this, [this, name, edit] {
            apply(name, edit->text().isEmpty() ? Value() : Value(edit->text().toStdString()));
        });
        connect(browse, &QToolButton::clicked, this, [this, name] {
            const QString f = QFileDialog::getOpenFileName(this, tr("Choose a file"));
            if (!f.isEmpty()) apply(name, Value(f.toStdString()));
        });
        mShow[name] = [edit, w](const Value& v) {
            const QSignalBlocker b(edit);
            edit->setText(v.isString() ? QString::fromStdString(v.toString()) : QString());
            // A long path shows its end (the file's name) in the field: the whole path heads
            // the field's tooltip, above the parameter's explanation (the row's tooltip).
            edit->setToolTip(edit->text().isEmpty()
                                 ? QString()
                                 : QStringLiteral("%1\n\n%2").arg(edit->text(), w->toolTip()));
        };
        return w;
    }
    case ParamKind::Text: {
        auto* button = new QPushButton(tr("Edit in the grammar editor"));
        connect(button, &QPushButton::clicked, this,
                [this] { Q_EMIT editGrammarRequested(mSpecies, mNode); });
        mShow[name] = [button](const Value& v) {
            button->setText(
                v.isString()
                    ? tr("Edit in the grammar editor (%n lines)", nullptr,
                         int(std::count(v.toString().begin(), v.toString().end(), '\n')) + 1)
                    : tr("Edit in the grammar editor"));
        };
        return button;
    }
    case ParamKind::Curve:
    case ParamKind::Object: {
        auto* w = new QWidget;
        auto* l = new QVBoxLayout(w);
        l->setContentsMargins(0, 0, 0, 0);
        auto* edit = new QPlainTextEdit(w);
        edit->setObjectName(QStringLiteral("json"));
        edit->setMaximumHeight(70);
        edit->setPlaceholderText(tr("unset (JSON)"));
        auto* applyButton = new QPushButton(tr("Apply"), w);
        l->addWidget(edit);
        l->addWidget(applyButton, 0, Qt::AlignRight);
        connect(applyButton, &QPushButton::clicked, this, [this, name, edit] {
            const std::string text = edit->toPlainText().trimmed().toStdString();
            if (text.empty()) {
                apply(name, Value());
                return;
            }
            try {
                apply(name, Value::parseJson(text, name));
            } catch (...) {
                mError->setText(QString::fromStdString(
                    doc::describeError(std::current_exception(), name).message));
                mError->show();
            }
        });
        if (spec.kind == ParamKind::Curve || name == "envelope") {
            addProfileEditor(spec, w, l, edit);
            return w;
        }
        mShow[name] = [edit](const Value& v) {
            if (edit->hasFocus()) return;
            edit->setPlainText(v.isNull() ? QString() : QString::fromStdString(v.toJson()));
        };
        return w;
    }
    }
    return new QWidget;
}

} // namespace sylva::ui
