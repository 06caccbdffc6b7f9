// exportShown without a window: what is shown written as sylva-cli would, only the selection,
// the forest rebuilt for another camera, and a species preview ignoring the project's options.
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cstring>

#include "document/document.h"
#include "engine/util/error.h"
#include "ui/generation/exportshown.h"
#include "ui/generation/scenegenerator.h"

using namespace sylva;
using namespace sylva::ui;

namespace {

QString dataFile(const char* name) {
    return QDir(QStringLiteral(SYLVA_TEST_DATA_DIR)).filePath(QLatin1String(name));
}

QByteArray readFile(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// The JSON chunk of a .glb.
QJsonObject glbJson(const QString& path) {
    const QByteArray bytes = readFile(path);
    if (!bytes.startsWith("glTF")) return {};
    quint32 jsonLength = 0;
    std::memcpy(&jsonLength, bytes.constData() + 12, 4);
    return QJsonDocument::fromJson(bytes.mid(20, jsonLength)).object();
}

} // namespace

class TestExportShown : public QObject {
    Q_OBJECT

private:
    QTemporaryDir mDir;
    doc::Document mDocument;
    GenerationResult mShown;

    /// forest.obj in its own folder \p name: the files name each other ("mtllib forest.mtl"),
    /// so exports compare byte for byte.
    QString out(const char* name) const {
        QDir(mDir.path()).mkpath(QLatin1String(name));
        return QDir(mDir.filePath(QLatin1String(name))).filePath(QStringLiteral("forest.obj"));
    }
    ShownScene shown(const glm::vec3& eye = glm::vec3(0.0f),
                     const glm::vec3& target = glm::vec3(0.0f)) const {
        return {mShown, &mDocument, eye, target};
    }

private Q_SLOTS:
    void initTestCase() {
        mDocument.open(dataFile("projects/small.sylva"));
        mShown = generateProject(mDocument.project(), mDocument.path(), nullptr);
        QVERIFY2(mShown.ok(), qPrintable(mShown.error));
        QVERIFY(mShown.exportTrees.size() > 1);
    }

    void writesEveryShownTree() {
        const ExportCount count = exportShown(out("all"), shown());
        QCOMPARE(count.trees, mShown.exportTrees.size());
        QVERIFY(count.files >= 2); // the OBJ and its materials
        QVERIFY(readFile(out("all")).contains("\nf "));
    }

    // A GLB of the shown forest instances the variants as sylva-cli forest does: every tree
    // is an instance (its id in a node's sylva_ids) or a unique node (sylva_id).
    void glbInstancesTheVariants() {
        QVERIFY(!mShown.exportVariants.empty());
        QDir(mDir.path()).mkpath(QStringLiteral("glb"));
        const QString path = mDir.filePath(QStringLiteral("glb/forest.glb"));
        const ExportCount count = exportShown(path, shown());
        QCOMPARE(count.files, std::size_t(1));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        QVERIFY(bytes.startsWith("glTF"));
        quint32 jsonLength = 0;
        std::memcpy(&jsonLength, bytes.constData() + 12, 4);
        const QJsonObject json = QJsonDocument::fromJson(bytes.mid(20, jsonLength)).object();
        QVERIFY(json.value(QStringLiteral("extensionsUsed"))
                    .toArray()
                    .contains(QStringLiteral("EXT_mesh_gpu_instancing")));
        std::size_t trees = 0, instanced = 0;
        for (const QJsonValue& node : json.value(QStringLiteral("nodes")).toArray()) {
            const QJsonObject extras = node.toObject().value(QStringLiteral("extras")).toObject();
            instanced += extras.value(QStringLiteral("sylva_ids")).toArray().size();
            trees += extras.contains(QStringLiteral("sylva_id")) ? 1 : 0;
        }
        QVERIFY(instanced > 0);
        QCOMPARE(trees + instanced, mShown.exportTrees.size());
    }

