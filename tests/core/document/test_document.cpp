// The editor's document: every command done, undone and redone; a seeded random sequence of
// edits of every kind undone to the original bytes and redone to the edited bytes; merging,
// obsolete edits, species inlining, files, and the autosave copy.
#include "document/autosave.h"
#include "document/document.h"
#include "document/filerefs.h"
#include "document/presetlibrary.h"
#include "document/projectsettings.h"
#include "document/scenebuild.h"
#include "document/speciesfile.h"
#include "engine/environment/obstaclemesh.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/text.h"

#include <gtest/gtest.h>

#include <functional>

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QTemporaryDir>
#include <QThread>

using namespace sylva;
using doc::Document;
using doc::TreeId;

namespace {

const QString kDemo = QStringLiteral(SYLVA_SOURCE_DIR "/resources/demo/alder-reference.sylva");

class DocumentTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        static int argc = 1;
        static char name[] = "test_document";
        static char* argv[] = {name, nullptr};
        if (!QCoreApplication::instance()) new QCoreApplication(argc, argv);
    }
    void SetUp() override {
        ASSERT_TRUE(mDir.isValid());
        // The demo project copied beside its meshes' and presets' folders would need the whole
        // tree: save it under a temporary name in its own folder instead and remove it after.
        mDoc.open(kDemo);
        mSaved = QDir(mDir.path()).filePath("demo.sylva");
        mDoc.save(mSaved);
    }
    QByteArray bytes() const { return mDoc.serialized(); }

    QTemporaryDir mDir;
    Document mDoc;
    QString mSaved;
};

const char* const kSeasons[] = {"", "spring", "summer", "autumn", "winter"};

doc::ProjectInstance alder(float x, float z) {
    doc::ProjectInstance t;
    t.species = "alder";
    t.position = {x, 0.0f, z};
    t.seed = 11;
    return t;
}

} // namespace

TEST_F(DocumentTest, SavedFileReloadsByteIdentically) {
    QFile file(mSaved);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray onDisk = file.readAll();
    EXPECT_EQ(onDisk, bytes());
    Document again;
    again.open(mSaved);
    EXPECT_EQ(again.serialized(), onDisk);
    EXPECT_FALSE(again.isModified());
    // Save As into another folder rewrote the relative paths: they still name the same files.
    EXPECT_EQ(
        QFileInfo(again.project().resolve(again.project().species[0].file)).canonicalFilePath(),
        QFileInfo(SYLVA_SOURCE_DIR "/presets/alder.json").canonicalFilePath());
    EXPECT_TRUE(QFileInfo::exists(again.project().resolve(again.project().obstacles[0].file)));
}

TEST_F(DocumentTest, EachTreeCommandDoesUndoesAndRedoes) {
    const QByteArray original = bytes();
    const TreeId id = mDoc.addTree(alder(5, 5));
    EXPECT_EQ(mDoc.project().instances.size(), 2u);
    EXPECT_EQ(mDoc.undoStack()->undoText().toStdString(), "Add tree");
    const QByteArray added = bytes();

    doc::ProjectInstance moved = mDoc.tree(id);
    moved.position.x = 9;
    mDoc.setTree(id, moved);
    EXPECT_EQ(mDoc.undoStack()->undoText().toStdString(), "Move tree");
    moved.rotation = 45;
    mDoc.setTree(id, moved);
    EXPECT_EQ(mDoc.undoStack()->undoText().toStdString(), "Rotate tree");
    moved.scale = 1.5;
    mDoc.setTree(id, moved);
    moved.seed = 99;
    mDoc.setTree(id, moved);
    moved.species = "ternary";
    mDoc.setTree(id, moved);
    EXPECT_EQ(mDoc.undoStack()->undoText().toStdString(), "Change tree species");
    const QByteArray edited = bytes();
    for (int i = 0; i < 5; ++i)
        mDoc.undoStack()->undo();
    EXPECT_EQ(bytes(), added);
    for (int i = 0; i < 5; ++i)
        mDoc.undoStack()->redo();
    EXPECT_EQ(bytes(), edited);

    const QList<TreeId> copies = mDoc.duplicateTrees({id});
    ASSERT_EQ(copies.size(), 1);
    EXPECT_NE(mDoc.tree(copies[0]).seed, mDoc.tree(id).seed);
    EXPECT_FLOAT_EQ(mDoc.tree(copies[0]).position.x, 10.0f);
    mDoc.removeTrees({id, copies[0]});
    EXPECT_EQ(mDoc.project().instances.size(), 1u);
    mDoc.undoStack()->undo(); // the removal of two trees is one step
    EXPECT_EQ(mDoc.treeIndex(id), 1);
    EXPECT_EQ(mDoc.treeIndex(copies[0]), 2);
    mDoc.undoStack()->setIndex(0);
    EXPECT_EQ(bytes(), original);
    EXPECT_FALSE(mDoc.isModified());
}

TEST_F(DocumentTest, DragsMergeAndNoOpEditsLeaveNoStep) {
    const TreeId id = mDoc.treeIds()[0];
    const int before = mDoc.undoStack()->count();
    doc::ProjectInstance t = mDoc.tree(id);
    const doc::ProjectInstance start = t;
    for (int step = 1; step <= 10; ++step) {
        t.position.x = start.position.x + static_cast<float>(step);
        mDoc.setTree(id, t, /*commit=*/step == 10);
    }
    EXPECT_EQ(mDoc.undoStack()->count(), before + 1);
    // A committed step does not swallow the next drag.
    t.position.z += 1;
    mDoc.setTree(id, t, false);
    EXPECT_EQ(mDoc.undoStack()->count(), before + 2);
    mDoc.undoStack()->undo();
    mDoc.undoStack()->undo();
    EXPECT_EQ(mDoc.tree(id), start);
    // Setting what is already there leaves no step; a drag that returns to its start neither.
    mDoc.setTree(id, start);
    EXPECT_EQ(mDoc.undoStack()->index(), before);
    mDoc.setSeed(mDoc.project().seed);
    EXPECT_EQ(mDoc.undoStack()->index(), before);
    t = start;
    t.position.y += 2;
    mDoc.setTree(id, t, false);
    mDoc.setTree(id, start, true);
    EXPECT_EQ(mDoc.undoStack()->index(), before);
}

