// OutlinerView: its groups open, and its selection and the document's the same both ways.
#include <QDir>
#include <QTest>

#include "document/document.h"
#include "ui/document/outlinermodel.h"
#include "ui/document/outlinerview.h"

using namespace sylva;
using namespace sylva::ui;

class TestOutlinerView : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void keepsBothSelectionsTheSame() {
        doc::Document document;
        OutlinerModel model(document);
        OutlinerView view(document, &model);
        QCOMPARE(view.objectName(), QStringLiteral("outlinerView"));
        document.open(QDir(QStringLiteral(SYLVA_TEST_DATA_DIR))
                          .filePath(QStringLiteral("projects/small.sylva")));
        for (auto group : {OutlinerModel::SpeciesGroup, OutlinerModel::TreesGroup,
                           OutlinerModel::DomainsGroup, OutlinerModel::ObstaclesGroup})
            QVERIFY(view.isExpanded(model.groupIndex(group)));

        // The document's selection shows in the view.
        const doc::TreeId tree = document.treeIds().front();
        document.selectTrees({tree});
        const QModelIndexList shown = view.selectionModel()->selectedIndexes();
        QCOMPARE(shown.size(), 1);
        QCOMPARE(*model.itemAt(shown.front()), (doc::ItemRef{doc::ItemRef::Kind::Tree, tree}));

        // A selection made in the view becomes the document's.
        const doc::ItemRef species{doc::ItemRef::Kind::Species, 1};
        view.selectionModel()->select(model.indexOf(species), QItemSelectionModel::ClearAndSelect);
        QCOMPARE(document.selection(), QList<doc::ItemRef>{species});
        QVERIFY(document.selectedTrees().isEmpty());
    }
};

QTEST_MAIN(TestOutlinerView)
#include "test_outlinerview.moc"
