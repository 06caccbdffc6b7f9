// The room for editing a species graph as JSON (speciesgraphedit.h), the one species envelope
// (speciesfile.h), and the node editor's multi-step edits as single Document calls whose undo
// gives back the exact document.
#include "document/document.h"
#include "document/speciesfile.h"
#include "document/speciesgraphedit.h"
#include "engine/graph/graph.h"
#include "engine/util/error.h"

#include <gtest/gtest.h>

#include <functional>

#include <QCoreApplication>

using namespace sylva;
using sylva::Value;

namespace {

Value sampleGraph() {
    return Value::parseJson(R"({
        "nodes": [
            {"id": "grow", "type": "lsystem", "params": {"grammar_file": "a.lsys"},
             "editor_position": [10, 20]},
            {"id": "mesh", "type": "tube_mesh", "params": {}, "inputs": ["grow"]}
        ],
        "output": "mesh"})");
}

std::string refusal(const std::function<void()>& edit) {
    try {
        edit();
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "accepted";
}

bool mentions(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST(SpeciesGraphEdit, ReadsNodesInputsPositionsAndParams) {
    const Value g = sampleGraph();
    ASSERT_EQ(doc::graphNodes(g).size(), 2u);
    EXPECT_TRUE(doc::graphNodes(Value(Value::Object{})).empty());
    ASSERT_NE(doc::findGraphNode(g, "mesh"), nullptr);
    EXPECT_EQ(doc::findGraphNode(g, "none"), nullptr);
    EXPECT_EQ(doc::nodeInputs(*doc::findGraphNode(g, "mesh")), std::vector<std::string>{"grow"});
    EXPECT_TRUE(doc::nodeInputs(*doc::findGraphNode(g, "grow")).empty());
    EXPECT_EQ(doc::nodeEditorPosition(*doc::findGraphNode(g, "grow")), glm::dvec2(10.0, 20.0));
    EXPECT_FALSE(doc::nodeEditorPosition(*doc::findGraphNode(g, "mesh")));
    EXPECT_EQ(doc::nodeParam(g, "s", "grow", "grammar_file").toString(), "a.lsys");
    EXPECT_TRUE(doc::nodeParam(g, "s", "grow", "generations").isNull());
    EXPECT_EQ(refusal([&] { doc::nodeParam(g, "s", "none", "x"); }),
              "species 's' has no node 'none'");
    EXPECT_EQ(doc::splitParamPath("grow.generations"),
              std::make_pair(std::string("grow"), std::string("generations")));
    EXPECT_TRUE(mentions(refusal([] { doc::splitParamPath("grow."); }), "node.param"));
    const Value numbered = Value::parseJson(R"({"id": "x", "inputs": [3]})");
    EXPECT_TRUE(mentions(refusal([&] { doc::nodeInputs(numbered); }), "an input id"));
}

TEST(SpeciesGraphEdit, EditsKeepTheGraphsRules) {
    Value g = sampleGraph();
    doc::setNodeParam(g, "s", "grow", "grammar", Value("axiom: F\n"));
    EXPECT_TRUE(doc::nodeParam(g, "s", "grow", "grammar_file").isNull()); // the text replaces it
    doc::setNodeParam(g, "s", "grow", "grammar", Value());
    EXPECT_TRUE(doc::nodeParam(g, "s", "grow", "grammar").isNull());

    EXPECT_EQ(doc::freshNodeId(g, "leaves"), "leaves");
    doc::requireNodeType("leaves");
    EXPECT_TRUE(mentions(refusal([] { doc::requireNodeType("nope"); }), "known: adapt"));
    doc::addGraphNode(g, "s", "leaves", "leaves", Value(), {1.5f, 2.5f});
    EXPECT_EQ(doc::freshNodeId(g, "leaves"), "leaves2");
    EXPECT_EQ(doc::nodeEditorPosition(*doc::findGraphNode(g, "leaves")), glm::dvec2(1.5, 2.5));
    EXPECT_TRUE(doc::findGraphNode(g, "leaves")->find("params")->isObject());
    EXPECT_TRUE(
        mentions(refusal([&] { doc::addGraphNode(g, "s", "leaves", "leaves", Value(), {}); }),
                 "already has a node 'leaves'"));

    // mesh takes one input: connecting leaves replaces grow; connecting again changes nothing.
    doc::connectGraphNodes(g, "s", "grow", "leaves", {});
    doc::connectGraphNodes(g, "s", "leaves", "mesh", {});
    EXPECT_EQ(doc::nodeInputs(*doc::findGraphNode(g, "mesh")), std::vector<std::string>{"leaves"});
    const std::string before = g.toJson();
    doc::connectGraphNodes(g, "s", "leaves", "mesh", {});
    EXPECT_EQ(g.toJson(), before);
    EXPECT_TRUE(mentions(refusal([&] { doc::connectGraphNodes(g, "s", "mesh", "grow", {}); }),
                         "takes no input"));
    EXPECT_EQ(g.toJson(), before);

    EXPECT_TRUE(mentions(refusal([&] { doc::disconnectGraphNodes(g, "s", "grow", "mesh"); }),
                         "'grow' is not connected to 'mesh'"));
    doc::disconnectGraphNodes(g, "s", "grow", "leaves");
    EXPECT_EQ(doc::findGraphNode(g, "leaves")->find("inputs"), nullptr); // no empty list

    EXPECT_TRUE(mentions(refusal([&] { doc::removeGraphNode(g, "s", "mesh"); }), "output"));
    doc::removeGraphNode(g, "s", "leaves");
    EXPECT_EQ(doc::findGraphNode(g, "leaves"), nullptr);
    EXPECT_EQ(doc::findGraphNode(g, "mesh")->find("inputs"), nullptr); // its edges went too

    doc::setGraphOutput(g, "s", "grow");
    EXPECT_EQ(g.string("output", ""), "grow");
    EXPECT_EQ(refusal([&] { doc::setGraphOutput(g, "s", "x"); }), "species 's' has no node 'x'");
    doc::setNodeEditorPosition(g, "s", "mesh", {3.0f, 4.0f});
    EXPECT_EQ(doc::nodeEditorPosition(*doc::findGraphNode(g, "mesh")), glm::dvec2(3.0, 4.0));
}

TEST(SpeciesGraphEdit, StandaloneGraphInlinesGrammarsAndDropsPositions) {
    const Value g = doc::standaloneGraph(sampleGraph(),
                                         [](const std::string& node) { return "text of " + node; });
    const Value* grow = doc::findGraphNode(g, "grow");
    EXPECT_EQ(grow->find("params")->string("grammar", ""), "text of grow");
    EXPECT_EQ(grow->find("params")->find("grammar_file"), nullptr);
    EXPECT_EQ(grow->find("editor_position"), nullptr);
}

TEST(SpeciesEnvelope, OneBuilderForFilesAndInlineSpecies) {
    const Value bare = doc::speciesEnvelope("oak", sampleGraph(), std::nullopt);
    EXPECT_EQ(bare.string("format", ""), "sylva-species");
    EXPECT_EQ(bare.number("format_version", 0), doc::kSpeciesFormatVersion);
    EXPECT_EQ(bare.string("name", ""), "oak");
    EXPECT_EQ(bare.find("traits"), nullptr);
    const Value traits(Value::Object{{"wood_density", 700.0}});
    const Value full = doc::speciesEnvelope("oak", sampleGraph(), traits);
    EXPECT_EQ(full.find("traits")->toJson(), traits.toJson());

    const graph::SpeciesGraph g = doc::speciesFromGraph("oak", sampleGraph(), traits, "/base");
    EXPECT_EQ(g.name, "oak");
    EXPECT_EQ(g.output, "mesh");
    EXPECT_EQ(g.baseDir, "/base");
    EXPECT_EQ(g.traits.woodDensity, 700.0);
    // A species file is written through the same envelope.
    EXPECT_EQ(doc::parseSpecies(doc::serializeSpecies(g), "oak", "/base").traits.woodDensity,
              700.0);
}

namespace {

class NodeEditTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        static int argc = 1;
        static char name[] = "test_document";
        static char* argv[] = {name, nullptr};
        if (!QCoreApplication::instance()) new QCoreApplication(argc, argv);
    }
    void SetUp() override {
        mDoc.open(QStringLiteral(SYLVA_SOURCE_DIR "/resources/demo/alder-reference.sylva"));
    }
    doc::Document mDoc;
};

// The node editor's clipboard: grow → leaves, at (100, 50) and (300, 50).
Value::Array clipboard() {
    return Value::parseJson(R"([
        {"id": "grow", "type": "lsystem", "params": {"grammar": "axiom: F\n"},
         "editor_position": [100, 50]},
        {"id": "leaves", "type": "leaves", "params": {"size": 0.3}, "inputs": ["grow"],
         "editor_position": [300, 50]}])")
        .toArray();
}

} // namespace