TEST_F(DocumentTest, WindIsOneUndoableStepWithExactBytes) {
    const QByteArray original = bytes();
    ASSERT_FALSE(mDoc.project().wind.has_value());
    QList<doc::DocumentChange> changes;
    QObject::connect(&mDoc, &Document::changed,
                     [&](const doc::DocumentChange& c) { changes << c; });
    wind::WindSettings wind;
    wind.direction = {0.0f, 0.0f, -1.0f};
    wind.strength = 1.25f;
    wind.gustiness = 0.7f;
    const int steps = mDoc.undoStack()->count();
    mDoc.setWind(wind);
    EXPECT_EQ(mDoc.undoStack()->count(), steps + 1);
    ASSERT_TRUE(mDoc.project().wind.has_value());
    EXPECT_EQ(*mDoc.project().wind, wind);
    EXPECT_FALSE(changes.isEmpty());
    EXPECT_TRUE(changes.last().what & doc::DocumentChange::Settings);
    // The change says which setting it was (the window redraws its wind, regrows nothing).
    EXPECT_EQ(changes.last().settings, QStringList{QStringLiteral("wind")});
    const QByteArray windy = bytes();
    EXPECT_NE(windy.indexOf("\"wind\""), -1);
    // Setting the same wind again leaves no step.
    mDoc.setWind(wind);
    EXPECT_EQ(mDoc.undoStack()->count(), steps + 1);
    mDoc.undoStack()->undo();
    EXPECT_EQ(changes.last().settings, QStringList{QStringLiteral("wind")});
    EXPECT_EQ(bytes(), original); // an unset wind is not written: the exact bytes come back
    EXPECT_FALSE(mDoc.project().wind.has_value());
    mDoc.undoStack()->redo();
    EXPECT_EQ(bytes(), windy);
    // Unsetting is an edit too.
    mDoc.setWind(std::nullopt);
    EXPECT_EQ(bytes(), original);
    mDoc.undoStack()->undo();
    EXPECT_EQ(bytes(), windy);
    // Out of range: a clear error naming the range, nothing changed.
    wind::WindSettings storm = wind;
    storm.strength = 3.0f;
    const int before = mDoc.undoStack()->count();
    try {
        mDoc.setWind(storm);
        ADD_FAILURE() << "a strength of 3 was accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("strength"), std::string::npos) << e.what();
    }
    EXPECT_EQ(mDoc.undoStack()->count(), before);
    EXPECT_EQ(bytes(), windy);
}

TEST_F(DocumentTest, BadEditsThrowAndChangeNothing) {
    const QByteArray original = bytes();
    const int steps = mDoc.undoStack()->count();
    doc::ProjectInstance t = alder(0, 0);
    t.scale = 0;
    EXPECT_THROW(mDoc.addTree(t), InvalidInput);
    try {
        mDoc.addTree(t);
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("[0.01, 100]"), std::string::npos) << e.what();
    }
    t = alder(0, 0);
    t.species = "baobab";
    EXPECT_THROW(mDoc.addTree(t), InvalidInput);
    EXPECT_THROW(mDoc.setTree(12345, alder(0, 0)), InvalidInput);
    EXPECT_THROW(mDoc.setParam("alder", "nosuchnode.x", 1.0), InvalidInput);
    EXPECT_THROW(mDoc.setParam("alder", "mesh.no_such_param", 1.0), InvalidInput);
    EXPECT_THROW(mDoc.setParam("alder", "noseparator", 1.0), InvalidInput);
    EXPECT_THROW(mDoc.removeSpecies("alder"), InvalidInput); // used by trees
    EXPECT_THROW(mDoc.removeObstacle(7), InvalidInput);
    EXPECT_THROW(mDoc.setCamera({1, 1, 1}, {1, 1, 1}), InvalidInput);
    EXPECT_EQ(bytes(), original);
    EXPECT_EQ(mDoc.undoStack()->count(), steps);
}

TEST_F(DocumentTest, SpeciesEditInlinesTheSpeciesAndKeepsItsFiles) {
    ASSERT_FALSE(mDoc.project().species[0].file.empty());
    const sylva::Value before = mDoc.param("alder", "mesh.resolution");
    EXPECT_EQ(before.toNumber(), 8.0);
    mDoc.setParam("alder", "mesh.resolution", 5.0);
    // The undo step names the parameter in words and its node, not the path.
    EXPECT_EQ(mDoc.undoStack()->undoText().toStdString(), "Change resolution (mesh)");
    const doc::ProjectSpecies& s = mDoc.project().species[0];
    EXPECT_TRUE(s.file.empty());
    ASSERT_TRUE(s.graph.has_value());
    EXPECT_TRUE(s.traits.has_value());
    EXPECT_EQ(mDoc.param("alder", "mesh.resolution").toNumber(), 5.0);
    // The grammar file still resolves from the project's folder.
    const std::string grammarFile = mDoc.param("alder", "grow.grammar_file").toString();
    EXPECT_TRUE(QFileInfo::exists(mDoc.project().resolve(grammarFile))) << grammarFile;
    // Saved with the project, and the species file on disk is untouched.
    mDoc.save();
    Document again;
    again.open(mSaved);
    EXPECT_EQ(again.param("alder", "mesh.resolution").toNumber(), 5.0);
    const std::string text = again.grammar("alder", "grow");
    EXPECT_NE(text.find("axiom"), std::string::npos);
    mDoc.setGrammar("alder", "grow", text + "\n# edited\n");
    EXPECT_TRUE(mDoc.param("alder", "grow.grammar_file").isNull());
    EXPECT_EQ(mDoc.undoStack()->undoText().toStdString(), "Edit grammar");
    mDoc.undoStack()->setIndex(0);
    EXPECT_FALSE(mDoc.project().species[0].file.empty());
}

