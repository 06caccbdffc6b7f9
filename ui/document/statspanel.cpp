#include "ui/document/statspanel.h"

#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QVBoxLayout>

#include "document/document.h"
#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "ui/generation/treegenerator.h"

namespace sylva::ui {

StatsPanel::StatsPanel(QWidget* parent) : QWidget(parent) {
    auto* outer = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    outer->addLayout(form);
    outer->addStretch(1);
    setLayout(outer);

    auto add = [&](const QString& label, const QString& name) {
        auto* value = new QLabel(QStringLiteral("–"), this);
        value->setObjectName(name);
        value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        form->addRow(label, value);
        return value;
    };
    mSpecies = add(tr("Showing:"), QStringLiteral("statSpecies"));
    mSpecies->setToolTip(tr("The species previewed, or the project and its tree count"));
    mSpecies->setWordWrap(true);
    mFile = add(tr("File:"), QStringLiteral("statFile"));
    mTrees = add(tr("Trees:"), QStringLiteral("statTrees"));
    mVertices = add(tr("Vertices:"), QStringLiteral("statVertices"));
    mTriangles = add(tr("Triangles:"), QStringLiteral("statTriangles"));
    mSegments = add(tr("Segments:"), QStringLiteral("statSegments"));
    mLeaves = add(tr("Leaves:"), QStringLiteral("statLeaves"));
    mHeight = add(tr("Height:"), QStringLiteral("statHeight"));
    mTime = add(tr("Generation time:"), QStringLiteral("statTime"));
    mCo2 = add(tr("CO₂ stored:"), QStringLiteral("statCo2"));
    mWood = add(tr("Wood, biomass:"), QStringLiteral("statWood"));
    mWood->setToolTip(tr("A project's wood volume and dry biomass, and the trees' mean DBH"));
    mSelection = add(tr("Selection:"), QStringLiteral("statSelection"));
    mSelection->setWordWrap(true);

    mStatus = new QLabel(this);
    mStatus->setObjectName(QStringLiteral("statStatus"));
    mStatus->setWordWrap(true);
    mStatus->setTextInteractionFlags(Qt::TextSelectableByMouse);
    outer->insertWidget(1, mStatus);
}

void StatsPanel::showResult(const GenerationResult& result) {
    const QLocale locale;
    mSpecies->setText(result.speciesName);
    mFile->setText(QFileInfo(result.path).fileName());
    mFile->setToolTip(result.path);
    mVertices->setText(QString::number(result.vertexCount()));
    mTriangles->setText(QString::number(result.triangleCount()));
    // A project's forest: how many trees, and the segments and leaves of all of them (an
    // instance counts its variant's skeleton).
    const auto trees = result.stats.find("trees");
    const bool forest = trees != result.stats.end();
    mTrees->setText(QString::number(forest ? qlonglong(trees->second) : 1));
    if (forest) {
        qlonglong segments = 0, leaves = 0;
        bool counted = false;
        for (const DrawnTree& t : result.trees)
            if (t.lod.skeleton) {
                counted = true;
                segments += qlonglong(t.lod.skeleton->segmentCount());
                leaves += qlonglong(t.lod.skeleton->leaves.size());
            }
        mSegments->setText(counted ? QString::number(segments) : QStringLiteral("–"));
        mLeaves->setText(counted ? QString::number(leaves) : QStringLiteral("–"));
    } else {
        mSegments->setText(QString::number(qlonglong(result.segments())));
        qlonglong leaves = result.skeleton ? qlonglong(result.skeleton->leaves.size()) : 0;
        if (auto it = result.stats.find("leaves"); it != result.stats.end())
            leaves = qlonglong(it->second);
        mLeaves->setText(QString::number(leaves));
    }
    mHeight->setText(tr("%1 m").arg(locale.toString(result.height(), 'f', 2)));
    mTime->setText(tr("%1 ms").arg(locale.toString(result.elapsedMs, 'f', 1)));
    // A project's scene total (sylva-cli stats gives the per-tree figures).
    const auto co2 = result.stats.find("co2_kg");
    mCo2->setText(co2 == result.stats.end()
                      ? QStringLiteral("–")
                      : tr("%1 t").arg(locale.toString(co2->second / 1000.0, 'f', 1)));
    const auto wood = result.stats.find("wood_m3");
    const auto biomass = result.stats.find("biomass_kg");
    const auto dbh = result.stats.find("mean_dbh_m");
    mWood->setText(
        wood == result.stats.end() || biomass == result.stats.end()
            ? QStringLiteral("–")
            : tr("%1 m³, %2 t; mean DBH %3 cm")
                  .arg(locale.toString(wood->second, 'f', 1),
                       locale.toString(biomass->second / 1000.0, 'f', 1),
                       locale.toString(dbh == result.stats.end() ? 0.0 : dbh->second * 100, 'f',
                                       1)));
    mStatus->clear();
    mStatus->setStyleSheet({});
}

void StatsPanel::showSelection(const doc::Document& document, const GenerationResult& result) {
    const QList<doc::TreeId> ids = document.selectedTrees();
    if (ids.isEmpty()) {
        mSelection->setText(tr("nothing selected"));
        return;
    }
    forest::TreeMetrics sum;
    double tallest = 0.0, widest = 0.0;
    int found = 0;
    for (const DrawnTree& t : result.trees) {
        if (!t.docId || !ids.contains(t.docId)) continue;
        ++found;
        tallest = std::max(tallest, t.metrics.heightM);
        widest = std::max(widest, t.metrics.dbhM);
        sum.woodVolumeM3 += t.metrics.woodVolumeM3;
        sum.dryBiomassKg += t.metrics.dryBiomassKg;
        sum.co2Kg += t.metrics.co2Kg;
    }
    const QLocale locale;
    QString text = tr("%n tree(s)", nullptr, int(ids.size()));
    if (found > 0)
        text +=
            tr("; up to %1 m tall, DBH up to %2 cm; wood %3 m³, biomass %4 kg, CO₂ %5 kg")
                .arg(locale.toString(tallest, 'f', 1), locale.toString(widest * 100, 'f', 1),
                     locale.toString(sum.woodVolumeM3, 'f', 2),
                     locale.toString(sum.dryBiomassKg, 'f', 0), locale.toString(sum.co2Kg, 'f', 0));
    mSelection->setText(text);
}

void StatsPanel::showGenerating(const QString& name) {
    mStatus->setStyleSheet({});
    mStatus->setText(tr("Generating %1…").arg(name));
}

void StatsPanel::showError(const QString& message) {
    mStatus->setStyleSheet(QStringLiteral("color: #b00020;"));
    mStatus->setText(message);
}

void StatsPanel::showWarning(const QString& message) {
    mStatus->setStyleSheet(QStringLiteral("color: #8a5a00;"));
    mStatus->setText(message);
}

QString StatsPanel::value(const QString& objectName) const {
    const auto* label = findChild<QLabel*>(objectName);
    return label ? label->text() : QString();
}

} // namespace sylva::ui
