#include "ui/document/propertiespanel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpressionValidator>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <cmath>
#include <memory>

#include "document/errormessage.h"
#include "document/projectsettings.h"
#include "ui/document/branchproperties.h"

namespace sylva::ui {

using Kind = doc::ItemRef::Kind;

PropertiesPanel::PropertiesPanel(doc::Document& document, QWidget* parent)
    : QWidget(parent), mDocument(document) {
    auto* layout = new QVBoxLayout(this);
    mTitle = new QLabel(this);
    mTitle->setObjectName(QStringLiteral("propertiesTitle"));
    QFont bold = mTitle->font();
    bold.setBold(true);
    mTitle->setFont(bold);
    layout->addWidget(mTitle);
    mBody = new QWidget(this);
    layout->addWidget(mBody);
    layout->addStretch(1);
    connect(&document, &doc::Document::selectionChanged, this, &PropertiesPanel::rebuild);
    connect(&document, &doc::Document::changed, this, [this](const doc::DocumentChange& c) {
        if (c.what & doc::DocumentChange::Reset)
            rebuild();
        else
            refresh();
    });
    rebuild();
}

int PropertiesPanel::addSetting(const doc::SettingSpec& spec) {
    QString unit = QString::fromUtf8(spec.unit);
    if (!unit.isEmpty() && unit != QStringLiteral("°")) unit.prepend(QLatin1Char(' '));
    return addSpins(spec.translatedLabel() + tr(":"), 1, spec.min, spec.max, spec.step,
                    spec.decimals, unit, spec.translatedHelp());
}

int PropertiesPanel::addSpins(const QString& label, int count, double lo, double hi, double step,
                              int decimals, const QString& suffix, const QString& tooltip) {
    auto* row = new QWidget(mBody);
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    const int first = int(mSpins.size());
    static const char* const kAxes[] = {"x", "y", "z"};
    for (int k = 0; k < count; ++k) {
        auto* box = new QDoubleSpinBox(row);
        box->setRange(lo, hi);
        box->setSingleStep(step);
        box->setDecimals(decimals);
        // Three boxes in a row leave no room for a unit in each (it was cut off): the row's
        // label carries it instead ("Position (m):").
        if (count == 1) box->setSuffix(suffix);
        box->setKeyboardTracking(false); // one edit per Enter, arrow click or focus change
        box->setAccelerated(true);
        // Narrow enough for three in a row in the dock; the value's width, not the range's.
        box->setMinimumWidth(56);
        box->setToolTip(count > 1 ? tooltip + QStringLiteral(" (%1)").arg(QLatin1String(kAxes[k]))
                                  : tooltip);
        box->setObjectName(QStringLiteral("spin%1").arg(first + k));
        h->addWidget(box);
        mSpins.push_back(box);
    }
    QString rowLabel = label;
    if (count > 1 && !suffix.trimmed().isEmpty() && rowLabel.endsWith(QLatin1Char(':')))
        rowLabel = tr("%1 (%2):").arg(rowLabel.chopped(1), suffix.trimmed());
    mForm->addRow(rowLabel, row);
    return first;
}

void PropertiesPanel::addSeasonCombo(const QString& unset, const QString& tooltip) {
    mSeason = new QComboBox(mBody);
    mSeason->setObjectName(QStringLiteral("seasonCombo"));
    mSeason->setToolTip(tooltip);
    mSeason->addItem(unset, QString());
    mSeason->addItem(tr("Spring"), QStringLiteral("spring"));
    mSeason->addItem(tr("Summer"), QStringLiteral("summer"));
    mSeason->addItem(tr("Autumn"), QStringLiteral("autumn"));
    mSeason->addItem(tr("Winter"), QStringLiteral("winter"));
    mForm->addRow(tr("Season:"), mSeason);
}

void PropertiesPanel::showSeason(const std::string& season) {
    const int i = mSeason->findData(QString::fromStdString(season));
    mSeason->setCurrentIndex(i < 0 ? 0 : i);
}

double PropertiesPanel::spin(int i) const {
    return mSpins[std::size_t(i)]->value();
}

glm::vec3 PropertiesPanel::vec3At(int first) const {
    return {float(spin(first)), float(spin(first + 1)), float(spin(first + 2))};
}

void PropertiesPanel::apply(const std::function<void()>& edit) {
    if (mUpdating) return;
    try {
        edit();
    } catch (...) {
        Q_EMIT failed(QString::fromStdString(doc::currentErrorMessage()));
        refresh(); // back to the document's value
    }
}

void PropertiesPanel::rebuild() {
    delete mBody;
    mBody = new QWidget(this);
    static_cast<QVBoxLayout*>(layout())->insertWidget(1, mBody);
    mForm = new QFormLayout(mBody);
    mForm->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    mSpins.clear();
    mSpecies = nullptr;
    mSeason = nullptr;
    mSeed = nullptr;
    mInfo = nullptr;
    mRefresh = nullptr;
    const QList<doc::ItemRef>& selection = mDocument.selection();
    mItem = selection.isEmpty() ? std::nullopt : std::optional<doc::ItemRef>(selection.last());
    const doc::Project& p = mDocument.project();
    auto connectAll = [this](int first, int count, const std::function<void()>& edit) {
        for (int k = first; k < first + count; ++k)
            connect(mSpins[std::size_t(k)], &QDoubleSpinBox::valueChanged, this,
                    [this, edit] { apply(edit); });
    };
    auto seedEditor = [this](const QString& tooltip) {
        mSeed = new QLineEdit(mBody);
        mSeed->setObjectName(QStringLiteral("seedEdit"));
        mSeed->setToolTip(tooltip);
        mSeed->setValidator(new QRegularExpressionValidator(
            QRegularExpression(QStringLiteral("[0-9]{1,19}")), mSeed));
        mForm->addRow(tr("Seed:"), mSeed);
    };

    if (!mItem) {
        mTitle->setText(tr("Project"));
        mInfo = new QLabel(mBody);
        mInfo->setWordWrap(true);
        mForm->addRow(tr("File:"), mInfo);
        seedEditor(tr("The project seed: domain trees take their seeds from it and their ids"));
        connect(mSeed, &QLineEdit::editingFinished, this,
                [this] { apply([this] { mDocument.setSeed(mSeed->text().toULongLong()); }); });
        addSeasonCombo(tr("Species' own (summer)"),
                       tr("The time of year of every tree without a season of its own: "
                          "deciduous species flush in spring, colour in autumn and are bare in "
                          "winter; conifers and evergreens stay as they are"));
        connect(mSeason, &QComboBox::currentIndexChanged, this, [this] {
            apply([this] { mDocument.setSeason(mSeason->currentData().toString().toStdString()); });
        });
        // The wind the viewport plays (View ▸ Wind) and wind exports use; the engine's
        // defaults shown until the project sets it. Each change is one "Change wind" step.
        namespace spec = doc::settings;
        const int windDir = addSetting(spec::kWindDirection);
        mSpins[std::size_t(windDir)]->setWrapping(true);
        const int windStrength = addSetting(spec::kWindStrength);
        const int windGust = addSetting(spec::kWindGustiness);
        const int windFrequency = addSetting(spec::kWindFrequency);
        mSpins[std::size_t(windDir)]->setObjectName(QStringLiteral("windDirection"));
        mSpins[std::size_t(windStrength)]->setObjectName(QStringLiteral("windStrength"));
        mSpins[std::size_t(windGust)]->setObjectName(QStringLiteral("windGustiness"));
        mSpins[std::size_t(windFrequency)]->setObjectName(QStringLiteral("windFrequency"));
        auto windEdit = [this](int spinIndex,
                               std::function<void(wind::WindSettings&, double)> set) {
            connect(mSpins[std::size_t(spinIndex)], &QDoubleSpinBox::valueChanged, this,
                    [this, set](double value) {
                        apply([this, set, value] {
                            wind::WindSettings w =
                                mDocument.project().wind.value_or(wind::WindSettings{});
                            set(w, value);
                            mDocument.setWind(w);
                        });
                    });
        };
        windEdit(windDir, [](wind::WindSettings& w, double degrees) {
            const double a = degrees * 3.14159265358979323846 / 180.0;
            // Whole numbers where the angle is a right one, not 6e-17 in the file.
            auto clean = [](double v) { return std::abs(v) < 1e-7 ? 0.0f : float(v); };
            w.direction = {clean(std::cos(a)), 0.0f, clean(std::sin(a))};
        });
        windEdit(windStrength, [](wind::WindSettings& w, double v) { w.strength = float(v); });
        windEdit(windGust, [](wind::WindSettings& w, double v) { w.gustiness = float(v); });
        windEdit(windFrequency, [](wind::WindSettings& w, double v) { w.frequency = float(v); });
        mRefresh = [this, windDir, windStrength, windGust, windFrequency] {
            mInfo->setText(mDocument.path().isEmpty() ? tr("not saved yet") : mDocument.path());
            mSeed->setText(QString::number(mDocument.project().seed));
            showSeason(mDocument.project().season);
            const wind::WindSettings w = mDocument.project().wind.value_or(wind::WindSettings{});
            double degrees = std::atan2(double(w.direction.z), double(w.direction.x)) * 180.0 /
                             3.14159265358979323846;
            if (degrees < 0.0) degrees += 360.0;
            mSpins[std::size_t(windDir)]->setValue(degrees);
            mSpins[std::size_t(windStrength)]->setValue(w.strength);
            mSpins[std::size_t(windGust)]->setValue(w.gustiness);
            mSpins[std::size_t(windFrequency)]->setValue(w.frequency);
        };
    } else if (mItem->kind == Kind::Tree) {
        const doc::TreeId id = mItem->id;
        mTitle->setText(tr("Tree #%1").arg(id));
        mSpecies = new QComboBox(mBody);
        mSpecies->setObjectName(QStringLiteral("speciesCombo"));
        for (const doc::ProjectSpecies& s : p.species)
            mSpecies->addItem(QString::fromStdString(s.name));
        mForm->addRow(tr("Species:"), mSpecies);
        const int pos = addSpins(tr("Position:"), 3, -1e5, 1e5, 0.5, 2, tr(" m"),
                                 tr("Where the trunk meets the ground, metres"));
        const int rot = addSpins(tr("Rotation:"), 1, -3600, 3600, 15, 1, tr("°"),
                                 tr("Turn about the vertical axis, degrees"));
        const int scale = addSpins(tr("Scale:"), 1, 0.01, 100, 0.05, 3, {},
                                   tr("Uniform size factor, 0.01 to 100"));
        const int growth = addSpins(tr("Growth:"), 1, 0.01, 1, 0.05, 2, {},
                                    tr("Growth stage, 0.01 (sapling) to 1 (mature)"));
        seedEditor(tr("The tree's own seed: another seed grows another tree of the species"));
        addSeasonCombo(tr("Project's season"),
                       tr("This tree's own time of year, or the project's season"));
        auto edit = [this, id, pos, rot, scale, growth] {
            doc::ProjectInstance t = mDocument.tree(id);
            t.species = mSpecies->currentText().toStdString();
            t.position = vec3At(pos);
            t.rotation = spin(rot);
            t.scale = spin(scale);
            t.growth = spin(growth);
            t.seed = mSeed->text().toULongLong();
            t.season = mSeason->currentData().toString().toStdString();
            mDocument.setTree(id, t);
        };
        connectAll(0, int(mSpins.size()), edit);
        connect(mSpecies, &QComboBox::currentIndexChanged, this, [this, edit] { apply(edit); });
        connect(mSeason, &QComboBox::currentIndexChanged, this, [this, edit] { apply(edit); });
        connect(mSeed, &QLineEdit::editingFinished, this, [this, edit] { apply(edit); });
        // The Branch tool's selected branch of this tree: its own settings below the tree's.
        BranchProperties* branch = nullptr;
        if (const auto& b = mDocument.selectedBranch(); b && b->tree == id && mResult) {
            branch = new BranchProperties(mDocument, *b, mResult, mBody);
            connect(branch, &BranchProperties::failed, this, &PropertiesPanel::failed);
            mForm->addRow(branch);
        }
        mRefresh = [this, id, pos, rot, scale, growth, branch] {
            if (mDocument.treeIndex(id) < 0) return;
            if (branch) branch->refresh();
            const doc::ProjectInstance& t = mDocument.tree(id);
            mSpecies->setCurrentText(QString::fromStdString(t.species));
            for (int k = 0; k < 3; ++k)
                mSpins[std::size_t(pos + k)]->setValue(t.position[k]);
            mSpins[std::size_t(rot)]->setValue(t.rotation);
            mSpins[std::size_t(scale)]->setValue(t.scale);
            mSpins[std::size_t(growth)]->setValue(t.growth);
            mSeed->setText(QString::number(t.seed));
            showSeason(t.season);
        };
    } else if (mItem->kind == Kind::Obstacle) {
        const int i = int(mItem->id);
        mTitle->setText(tr("Obstacle %1").arg(i + 1));
        mInfo = new QLabel(mBody);
        mInfo->setWordWrap(true);
        mForm->addRow(tr("Mesh:"), mInfo);
        const int t = addSpins(tr("Translate:"), 3, -1e5, 1e5, 0.5, 2, tr(" m"),
                               tr("Moves the mesh, metres"));
        const int r = addSpins(tr("Rotate:"), 3, -360, 360, 5, 1, tr("°"),
                               tr("Rotation about x, then y, then z, degrees"));
        const int s = addSpins(tr("Scale:"), 3, 1e-4, 1e4, 0.1, 3, {}, tr("Scale per axis"));
        connectAll(0, 9, [this, i, t, r, s] {
            doc::ProjectObstacle o = mDocument.project().obstacles[std::size_t(i)];
            o.translate = vec3At(t);
            o.rotate = vec3At(r);
            o.scale = vec3At(s);
            mDocument.setObstacle(i, o);
        });
        mRefresh = [this, i, t, r, s] {
            if (i >= int(mDocument.project().obstacles.size())) return;
            const doc::ProjectObstacle& o = mDocument.project().obstacles[std::size_t(i)];
            mInfo->setText(QString::fromStdString(o.file));
            for (int k = 0; k < 3; ++k) {
                mSpins[std::size_t(t + k)]->setValue(o.translate[k]);
                mSpins[std::size_t(r + k)]->setValue(o.rotate[k]);
                mSpins[std::size_t(s + k)]->setValue(o.scale[k]);
            }
        };
    } else if (mItem->kind == Kind::Domain) {
        const int i = int(mItem->id);
        const doc::PlacementDomain& d = p.domains[std::size_t(i)];
        mTitle->setText(tr("Domain %1 (%2)").arg(i + 1).arg(QString::fromStdString(d.shape)));
        int lo = -1, hi = -1;
        if (d.shape == "rectangle") {
            lo = addSpins(tr("Minimum x, z:"), 2, -1e5, 1e5, 1, 1, tr(" m"),
                          tr("Corner of the rectangle on the ground"));
            hi = addSpins(tr("Maximum x, z:"), 2, -1e5, 1e5, 1, 1, tr(" m"),
                          tr("Opposite corner of the rectangle"));
        }
        const int counts = int(mSpins.size());
        std::vector<std::string> names;
        for (const doc::ProjectSpecies& s : p.species) {
            addSpins(tr("%1 trees:").arg(QString::fromStdString(s.name)), 1, 0, 1e6, 1, 0, {},
                     tr("How many trees of this species the domain scatters"));
            names.push_back(s.name);
        }
        connectAll(0, int(mSpins.size()), [this, i, lo, hi, counts, names] {
            doc::PlacementDomain dom = mDocument.project().domains[std::size_t(i)];
            if (lo >= 0) {
                dom.min = {float(spin(lo)), float(spin(lo + 1))};
                dom.max = {float(spin(hi)), float(spin(hi + 1))};
            }
            for (std::size_t k = 0; k < names.size(); ++k) {
                const int n = int(spin(counts + int(k)));
                if (n > 0)
                    dom.counts[names[k]] = n;
                else
                    dom.counts.erase(names[k]);
            }
            mDocument.setDomain(i, dom);
        });
        mRefresh = [this, i, lo, hi, counts, names] {
            if (i >= int(mDocument.project().domains.size())) return;
            const doc::PlacementDomain& dom = mDocument.project().domains[std::size_t(i)];
            if (lo >= 0) {
                mSpins[std::size_t(lo)]->setValue(dom.min.x);
                mSpins[std::size_t(lo + 1)]->setValue(dom.min.y);
                mSpins[std::size_t(hi)]->setValue(dom.max.x);
                mSpins[std::size_t(hi + 1)]->setValue(dom.max.y);
            }
            for (std::size_t k = 0; k < names.size(); ++k) {
                auto it = dom.counts.find(names[k]);
                mSpins[std::size_t(counts) + k]->setValue(it == dom.counts.end() ? 0 : it->second);
            }
        };
    } else if (mItem->kind == Kind::Camera) {
        mTitle->setText(tr("Camera"));
        const int pos = addSpins(tr("Position:"), 3, -1e5, 1e5, 1, 2, tr(" m"),
                                 tr("Where the camera stands: the reference for level of detail"));
        const int target = addSpins(tr("Target:"), 3, -1e5, 1e5, 1, 2, tr(" m"),
                                    tr("The point the camera looks at"));
        connectAll(0, 6, [this, pos, target] { mDocument.setCamera(vec3At(pos), vec3At(target)); });
        mRefresh = [this, pos, target] {
            for (int k = 0; k < 3; ++k) {
                mSpins[std::size_t(pos + k)]->setValue(mDocument.project().cameraPosition[k]);
                mSpins[std::size_t(target + k)]->setValue(mDocument.project().cameraTarget[k]);
            }
        };
    } else if (mItem->kind == Kind::Light) {
        mTitle->setText(tr("Light"));
        const int dir = addSpins(tr("Direction:"), 3, -1, 1, 0.05, 3, {},
                                 tr("The direction sunlight travels (towards the ground: y < 0); "
                                    "trees grow towards where it comes from"));
        connectAll(0, 3, [this, dir] { mDocument.setLight(vec3At(dir)); });
        mRefresh = [this, dir] {
            for (int k = 0; k < 3; ++k)
                mSpins[std::size_t(dir + k)]->setValue(mDocument.project().lightDirection[k]);
        };
    } else if (mItem->kind == Kind::Species) {
        const int i = int(mItem->id);
        mTitle->setText(tr("Species"));
        mInfo = new QLabel(mBody);
        mInfo->setWordWrap(true);
        mInfo->setTextInteractionFlags(Qt::TextSelectableByMouse);
        mForm->addRow(mInfo);
        // K (issue 30): how many different trees of the species a forest repeats.
        const int variants = addSetting(doc::settings::kVariants);
        mSpins[std::size_t(variants)]->setSpecialValueText(tr("0 (every tree unique)"));
        connectAll(variants, 1, [this, i, variants] {
            if (i >= int(mDocument.project().species.size())) return;
            mDocument.setSpeciesVariants(mDocument.project().species[std::size_t(i)].name,
                                         int(spin(variants)));
        });
        mRefresh = [this, i, variants] {
            if (i >= int(mDocument.project().species.size())) return;
            const doc::ProjectSpecies& s = mDocument.project().species[std::size_t(i)];
            mSpins[std::size_t(variants)]->setValue(s.variants);
            int trees = 0;
            for (const doc::ProjectInstance& t : mDocument.project().instances)
                trees += t.species == s.name ? 1 : 0;
            mInfo->setText(
                tr("<b>%1</b><br>%2<br>%3 hand-placed tree(s). Rename it in the outliner; "
                   "tune its graph and parameters in the Species Editor (Scene ▸ Edit "
                   "species…, Ctrl+Shift+E).")
                    .arg(QString::fromStdString(s.name).toHtmlEscaped(),
                         s.file.empty()
                             ? tr("Stored in the project.")
                             : tr("From %1 (stored in the project after its first edit).")
                                   .arg(QString::fromStdString(s.file).toHtmlEscaped()))
                    .arg(trees));
        };
    }
    // Shown now, not by the layout's queued show, so that the size the scroll area gives the
    // panel counts the new rows: otherwise they were squeezed into the old page's height.
    mBody->show();
    updateGeometry();
    refresh();
}

void PropertiesPanel::refresh() {
    if (!mRefresh) return;
    mUpdating = true;
    std::vector<std::unique_ptr<QSignalBlocker>> blockers;
    for (QDoubleSpinBox* box : mSpins)
        blockers.push_back(std::make_unique<QSignalBlocker>(box));
    if (mSpecies) blockers.push_back(std::make_unique<QSignalBlocker>(mSpecies));
    if (mSeason) blockers.push_back(std::make_unique<QSignalBlocker>(mSeason));
    if (mSeed) blockers.push_back(std::make_unique<QSignalBlocker>(mSeed));
    mRefresh();
    mUpdating = false;
}

} // namespace sylva::ui