// Variants (K) are the project's setting of a species, not part of its file: the first edit that
// inlines the species, and applying a preset, keep them (they were reset to the default 8: a
// hand-placed project's "variants": 0 came back as 8 after the first parameter edit, which grew
// 8 variants nobody used).
TEST_F(DocumentTest, InliningAndPresetsKeepTheSpeciesVariants) {
    for (const int k : {0, 3}) {
        SCOPED_TRACE(k);
        mDoc.setSpeciesVariants("alder", k);
        ASSERT_FALSE(mDoc.project().species[0].file.empty());
        mDoc.setParam("alder", "mesh.resolution", 5.0);
        EXPECT_TRUE(mDoc.project().species[0].file.empty());
        EXPECT_EQ(mDoc.project().species[0].variants, k);
        mDoc.applyPreset("alder", QStringLiteral(SYLVA_SOURCE_DIR "/presets/silver-birch.json"));
        EXPECT_EQ(mDoc.project().species[0].variants, k);
        mDoc.undoStack()->setIndex(0);
    }
}

// The node editor's edits: each is one undo step, refused edits say why and change nothing,
// and undoing all of them gives back the exact file.
TEST_F(DocumentTest, GraphEditsAreCheckedAndUndoable) {
    const QByteArray original = bytes();
    const int steps = mDoc.undoStack()->count();
    // alder: grow (lsystem) → mesh (tube_mesh, the output).
    const std::string leaves =
        mDoc.addNode("alder", "leaves", sylva::Value::Object{{"size", 0.2}}, {}, {120.0f, 40.0f});
    EXPECT_EQ(leaves, "leaves");
    EXPECT_EQ(mDoc.addNode("alder", "leaves"), "leaves2"); // a fresh id from the type
    EXPECT_EQ(mDoc.nodePosition("alder", "leaves"), glm::vec2(120.0f, 40.0f));
    EXPECT_EQ(mDoc.undoStack()->undoText().toStdString(), "Add node leaves2");
    mDoc.undoStack()->undo();

    // Refused, with the engine's reason, and nothing changes.
    const QByteArray beforeRefusals = bytes();
    auto refusal = [&](const std::function<void()>& edit) -> std::string {
        try {
            edit();
        } catch (const InvalidInput& e) {
            return e.what();
        }
        return "accepted";
    };
    EXPECT_NE(refusal([&] { mDoc.connectNodes("alder", "mesh", "grow"); }).find("takes no input"),
              std::string::npos);
    EXPECT_NE(refusal([&] { mDoc.addNode("alder", "no_such_type"); }).find("known: adapt"),
              std::string::npos);
    EXPECT_NE(refusal([&] {
                  mDoc.addNode("alder", "tube_mesh", sylva::Value::Object{{"resolution", 99}});
              }).find("resolution must be in [3, 64]"),
              std::string::npos);
    EXPECT_NE(refusal([&] { mDoc.removeNode("alder", "mesh"); }).find("output"), std::string::npos);
    EXPECT_NE(
        refusal([&] { mDoc.disconnectNodes("alder", "grow", "mesh"); }).find("the tree needs it"),
        std::string::npos);
    EXPECT_NE(refusal([&] { mDoc.removeNode("alder", "grow"); }).find("the tree needs it"),
              std::string::npos);
    EXPECT_EQ(bytes(), beforeRefusals);

    // Wire grow → leaves → mesh: mesh's one input is replaced by leaves.
    mDoc.connectNodes("alder", "grow", "leaves");
    mDoc.connectNodes("alder", "leaves", "mesh");
    sylva::Value g = mDoc.speciesGraph("alder");
    for (const sylva::Value& n : g.toObject().at("nodes").toArray()) {
        if (n.string("id", "") == "mesh") {
            EXPECT_EQ(n.find("inputs")->toJson(), "[\"leaves\"]");
        }
    }
    // A mesh into a node that takes a skeleton is refused.
    mDoc.addNode("alder", "adapt", sylva::Value::Object{}, "bend");
    mDoc.connectNodes("alder", "grow", "bend");
    EXPECT_NE(refusal([&] { mDoc.connectNodes("alder", "mesh", "bend"); }).find("takes a skeleton"),
              std::string::npos);
    // Dragging a node: one undo step however many moves.
    const int before = mDoc.undoStack()->count();
    for (int k = 0; k < 10; ++k)
        mDoc.moveNode("alder", "bend", {float(k), 2.0f * float(k)}, k == 9);
    EXPECT_EQ(mDoc.undoStack()->count(), before + 1);
    EXPECT_EQ(mDoc.nodePosition("alder", "bend"), glm::vec2(9.0f, 18.0f));
    mDoc.removeNode("alder", "bend");
    mDoc.setOutputNode("alder", "mesh");
    EXPECT_EQ(mDoc.param("alder", "leaves.size").toNumber(), 0.2);

    // Saved and reloaded: the graph and the positions come back.
    mDoc.save();
    Document again;
    again.open(mSaved);
    EXPECT_EQ(again.speciesGraph("alder").toJson(), mDoc.speciesGraph("alder").toJson());
    EXPECT_EQ(again.nodePosition("alder", "leaves"), glm::vec2(120.0f, 40.0f));

    mDoc.undoStack()->setIndex(steps);
    EXPECT_EQ(bytes(), original);
    mDoc.undoStack()->setIndex(mDoc.undoStack()->count());
    EXPECT_EQ(mDoc.speciesGraph("alder").toJson(), again.speciesGraph("alder").toJson());
}