TEST_F(NodeEditTest, PasteIsOneStepAndUndoGivesBackTheExactDocument) {
    const QByteArray original = mDoc.serialized();
    const int steps = mDoc.undoStack()->count();
    const std::vector<std::string> made = mDoc.pasteNodes("alder", clipboard(), {10.0, 20.0});
    EXPECT_EQ(made, (std::vector<std::string>{"lsystem", "leaves"}));
    EXPECT_EQ(mDoc.undoStack()->count(), steps + 1);
    EXPECT_EQ(mDoc.undoStack()->undoText().toStdString(), "Paste nodes");
    // The copied layout, its top-left corner at the cursor; the edge among the copies.
    EXPECT_EQ(mDoc.nodePosition("alder", "lsystem"), glm::vec2(10.0f, 20.0f));
    EXPECT_EQ(mDoc.nodePosition("alder", "leaves"), glm::vec2(210.0f, 20.0f));
    const Value g = mDoc.speciesGraph("alder");
    EXPECT_EQ(doc::nodeInputs(*doc::findGraphNode(g, "leaves")),
              std::vector<std::string>{"lsystem"});
    EXPECT_EQ(mDoc.param("alder", "leaves.size").toNumber(), 0.3);
    const QByteArray pasted = mDoc.serialized();

    mDoc.undoStack()->undo();
    EXPECT_EQ(mDoc.serialized(), original);
    mDoc.undoStack()->redo();
    EXPECT_EQ(mDoc.serialized(), pasted);
    mDoc.undoStack()->undo();

    // All or nothing: a copy the graph refuses leaves no step and no node behind.
    Value::Array bad = clipboard();
    bad[1].objectRef()["params"] = Value(Value::Object{{"size", -1.0}});
    EXPECT_FALSE(mentions(refusal([&] { mDoc.pasteNodes("alder", bad, {}); }), "accepted"));
    EXPECT_EQ(mDoc.serialized(), original);
    EXPECT_EQ(mDoc.undoStack()->index(), steps);
    EXPECT_EQ(mDoc.undoStack()->count(), steps + 1); // only the undone paste, to redo
}