    // The project's wind (#31): File ▸ Export writes the forest as sylva-cli forest --wind with
    // the project's settings (a skin per tree, the clip, the Pivot Painter textures, the table);
    // without a wind, or with the option off, as before.
    void writesTheProjectsWind() {
        QDir(mDir.path()).mkpath(QStringLiteral("wind"));
        const QString path = mDir.filePath(QStringLiteral("wind/forest.glb"));
        QVERIFY(!mDocument.project().wind);
        QVERIFY(!exportShown(path, shown()).wind);
        QVERIFY(!glbJson(path).contains(QStringLiteral("skins")));

        wind::WindSettings wind;
        wind.strength = 1.25f;
        wind.direction = glm::vec3(0, 0, 1);
        mDocument.setWind(wind);
        struct Calm { // the other cases export the project without a wind, whatever happens here
            doc::Document& d;
            ~Calm() { d.setWind(std::nullopt); }
        } calm{mDocument};
        const ExportCount count = exportShown(path, shown());
        QVERIFY(count.wind);
        QCOMPARE(count.trees, mShown.exportTrees.size());
        QVERIFY(count.files >= 4); // the GLB, its table, a texture pair per unique mesh
        const QJsonObject json = glbJson(path);
        // One skin per tree that has a mesh (a tree pruned away has nothing to rig).
        qsizetype drawn = 0;
        for (const exporter::ExportTree& t : mShown.exportTrees)
            drawn += t.mesh && !t.mesh->empty() ? 1 : 0;
        QVERIFY(drawn > 1);
        QCOMPARE(json.value(QStringLiteral("skins")).toArray().size(), drawn);
        QCOMPARE(json.value(QStringLiteral("animations"))
                     .toArray()
                     .at(0)
                     .toObject()
                     .value(QStringLiteral("name"))
                     .toString(),
                 QStringLiteral("wind"));
        const QJsonObject settings = json.value(QStringLiteral("asset"))
                                         .toObject()
                                         .value(QStringLiteral("extras"))
                                         .toObject()
                                         .value(QStringLiteral("sylva_wind"))
                                         .toObject();
        QCOMPARE(settings.value(QStringLiteral("strength")).toDouble(), 1.25);
        QCOMPARE(settings.value(QStringLiteral("direction")).toArray().at(2).toDouble(), 1.0);
        QVERIFY(QFile::exists(mDir.filePath(QStringLiteral("wind/forest.wind.csv"))));

        // The option off: the same project written still.
        ExportOptions still;
        still.projectWind = false;
        QVERIFY(!exportShown(path, shown(), still).wind);
        QVERIFY(!glbJson(path).contains(QStringLiteral("skins")));
    }

    void onlyTheSelectedTrees() {
        mDocument.selectTrees({mDocument.treeIds().front()});
        const ExportCount count = exportShown(out("one"), shown(), {true, false});
        QCOMPARE(count.trees, std::size_t(1));
        QVERIFY(readFile(out("one")).size() < readFile(out("all")).size());
        // Nothing hand-placed selected: a message, and no file.
        mDocument.selectTrees({});
        QVERIFY_THROWS_EXCEPTION(InvalidInput, exportShown(out("none"), shown(), {true, false}));
        QVERIFY(!QFileInfo::exists(out("none")));
    }

    void rebuildsForTheViewportCamera() {
        // The project's own camera builds the very forest that is shown.
        const doc::Project& p = mDocument.project();
        exportShown(out("project-camera"), shown(p.cameraPosition, p.cameraTarget), {false, true});
        QCOMPARE(readFile(out("project-camera")), readFile(out("all")));
        // A camera far away chooses coarser levels.
        exportShown(out("far"), shown({0.0f, 50.0f, 3000.0f}, glm::vec3(0.0f)), {false, true});
        QVERIFY(readFile(out("far")).size() < readFile(out("all")).size());
    }

    void aPreviewIgnoresTheProjectsOptions() {
        mDocument.selectTrees({});
        const ShownScene preview{mShown, nullptr, glm::vec3(0.0f), glm::vec3(0.0f)};
        const ExportCount count = exportShown(out("preview"), preview, {true, true});
        QCOMPARE(count.trees, mShown.exportTrees.size());
        QCOMPARE(readFile(out("preview")), readFile(out("all")));
    }

    void aFileThatCannotBeWrittenThrows() {
        QVERIFY_THROWS_EXCEPTION(std::exception,
                                 exportShown(QStringLiteral("/proc/no-such-dir/t.obj"), shown()));
    }
};

QTEST_GUILESS_MAIN(TestExportShown)
#include "test_exportshown.moc"