// Presets: each one applies to a species of the project (one undo step, its files still found
// from the project), saves back as a self-contained species file that loads to the same graph,
// and undo gives back the exact project.
TEST_F(DocumentTest, EveryPresetAppliesAndRoundTrips) {
    const QByteArray original = bytes();
    QTemporaryDir out;
    ASSERT_TRUE(out.isValid());
    const QList<doc::PresetInfo> presets =
        doc::PresetLibrary::list(QStringLiteral(SYLVA_SOURCE_DIR "/presets"));
    ASSERT_GE(presets.size(), 12);
    // A parameter with its file references (also nested: a mesh envelope's) by file name:
    // rebased to the project's folder, they name the same files.
    std::function<sylva::Value(const sylva::Value&, const std::string&)> fileNames =
        [&fileNames](const sylva::Value& v, const std::string& key) -> sylva::Value {
        if (v.isString() && graph::isFileParam(key))
            return sylva::Value(
                QFileInfo(QString::fromStdString(v.toString())).fileName().toStdString());
        if (v.isObject()) {
            sylva::Value::Object out;
            for (const auto& [k, member] : v.toObject())
                out[k] = fileNames(member, k);
            return sylva::Value(std::move(out));
        }
        if (v.isArray()) {
            sylva::Value::Array out;
            for (const sylva::Value& element : v.toArray())
                out.push_back(fileNames(element, {}));
            return sylva::Value(std::move(out));
        }
        return v;
    };
    auto resolved = [&fileNames](const graph::NodeDesc& n, const std::string& key) {
        const sylva::Value* v = n.params.find(key);
        return v ? fileNames(*v, key) : sylva::Value();
    };
    for (const doc::PresetInfo& p : presets) {
        SCOPED_TRACE(p.path.toStdString());
        const graph::SpeciesGraph preset = doc::loadSpecies(p.path);
        mDoc.applyPreset("alder", p.path);
        EXPECT_EQ(mDoc.undoStack()->undoText(),
                  QStringLiteral("Apply preset %1").arg(QFileInfo(p.path).completeBaseName()));
        const graph::SpeciesGraph applied = mDoc.engineSpecies("alder");
        ASSERT_EQ(applied.nodes.size(), preset.nodes.size());
        EXPECT_EQ(applied.output, preset.output);
        for (std::size_t k = 0; k < preset.nodes.size(); ++k) {
            const graph::NodeDesc& a = applied.nodes[k];
            const graph::NodeDesc& b = preset.nodes[k];
            EXPECT_EQ(a.id, b.id);
            EXPECT_EQ(a.type, b.type);
            EXPECT_EQ(a.inputs, b.inputs);
            for (const auto& [key, value] : b.params.toObject())
                EXPECT_EQ(resolved(a, key).toJson(), resolved(b, key).toJson()) << key;
            if (a.type == "lsystem") {
                // The grammar is still found (from the project's folder) and is the preset's.
                EXPECT_EQ(mDoc.grammar("alder", a.id), [&] {
                    if (const sylva::Value* g = b.params.find("grammar")) return g->toString();
                    QFile f(QDir(QString::fromStdString(preset.baseDir.string()))
                                .filePath(QString::fromStdString(
                                    b.params.find("grammar_file")->toString())));
                    EXPECT_TRUE(f.open(QIODevice::ReadOnly));
                    return f.readAll().toStdString();
                }());
            }
        }
        // Saved as a preset: self-contained, and it loads to the same graph.
        const QString saved = out.filePath(QFileInfo(p.path).fileName());
        mDoc.saveSpeciesAs("alder", saved);
        const graph::SpeciesGraph again = doc::loadSpecies(saved);
        ASSERT_EQ(again.nodes.size(), applied.nodes.size());
        for (std::size_t k = 0; k < again.nodes.size(); ++k) {
            EXPECT_EQ(again.nodes[k].type, applied.nodes[k].type);
            EXPECT_EQ(again.nodes[k].inputs, applied.nodes[k].inputs);
            EXPECT_FALSE(again.nodes[k].params.contains("grammar_file"));
            if (again.nodes[k].type == "lsystem") {
                EXPECT_EQ(again.nodes[k].params.find("grammar")->toString(),
                          mDoc.grammar("alder", applied.nodes[k].id));
            }
        }
        mDoc.undoStack()->undo();
        EXPECT_EQ(bytes(), original);
    }
}