TEST_F(NodeEditTest, DeletingAndMovingSeveralNodesAreOneStepEach) {
    const QByteArray original = mDoc.serialized();
    const int steps = mDoc.undoStack()->count();
    const std::string graphBefore = mDoc.speciesGraph("alder").toJson();
    mDoc.pasteNodes("alder", clipboard(), {0.0, 0.0});
    const QByteArray pasted = mDoc.serialized();
    mDoc.moveNodes("alder", {{"lsystem", {5.0f, 6.0f}}, {"leaves", {7.0f, 8.0f}}});
    EXPECT_EQ(mDoc.undoStack()->undoText().toStdString(), "Move nodes");
    EXPECT_EQ(mDoc.nodePosition("alder", "leaves"), glm::vec2(7.0f, 8.0f));
    mDoc.moveNodes("alder", {{"leaves", {9.0f, 8.0f}}});
    EXPECT_EQ(mDoc.undoStack()->undoText().toStdString(), "Move node leaves");

    // The edge between two deleted nodes goes with them; a refused step refuses all.
    EXPECT_TRUE(mentions(refusal([&] {
                             mDoc.removeNodes("alder", {"leaves"}, {{"grow", "mesh"}});
                         }),
                         "the tree needs it"));
    EXPECT_EQ(mDoc.undoStack()->count(), steps + 3);
    mDoc.removeNodes("alder", {"lsystem", "leaves"}, {{"lsystem", "leaves"}});
    EXPECT_EQ(mDoc.undoStack()->undoText().toStdString(), "Delete nodes");
    EXPECT_EQ(mDoc.undoStack()->count(), steps + 4);
    EXPECT_EQ(mDoc.speciesGraph("alder").toJson(), graphBefore);
    mDoc.undoStack()->setIndex(steps + 1);
    EXPECT_EQ(mDoc.serialized(), pasted);
    mDoc.undoStack()->setIndex(steps);
    EXPECT_EQ(mDoc.serialized(), original);
}