TEST_F(DocumentTest, RandomEditsUndoneAndRedoneGiveTheExactBytes) {
    const QByteArray original = bytes();
    Rng rng(20261124);
    auto uniform = [&rng](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
    const QString wall = QStringLiteral(SYLVA_SOURCE_DIR "/resources/demo/meshes/wall.obj");
    int kinds[12] = {};
    for (int edit = 0; edit < 240; ++edit) {
        const int kind = static_cast<int>(rng.next() % 12);
        const auto& ids = mDoc.treeIds();
        const TreeId someTree = ids.empty() ? 0 : ids[rng.next() % ids.size()];
        try {
            switch (kind) {
            case 0:
                mDoc.addTree(alder(float(uniform(-20, 20)), float(uniform(-20, 20))));
                break;
            case 1:
                if (ids.size() > 1) mDoc.removeTrees({someTree});
                break;
            case 2:
                if (someTree) mDoc.duplicateTrees({someTree});
                break;
            case 3: {
                if (!someTree) break;
                doc::ProjectInstance t = mDoc.tree(someTree);
                // A drag: several uncommitted moves and a committed release.
                for (int k = 0; k < 4; ++k) {
                    t.position.x += float(uniform(-1, 1));
                    t.rotation = uniform(0, 360);
                    mDoc.setTree(someTree, t, k == 3);
                }
                break;
            }
            case 4: {
                if (!someTree) break;
                doc::ProjectInstance t = mDoc.tree(someTree);
                t.scale = uniform(0.5, 2);
                t.seed = rng.next() % 1000;
                t.species = rng.next() % 2 ? "alder" : "ternary";
                mDoc.setTree(someTree, t);
                break;
            }
            case 5: {
                doc::ProjectObstacle o;
                o.file = wall.toStdString();
                o.translate = {float(uniform(-20, 20)), 0, float(uniform(-20, 20))};
                mDoc.addObstacle(o);
                break;
            }
            case 6:
                if (!mDoc.project().obstacles.empty()) {
                    const int i = int(rng.next() % mDoc.project().obstacles.size());
                    if (rng.next() % 3 == 0) {
                        mDoc.removeObstacle(i);
                    } else {
                        doc::ProjectObstacle o = mDoc.project().obstacles[std::size_t(i)];
                        o.rotate.y = float(uniform(0, 90));
                        o.scale = glm::vec3(float(uniform(0.5, 2)));
                        mDoc.setObstacle(i, o);
                    }
                }
                break;
            case 7: {
                if (mDoc.project().domains.empty()) {
                    mDoc.addDomain(doc::PlacementDomain{});
                    break;
                }
                doc::PlacementDomain d = mDoc.project().domains[0];
                d.counts["alder"] = int(rng.next() % 50);
                d.max.x = float(uniform(10, 60));
                if (rng.next() % 4 == 0)
                    mDoc.removeDomain(0);
                else
                    mDoc.setDomain(0, d);
                break;
            }
            case 8:
                mDoc.setSeed(rng.next() % 100000);
                break;
            case 9:
                mDoc.setCamera({float(uniform(-50, 50)), float(uniform(5, 40)), 70},
                               {0, float(uniform(0, 8)), 0}, rng.next() % 2);
                mDoc.setLight({float(uniform(-1, 1)), -1, float(uniform(-1, 1))});
                mDoc.setSeason(kSeasons[rng.next() % 5]);
                if (someTree) mDoc.setTreeSeason(someTree, kSeasons[rng.next() % 5]);
                break;
            case 10:
                mDoc.setParam(rng.next() % 2 ? "alder" : "ternary", "mesh.resolution",
                              double(3 + rng.next() % 10), rng.next() % 2);
                break;
            case 11:
                mDoc.setGrammar(
                    "ternary",
                    mDoc.speciesGraph("ternary").find("nodes")->toArray()[0].string("id", ""),
                    "# random edit " + std::to_string(edit) + "\naxiom: F\n");
                break;
            }
            ++kinds[kind];
        } catch (const InvalidInput& e) {
            FAIL() << "edit " << edit << " kind " << kind << ": " << e.what();
        }
    }
    for (int k = 0; k < 12; ++k)
        EXPECT_GT(kinds[k], 0) << "edit kind " << k << " never ran";
    ASSERT_GE(mDoc.undoStack()->count(), 200);
    const QByteArray edited = bytes();
    EXPECT_NE(edited, original);
    while (mDoc.undoStack()->canUndo())
        mDoc.undoStack()->undo();
    EXPECT_EQ(bytes(), original);
    EXPECT_FALSE(mDoc.isModified());
    while (mDoc.undoStack()->canRedo())
        mDoc.undoStack()->redo();
    EXPECT_EQ(bytes(), edited);
    // And through the file: saved, the edited state reloads byte for byte.
    mDoc.save();
    Document again;
    again.open(mSaved);
    EXPECT_EQ(again.serialized(), edited);
}

TEST_F(DocumentTest, SeasonsAreUndoableSavedOnlyWhenSetAndChecked) {
    mDoc.addTree(alder(3, 4));
    mDoc.save();
    const QByteArray original = bytes();
    // A project without seasons saves without a season key: files stay as they were.
    EXPECT_FALSE(original.contains("\"season\""));
    const doc::TreeId tree = mDoc.treeIds().back();
    mDoc.setSeason("autumn");
    mDoc.setTreeSeason(tree, "fall"); // autumn's other name, stored as "autumn"
    EXPECT_EQ(mDoc.project().season, "autumn");
    EXPECT_EQ(mDoc.tree(tree).season, "autumn");
    mDoc.setSeason("winter");
    const int steps = mDoc.undoStack()->count();
    EXPECT_THROW(mDoc.setSeason("monsoon"), InvalidInput);
    doc::ProjectInstance bad = mDoc.tree(tree);
    bad.season = "monsoon";
    EXPECT_THROW(mDoc.setTree(tree, bad), InvalidInput);
    EXPECT_EQ(mDoc.undoStack()->count(), steps);
    // Saved and reloaded, the seasons come back.
    mDoc.save();
    Document again;
    again.open(mSaved);
    EXPECT_EQ(again.project().season, "winter");
    EXPECT_EQ(again.tree(again.treeIds().back()).season, "autumn");
    EXPECT_EQ(again.serialized(), bytes());
    // Undone, the document is the exact one it was before the season edits.
    for (int k = 0; k < 3; ++k)
        mDoc.undoStack()->undo();
    EXPECT_EQ(bytes(), original);
    EXPECT_TRUE(mDoc.project().season.empty());
}

TEST_F(DocumentTest, CorruptOrNewerFileLeavesTheDocumentAsItWas) {
    mDoc.addTree(alder(3, 3));
    const QByteArray before = bytes();
    const QString broken = QDir(mDir.path()).filePath("broken.sylva");
    QFile f(broken);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("{ \"format\": \"sylva-project\", \"format_version\": 1,\n  \"seed\": 7,,\n}");
    f.close();
    try {
        mDoc.open(broken);
        FAIL() << "a corrupt file opened";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("broken.sylva:2:"), std::string::npos) << e.what();
    }
    EXPECT_THROW(mDoc.open(QDir(mDir.path()).filePath("missing.sylva")), IoError);
    EXPECT_EQ(bytes(), before);
    EXPECT_TRUE(mDoc.isModified());
    EXPECT_EQ(mDoc.path(), mSaved);
}

TEST_F(DocumentTest, AutosaveCopyRestoresEveryEdit) {
    const QString folder = QDir(mDir.path()).filePath("recovery");
    {
        doc::Autosave autosave(mDoc, folder);
        EXPECT_FALSE(autosave.saveNow()); // nothing unsaved
        mDoc.addTree(alder(4, 4));
        mDoc.setSeed(1234);
        ASSERT_TRUE(autosave.saveNow()) << autosave.lastError().toStdString();
        EXPECT_TRUE(QFileInfo::exists(autosave.recoveryFile()));
        // Never over the user's file.
        QFile user(mSaved);
        ASSERT_TRUE(user.open(QIODevice::ReadOnly));
        EXPECT_NE(user.readAll(), bytes());
    }
    const QByteArray edited = bytes();
    Document fresh;
    doc::Autosave next(fresh, folder);
    const auto pending = next.pending();
    ASSERT_TRUE(pending.has_value());
    EXPECT_EQ(pending->documentPath, mSaved);
    next.restore();
    EXPECT_EQ(fresh.serialized(), edited);
    EXPECT_TRUE(fresh.isModified());
    EXPECT_EQ(fresh.path(), mSaved);
    // Relative paths still resolve against the project's own folder.
    EXPECT_TRUE(QFileInfo::exists(fresh.project().resolve(fresh.project().obstacles[0].file)));
    // Saving the document removes the copy this run made.
    next.saveNow();
    fresh.save();
    EXPECT_FALSE(next.pending().has_value());
}

// The first edit after opening, and the first after a save, reach the recovery file a few
// seconds later like every other edit (the idle timer used to start only when the document
// already read as modified, which the first edit's change signal arrives before).
TEST_F(DocumentTest, AutosaveWritesTheFirstEditAfterOpeningAndAfterSaving) {
    const QString folder = QDir(mDir.path()).filePath("recovery");
    doc::Autosave autosave(mDoc, folder);
    autosave.setIdleDelay(20);
    int writes = 0;
    QObject::connect(&autosave, &doc::Autosave::saved, [&] { ++writes; });
    auto waitForWrite = [&](int before) {
        QElapsedTimer clock;
        clock.start();
        while (writes == before && clock.elapsed() < 5000) {
            QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
            QThread::msleep(5);
        }
        return writes > before;
    };
    ASSERT_FALSE(mDoc.isModified());
    mDoc.addTree(alder(4, 4)); // one edit, the first since opening
    ASSERT_TRUE(waitForWrite(0)) << "the first edit after opening was not autosaved";
    EXPECT_TRUE(QFileInfo::exists(autosave.recoveryFile()));

    mDoc.save(); // clean: the copy goes
    EXPECT_FALSE(QFileInfo::exists(autosave.recoveryFile()));
    const int afterSave = writes;
    mDoc.setSeed(4321); // the first edit after the save
    ASSERT_TRUE(waitForWrite(afterSave)) << "the first edit after saving was not autosaved";
    Document fresh;
    doc::Autosave next(fresh, folder);
    next.restore();
    EXPECT_EQ(fresh.serialized(), bytes());
}

TEST(FileRefs, SourceFilesOfTheDemo) {
    const doc::Project p = doc::loadProject(kDemo);
    const QStringList files = doc::projectSourceFiles(p);
    auto has = [&](const char* end) {
        for (const QString& f : files)
            if (f.endsWith(QLatin1String(end))) return true;
        return false;
    };
    EXPECT_TRUE(has("presets/alder.json"));
    EXPECT_TRUE(has("presets/lsystem/alder.lsys"));
    EXPECT_TRUE(has("meshes/wall.obj"));
    EXPECT_TRUE(has("meshes/boulder.obj"));
    EXPECT_TRUE(graph::isFileParam("grammar_file"));
    EXPECT_FALSE(graph::isFileParam("profile"));
}

// A species graph kept in the project names files inside nested parameters too (a mesh
// envelope, an adapt node's obstacles): a save under another folder must move them as well,
// or the saved project points nowhere.
TEST(FileRefs, NestedFilesAreRebased) {
    sylva::Value g = sylva::Value::parseJson(R"({"nodes":[{"id":"grow","type":"space_colonization",
        "params":{"envelope":{"shape":"mesh","file":"meshes/crown.obj"},"grammar_file":"g.lsys",
        "obstacles":[{"file":"rock.obj","scale":2}],"profile":"keep/me"}}]})");
    doc::rebaseGraphFiles(g, QStringLiteral("/p/a"), QStringLiteral("/p/b"));
    const sylva::Value& params = g.find("nodes")->toArray()[0].find("params")[0];
    EXPECT_EQ(params.find("envelope")->find("file")->toString(), "../a/meshes/crown.obj");
    EXPECT_EQ(params.find("grammar_file")->toString(), "../a/g.lsys");
    EXPECT_EQ(params.find("obstacles")->toArray()[0].find("file")->toString(), "../a/rock.obj");
    EXPECT_EQ(params.find("profile")->toString(), "keep/me"); // not a file
}

// The files an editor watches for a species include those named inside nested parameters (an
// adapt node's obstacles, a mesh envelope): an edit to such a mesh on disk regrows the trees.
TEST(FileRefs, NestedFilesAreWatched) {
    graph::SpeciesGraph g;
    g.baseDir = "/p/a";
    g.nodes.push_back({"grow",
                       "space_colonization",
                       sylva::Value::parseJson(R"({"envelope":{"shape":"mesh",
                           "file":"meshes/crown.obj"},"grammar_file":"g.lsys",
                           "obstacles":[{"file":"/q/rock.obj","scale":2}],"profile":"keep/me"})"),
                       {}});
    QStringList files;
    doc::addSpeciesSourceFiles(g, files);
    files.sort();
    EXPECT_EQ(files,
              QStringList({QStringLiteral("/p/a/g.lsys"), QStringLiteral("/p/a/meshes/crown.obj"),
                           QStringLiteral("/q/rock.obj")}));
}

// Issue 30: a hand-placed tree's id is made when it is added (or duplicated), saved in the
// project, kept by every edit and never given to another tree, even after the tree is removed
// and the project saved and opened again.
TEST_F(DocumentTest, TreeIdsSurviveEditsSavesAndAreNeverGivenTwice) {
    ASSERT_EQ(mDoc.treeIds().size(), 1u);
    const TreeId first = mDoc.treeIds()[0];
    EXPECT_EQ(mDoc.project().instances[0].id, first);
    const TreeId added = mDoc.addTree(alder(5, 5));
    EXPECT_EQ(added, first + 1);
    const TreeId copy = mDoc.duplicateTrees({added}).front();
    EXPECT_EQ(copy, added + 1);
    doc::ProjectInstance moved = mDoc.tree(copy);
    moved.position.x += 30;
    moved.id = 999; // the caller's copy cannot change a tree's id
    mDoc.setTree(copy, moved);
    EXPECT_EQ(mDoc.tree(copy).id, copy);
    EXPECT_EQ(mDoc.tree(first).id, first);
    mDoc.removeTrees({added});
    mDoc.save();
    Document again;
    again.open(mSaved);
    EXPECT_EQ(again.treeIds(), (std::vector<TreeId>{first, copy}));
    EXPECT_FLOAT_EQ(again.tree(copy).position.x, 36.0f); // duplicated 1 m aside, then moved
    // Neither the removed tree's id nor any other in use comes back.
    const TreeId next = again.addTree(alder(1, 1));
    EXPECT_EQ(next, copy + 1);
    // Undoing an add gives the id back with the exact bytes (the tree never existed).
    const QByteArray before = again.serialized();
    again.addTree(alder(2, 2));
    again.undoStack()->undo();
    EXPECT_EQ(again.serialized(), before);
}

TEST_F(DocumentTest, DomainsGetFreshIdsAndKeepThemThroughEdits) {
    const std::size_t n = mDoc.project().domains.size();
    std::uint64_t largest = 0;
    for (const doc::PlacementDomain& d : mDoc.project().domains)
        largest = std::max(largest, d.id);
    doc::PlacementDomain d;
    d.id = 1; // taken: a new domain always gets a fresh id
    mDoc.addDomain(d);
    ASSERT_EQ(mDoc.project().domains.size(), n + 1);
    EXPECT_EQ(mDoc.project().domains[n].id, largest + 1);
    doc::PlacementDomain edited = mDoc.project().domains[n];
    edited.max.x += 5;
    edited.id = 77;
    mDoc.setDomain(static_cast<int>(n), edited);
    EXPECT_EQ(mDoc.project().domains[n].id, largest + 1);
}

// Issue #40: opening a project whose linked obstacle mesh is missing, or whose linked species
// file is broken, replaced the open document. Opening is atomic: every linked file is read and
// checked first; on failure the open project keeps its bytes, its path and its undo history,
// and the error names the linked file (with line:column where it has one).
TEST_F(DocumentTest, OpeningAProjectWithABadLinkedFileLeavesTheOpenOneAsItWas) {
    mDoc.addTree(alder(4.0f, 4.0f));
    const QByteArray before = bytes();
    const QString path = mDoc.path();
    const int undoSteps = mDoc.undoStack()->count();
    const int undoIndex = mDoc.undoStack()->index();
    ASSERT_GT(undoSteps, 0);

    QFile demo(kDemo);
    ASSERT_TRUE(demo.open(QIODevice::ReadOnly));
    const QString presets = QStringLiteral(SYLVA_SOURCE_DIR "/presets/");
    const QString meshes = QStringLiteral(SYLVA_SOURCE_DIR "/resources/demo/meshes/");
    QString text = QString::fromUtf8(demo.readAll())
                       .replace(QStringLiteral("../../presets/"), presets)
                       .replace(QStringLiteral("meshes/"), meshes);
    auto write = [this](const QString& name, const QString& content) {
        const QString file = QDir(mDir.path()).filePath(name);
        QFile f(file);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(content.toUtf8());
        return file;
    };
    auto expectUnchanged = [&] {
        EXPECT_EQ(bytes(), before);
        EXPECT_EQ(mDoc.path(), path);
        EXPECT_EQ(mDoc.undoStack()->count(), undoSteps);
        EXPECT_EQ(mDoc.undoStack()->index(), undoIndex);
    };
    auto openError = [&](const QString& file) -> std::string {
        try {
            mDoc.open(file);
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    };

    // The good copy opens (the check itself refuses nothing valid); then back to the edit.
    const QString good = write(QStringLiteral("good.sylva"), text);
    {
        Document other;
        EXPECT_NO_THROW(other.open(good));
    }

    QString missing = text;
    missing.replace(meshes + QStringLiteral("boulder.obj"), QStringLiteral("nothere/boulder.obj"));
    const std::string meshError = openError(write(QStringLiteral("missingmesh.sylva"), missing));
    EXPECT_NE(meshError.find("boulder.obj"), std::string::npos) << meshError;
    expectUnchanged();

    write(QStringLiteral("broken.json"),
          QStringLiteral("{ \"format\": \"sylva-species\",\n"
                         "  \"name\": \"broken\",\n  \"graph\": [ }\n"));
    QString brokenSpecies = text;
    brokenSpecies.replace(presets + QStringLiteral("ternary-tree.json"),
                          QDir(mDir.path()).filePath(QStringLiteral("broken.json")));
    const std::string speciesError =
        openError(write(QStringLiteral("brokenspecies.sylva"), brokenSpecies));
    EXPECT_NE(speciesError.find("broken.json:3:"), std::string::npos) << speciesError;
    expectUnchanged();

    // A species whose grammar file does not parse: named with its line and column.
    write(QStringLiteral("bad.lsys"), QStringLiteral("generations: 2\naxiom: F\nF -> F[+F\n"));
    write(
        QStringLiteral("badgrammar.json"),
        QStringLiteral("{ \"format\": \"sylva-species\", \"format_version\": 1, \"name\": \"b\",\n"
                       "  \"graph\": { \"nodes\": [\n"
                       "    { \"id\": \"grow\", \"type\": \"lsystem\", \"params\": { "
                       "\"grammar_file\": \"bad.lsys\" } },\n"
                       "    { \"id\": \"mesh\", \"type\": \"tube_mesh\", \"inputs\": [\"grow\"] }"
                       " ], \"output\": \"mesh\" } }\n"));
    QString badGrammar = text;
    badGrammar.replace(presets + QStringLiteral("ternary-tree.json"),
                       QDir(mDir.path()).filePath(QStringLiteral("badgrammar.json")));
    const std::string grammarError =
        openError(write(QStringLiteral("badgrammar.sylva"), badGrammar));
    EXPECT_NE(grammarError.find("bad.lsys:3:"), std::string::npos) << grammarError;
    expectUnchanged();
}

// Opening checks every linked obstacle mesh by loading it as the growth does, into the scene
// cache the growth then reads: each file is read once, not once to check and again to grow (a
// scanned cliff of a million triangles took as long again to open).
TEST_F(DocumentTest, OpeningAndGrowingReadEachObstacleMeshOnce) {
    const QString rock = QDir(mDir.path()).filePath(QStringLiteral("rock.obj"));
    ASSERT_TRUE(
        QFile::copy(QStringLiteral(SYLVA_SOURCE_DIR "/resources/demo/meshes/boulder.obj"), rock));
    doc::ProjectObstacle o;
    o.file = rock.toStdString();
    o.translate = {3.0f, 0.0f, 1.0f};
    mDoc.addObstacle(o);
    const QString saved = QDir(mDir.path()).filePath(QStringLiteral("rocks.sylva"));
    mDoc.save(saved);

    Document other;
    const std::size_t before = env::obstacleMeshFilesRead();
    other.open(saved);
    const std::size_t obstacles = other.project().obstacles.size();
    ASSERT_GE(obstacles, 1u);
    EXPECT_EQ(env::obstacleMeshFilesRead() - before, obstacles);
    const forest::ForestScene scene = doc::makeForestScene(other.project());
    ASSERT_TRUE(scene.obstacles);
    EXPECT_EQ(env::obstacleMeshFilesRead() - before, obstacles);
}

// Issue #43: hand edits of single branches go through the document as one undo step each, and
// undo gives back the exact bytes (a project without edits is a format-2 file again).
TEST_F(DocumentTest, BranchEditsAreUndoableSteps) {
    const TreeId id = mDoc.addTree(alder(1.0f, 2.0f));
    const QByteArray before = bytes();
    const int steps = mDoc.undoStack()->count();
    skel::BranchEdit cut;
    cut.branch = "0.2";
    cut.prune = true;
    mDoc.editBranch(id, cut);
    skel::BranchEdit bend;
    bend.branch = "0.1";
    bend.bend = glm::vec3(1.0f, 1.0f, 0.0f);
    bend.length = 0.8f;
    mDoc.editBranch(id, bend);
    EXPECT_EQ(mDoc.undoStack()->count(), steps + 2);
    EXPECT_EQ(mDoc.undoStack()->undoText(), QStringLiteral("Edit branch"));
    ASSERT_EQ(mDoc.branchEdits(id).size(), 2u);
    EXPECT_TRUE(bytes().contains("\"format_version\": 3"));
    const QByteArray edited = bytes();
    // An edit that changes nothing removes the branch's edit.
    skel::BranchEdit plain;
    plain.branch = "0.2";
    mDoc.editBranch(id, plain);
    EXPECT_EQ(mDoc.branchEdits(id).size(), 1u);
    mDoc.undoStack()->undo();
    EXPECT_EQ(bytes(), edited);
    mDoc.clearBranchEdits(id);
    EXPECT_EQ(mDoc.undoStack()->undoText(), QStringLiteral("Clear branch edits"));
    EXPECT_TRUE(mDoc.branchEdits(id).empty());
    mDoc.undoStack()->undo();
    EXPECT_EQ(bytes(), edited);
    mDoc.undoStack()->undo();
    mDoc.undoStack()->undo();
    EXPECT_EQ(bytes(), before);
    EXPECT_TRUE(bytes().contains("\"format_version\": 2"));
    // Out of range: refused, naming the setting and its range; nothing pushed.
    skel::BranchEdit tooLong;
    tooLong.branch = "0.1";
    tooLong.length = 25.0f;
    try {
        mDoc.editBranch(id, tooLong);
        ADD_FAILURE() << "accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("length 25 is out of range [0.05, 20]"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(mDoc.editBranch(9999, cut), InvalidInput);
    EXPECT_EQ(bytes(), before);
}

// Issue 42: one spec for the project's settings. Its ranges are the engine's (a wind at each
// end of a range is accepted, past it refused by the document and by the parser alike), its
// defaults the engine's, and a settings edit names what it changed.
TEST_F(DocumentTest, SettingsSpecIsWhatTheDocumentAndTheFileAccept) {
    namespace spec = doc::settings;
    const wind::WindSettings defaults;
    EXPECT_EQ(spec::kWindStrength.defaultValue, decimalOf(defaults.strength));
    EXPECT_EQ(spec::kWindGustiness.defaultValue, decimalOf(defaults.gustiness));
    EXPECT_EQ(spec::kWindFrequency.defaultValue, decimalOf(defaults.frequency));
    EXPECT_EQ(spec::kVariants.defaultValue, double(doc::kDefaultVariants));
    EXPECT_EQ(spec::kWindFrequency.rangeText(), "0.05 .. 5 Hz");
    struct Field {
        const doc::SettingSpec* spec;
        float wind::WindSettings::*member;
    };
    for (const Field& f : {Field{&spec::kWindStrength, &wind::WindSettings::strength},
                           Field{&spec::kWindGustiness, &wind::WindSettings::gustiness},
                           Field{&spec::kWindFrequency, &wind::WindSettings::frequency}}) {
        for (const double v : {f.spec->min, f.spec->max}) {
            wind::WindSettings w;
            w.*f.member = float(v);
            EXPECT_NO_THROW(mDoc.setWind(w)) << f.spec->key << " " << v;
        }
        for (const double v : {f.spec->min - 0.01, f.spec->max + 0.01}) {
            wind::WindSettings w;
            w.*f.member = float(v);
            EXPECT_THROW(mDoc.setWind(w), InvalidInput) << f.spec->key << " " << v;
            EXPECT_THROW(f.spec->check(v), InvalidInput) << f.spec->key << " " << v;
        }
    }
    // The species' K: the document's setter and the file's parser both hold the spec's range.
    ASSERT_FALSE(mDoc.project().species.empty());
    const std::string species = mDoc.project().species.front().name;
    EXPECT_NO_THROW(mDoc.setSpeciesVariants(species, int(spec::kVariants.max)));
    EXPECT_THROW(mDoc.setSpeciesVariants(species, int(spec::kVariants.max) + 1), InvalidInput);
    QByteArray text = bytes();
    const QByteArray k =
        QByteArray("\"variants\": ") + QByteArray::number(int(spec::kVariants.max));
    ASSERT_NE(text.indexOf(k), -1) << text.constData();
    text.replace(k,
                 QByteArray("\"variants\": ") + QByteArray::number(int(spec::kVariants.max) + 1));
    try {
        doc::parseProject(text, QString());
        ADD_FAILURE() << "variants past the spec's range were accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("[0, 256]"), std::string::npos) << e.what();
    }
    // A settings edit names what it changed; one that changes two names both.
    QList<doc::DocumentChange> changes;
    QObject::connect(&mDoc, &Document::changed,
                     [&](const doc::DocumentChange& c) { changes << c; });
    mDoc.setSeed(mDoc.project().seed + 1);
    ASSERT_FALSE(changes.isEmpty());
    EXPECT_EQ(changes.last().settings, QStringList{QStringLiteral("seed")});
    mDoc.setLight({0.1f, -1.0f, 0.4f});
    EXPECT_EQ(changes.last().settings, QStringList{QStringLiteral("light")});
}
