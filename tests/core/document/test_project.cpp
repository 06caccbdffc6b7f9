#include "document/formatupgrade.h"
#include "document/project.h"
#include "document/scenebuild.h"
#include "engine/util/error.h"
#include "engine/util/random.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>

using namespace sylva;

namespace {

// The public contract example of the forest issue, verbatim.
const char* kContract = R"({ "format": "sylva-project", "format_version": 1, "seed": 7,
  "species":   [ { "name": "alder", "file": "species/alder.json" } ],
  "domains":   [ { "shape": "rectangle", "min": [-50, -50], "max": [50, 50], "counts": { "alder": 1000 } } ],
  "instances": [ { "species": "alder", "position": [0, 0, 0], "rotation": 0, "scale": 1, "seed": 3 } ],
  "obstacles": [ { "file": "meshes/wall.obj", "translate": [0, 0, 0], "rotate": [0, 0, 0], "scale": [1, 1, 1] } ],
  "camera":    { "position": [0, 20, 80], "target": [0, 0, 0] },
  "light":     { "direction": [0.3, -1, 0.2] } })";

std::string errorOf(const std::string& json) {
    try {
        doc::parseProject(QByteArray::fromStdString(json), "p.sylva");
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Project, ReadsThePublicContract) {
    const doc::Project p = doc::parseProject(kContract, "/proj/forest.sylva");
    EXPECT_EQ(p.seed, 7u);
    ASSERT_EQ(p.species.size(), 1u);
    EXPECT_EQ(p.species[0].file, "species/alder.json");
    EXPECT_EQ(p.resolve(p.species[0].file), "/proj/species/alder.json");
    ASSERT_EQ(p.domains.size(), 1u);
    EXPECT_EQ(p.domains[0].counts.at("alder"), 1000);
    EXPECT_FLOAT_EQ(p.domains[0].min.x, -50.0f);
    ASSERT_EQ(p.instances.size(), 1u);
    EXPECT_EQ(p.instances[0].seed, 3u);
    ASSERT_EQ(p.obstacles.size(), 1u);
    EXPECT_EQ(p.obstacles[0].file, "meshes/wall.obj");
    EXPECT_FLOAT_EQ(p.cameraPosition.z, 80.0f);
    EXPECT_FLOAT_EQ(p.lightDirection.y, -1.0f);
}

TEST(Project, RoundTripsByteIdentically) {
    const doc::Project p = doc::parseProject(kContract, "/proj/forest.sylva");
    const QByteArray saved = doc::serializeProject(p);
    const doc::Project again = doc::parseProject(saved, "/proj/forest.sylva");
    EXPECT_EQ(again.appVersion, SYLVA_VERSION); // the saving version is recorded
    doc::Project expected = p;
    expected.appVersion = again.appVersion;
    EXPECT_EQ(again, expected);
    EXPECT_EQ(doc::serializeProject(again), saved);
}

TEST(Project, FloatsAreSavedAsTheDecimalsTheyWereWrittenAs) {
    // 0.3 is held as a float; widened to a double it would save as 0.30000001192092896, so an
    // unedited project saved again would differ from its file.
    const doc::Project p = doc::parseProject(kContract, "/proj/forest.sylva");
    const QByteArray saved = doc::serializeProject(p);
    EXPECT_TRUE(saved.contains("[0.3,-1,0.2]")) << saved.toStdString();
    EXPECT_FALSE(saved.contains("0.3000000")) << saved.toStdString();
    doc::Project windy = p;
    windy.wind = wind::WindSettings{{0.1f, 0.0f, -0.7f}, 0.3f, 0.1f, 0.45f};
    const QByteArray w = doc::serializeProject(windy);
    EXPECT_TRUE(w.contains("\"strength\": 0.3")) << w.toStdString();
    EXPECT_TRUE(w.contains("[0.1,0,-0.7]")) << w.toStdString();
}

TEST(Project, WindIsSavedOnlyWhenSetAndRoundTrips) {
    doc::Project p = doc::parseProject(kContract, "/proj/forest.sylva");
    EXPECT_FALSE(p.wind);
    EXPECT_FALSE(doc::serializeProject(p).contains("\"wind\""));
    p.wind = wind::WindSettings{{0.0f, 0.0f, -1.0f}, 1.25f, 0.75f, 0.4f};
    const QByteArray saved = doc::serializeProject(p);
    EXPECT_TRUE(saved.contains("\"wind\""));
    const doc::Project again = doc::parseProject(saved, "/proj/forest.sylva");
    ASSERT_TRUE(again.wind);
    EXPECT_EQ(*again.wind, *p.wind);
    EXPECT_EQ(doc::serializeProject(again), saved);
    EXPECT_THROW(
        doc::parseProject(R"({"format":"sylva-project","format_version":1,"wind":{"strength":9}})",
                          "/proj/x.sylva"),
        sylva::InvalidInput);
}

TEST(Project, KeepsKeysItDoesNotKnow) {
    std::string json = kContract;
    json.insert(1, R"("render_settings": {"samples": 64}, )");
    const doc::Project p = doc::parseProject(QByteArray::fromStdString(json), "x.sylva");
    const QByteArray saved = doc::serializeProject(p);
    EXPECT_TRUE(saved.contains("\"samples\": 64"));
}

TEST(Project, NewerFilesLoadWithAWarning) {
    std::string json = kContract;
    json.replace(json.find("\"format_version\": 1"), 19, "\"format_version\": 9");
    doc::LoadReport report;
    const doc::Project p = doc::parseProject(QByteArray::fromStdString(json), "new.sylva", &report);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_NE(report.warnings[0].find("newer Sylva"), std::string::npos);
    EXPECT_EQ(p.species.size(), 1u);
}

TEST(Project, BadInputIsRefusedWithAMessage) {
    EXPECT_NE(errorOf("{").find("p.sylva:1:2"), std::string::npos);
    EXPECT_NE(
        errorOf(R"({"format":"sylva-species","format_version":1})").find("not a sylva-project"),
        std::string::npos);
    EXPECT_NE(
        errorOf(R"({"format":"sylva-project","format_version":1,"domains":[{"shape":"circle"}]})")
            .find("rectangle, polygon or terrain"),
        std::string::npos);
    EXPECT_NE(
        errorOf(
            R"({"format":"sylva-project","format_version":1,"species":[{"name":"a","file":"a.json"}],
                         "instances":[{"species":"b"}]})")
            .find("unknown species \"b\""),
        std::string::npos);
    EXPECT_NE(
        errorOf(
            R"({"format":"sylva-project","format_version":1,"species":[{"name":"a","file":"a.json"}],
                         "instances":[{"species":"a","scale":0}]})")
            .find("instances[0].scale must be in [0.001, 1000]"),
        std::string::npos);
    EXPECT_NE(
        errorOf(R"({"format":"sylva-project","format_version":1,"camera":{"position":[1,2]}})")
            .find("camera.position must be [x, y, z]"),
        std::string::npos);
}

TEST(Project, SavesAtomically) {
    const QString dir = QDir::tempPath() + "/sylva-test-project";
    QDir(dir).removeRecursively();
    QDir().mkpath(dir);
    doc::Project p = doc::parseProject(kContract, dir + "/a.sylva");
    doc::saveProject(p, dir + "/a.sylva");
    const doc::Project loaded = doc::loadProject(dir + "/a.sylva");
    EXPECT_EQ(doc::serializeProject(loaded), doc::serializeProject(p));
    EXPECT_EQ(QDir(dir).entryList(QDir::Files | QDir::Hidden).size(), 1);
    EXPECT_THROW(doc::saveProject(p, "/nonexistent-dir/a.sylva"), IoError);
}

TEST(UpgradeChain, RunsStepsInOrderAndOnlyFromTheFilesVersion) {
    std::vector<std::string> log;
    const std::vector<doc::UpgradeStep> steps = {
        {1, "rename trees to instances",
         [&](sylva::Value::Object& o) {
             log.push_back("1");
             o["instances"] = o["trees"];
             o.erase("trees");
         }},
        {2, "add light",
         [&](sylva::Value::Object& o) {
             log.push_back("2");
             o["light"] = sylva::Value::Object{{"direction", sylva::Value::Array{0, -1, 0}}};
         }},
    };
    sylva::Value v1 = sylva::Value::parseJson(R"({"format":"f","format_version":1,"trees":[1]})");
    const doc::UpgradeReport r = doc::upgradeFormat(v1.objectRef(), "f", 3, steps, "a", true);
    EXPECT_EQ(log, (std::vector<std::string>{"1", "2"}));
    EXPECT_EQ(r.applied.size(), 2u);
    EXPECT_EQ(
        v1.toJson(),
        R"({"format":"f","format_version":3,"instances":[1],"light":{"direction":[0,-1,0]}})");

    log.clear();
    sylva::Value v2 = sylva::Value::parseJson(R"({"format":"f","format_version":2})");
    doc::upgradeFormat(v2.objectRef(), "f", 3, steps, "a", true);
    EXPECT_EQ(log, std::vector<std::string>{"2"});

    sylva::Value v4 = sylva::Value::parseJson(R"({"format":"f","format_version":4})");
    EXPECT_THROW(doc::upgradeFormat(v4.objectRef(), "f", 3, steps, "a", true), InvalidInput);
    EXPECT_EQ(doc::upgradeFormat(v4.objectRef(), "f", 3, steps, "a", false).warnings.size(), 1u);
    sylva::Value gap = sylva::Value::parseJson(R"({"format":"f","format_version":1})");
    EXPECT_THROW(doc::upgradeFormat(gap.objectRef(), "f", 3, {steps[1]}, "a", true), InvalidInput);
}

// Found by fuzz_species (UBSan): a format_version of 1e116 was converted to int. Versions are
// whole numbers from 1 to 1e9; a larger one is an error, not a "newer file" warning.
TEST(UpgradeChain, HugeVersionsAreRefused) {
    for (const char* v : {"1e116", "4294967296", "1000000001"}) {
        sylva::Value root =
            sylva::Value::parseJson(std::string(R"({"format":"f","format_version":)") + v + "}");
        try {
            doc::upgradeFormat(root.objectRef(), "f", 1, {}, "a.json", false);
            ADD_FAILURE() << v;
        } catch (const InvalidInput& e) {
            EXPECT_STREQ(e.what(),
                         "a.json: \"format_version\" must be a whole number from 1 to 1000000000");
        }
    }
    sylva::Value newer = sylva::Value::parseJson(R"({"format":"f","format_version":1000000000})");
    EXPECT_EQ(doc::upgradeFormat(newer.objectRef(), "f", 1, {}, "a", false).warnings.size(), 1u);
}

TEST(Project, ImportsTheReferenceSceneDescription) {
    const QString dir = QDir::tempPath() + "/sylva-test-refscene";
    QDir().mkpath(dir);
    QFile f(dir + "/scene.json");
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(R"({"plants":[{"file":"alder.txt","quantity":100},{"file":"bush.txt","quantity":20}],
                "collision_meshes":["wall.obj","rock.obj"]})");
    f.close();
    const doc::Project p = doc::importReferenceScene(dir + "/scene.json");
    ASSERT_EQ(p.species.size(), 2u);
    EXPECT_EQ(p.species[0].name, "alder");
    EXPECT_EQ(p.domains.at(0).counts.at("alder"), 100);
    EXPECT_EQ(p.domains.at(0).counts.at("bush"), 20);
    ASSERT_EQ(p.obstacles.size(), 2u);
    EXPECT_EQ(p.obstacles[1].file, "rock.obj");
    // The imported project saves as a regular project and loads back the same.
    const QByteArray saved = doc::serializeProject(p);
    EXPECT_EQ(doc::serializeProject(doc::parseProject(saved, dir + "/scene.sylva")), saved);
}

// Found while fuzzing the import (fuzz_project, UBSan): two quantities of one species summed
// past INT_MAX. Quantities are limited like a project's counts: [0, 1e8], also summed.
TEST(Project, ReferenceSceneQuantitiesAreLimited) {
    const QString dir = QDir::tempPath() + "/sylva-test-refscene";
    QDir().mkpath(dir);
    auto importError = [&](const char* json) -> std::string {
        QFile f(dir + "/quantities.json");
        EXPECT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(json);
        f.close();
        try {
            doc::importReferenceScene(dir + "/quantities.json");
        } catch (const InvalidInput& e) {
            return e.what();
        }
        return "";
    };
    const std::string sum = importError(
        R"({"plants":[{"file":"a.txt","quantity":60000000},{"file":"a.txt","quantity":60000000}]})");
    EXPECT_NE(sum.find("the quantities of \"a\" must be whole numbers in [0, 1e8], also summed"),
              std::string::npos)
        << sum;
    EXPECT_NE(importError(R"({"plants":[{"file":"a.txt","quantity":-5}]})").find("[0, 1e8]"),
              std::string::npos);
    EXPECT_EQ(importError(R"({"plants":[{"file":"a.txt","quantity":100000000}]})"), "");
}

TEST(Project, InlineSpeciesGraphsBecomeSceneSpecies) {
    const char* json = R"({"format":"sylva-project","format_version":1,
      "species":[{"name":"bush","graph":{"nodes":[
          {"id":"grow","type":"lsystem","params":{"grammar":"axiom: F\nF -> FF\n"}},
          {"id":"mesh","type":"tube_mesh","inputs":["grow"],"params":{"resolution":5}}],
        "output":"mesh"}}],
      "instances":[{"species":"bush","position":[1,0,2],"rotation":90,"seed":4}]})";
    const doc::Project p = doc::parseProject(json, "/proj/inline.sylva");
    const forest::ForestScene s = doc::makeForestScene(p);
    ASSERT_EQ(s.species.size(), 1u);
    EXPECT_EQ(s.species[0].graph.name, "bush");
    EXPECT_EQ(s.species[0].graph.skeletonSource(), "grow");
    EXPECT_EQ(s.species[0].graph.findNode("mesh")->params.integer("resolution", 0), 5);
    ASSERT_EQ(s.handPlaced.size(), 1u);
    EXPECT_NEAR(s.handPlaced[0].rotation, 3.14159265f / 2.0f, 1e-6f);
    EXPECT_EQ(s.handPlaced[0].seed, 4u);
}

// An edit of a species regrows the forest only when a tree grows from it (the editor asks this).
TEST(Project, UsesSpeciesOfItsTreesAndOfDomainsThatScatterThem) {
    doc::Project p;
    for (const char* name : {"alder", "birch", "oak", "pine"}) {
        doc::ProjectSpecies species;
        species.name = name;
        p.species.push_back(species);
    }
    doc::ProjectInstance tree;
    tree.species = "alder";
    p.instances.push_back(tree);
    doc::PlacementDomain domain;
    domain.counts = {{"birch", 3}, {"oak", 0}};
    p.domains.push_back(domain);
    EXPECT_TRUE(p.usesSpecies("alder"));  // a hand-placed tree
    EXPECT_TRUE(p.usesSpecies("birch"));  // scattered by a domain
    EXPECT_FALSE(p.usesSpecies("oak"));   // a domain that scatters none
    EXPECT_FALSE(p.usesSpecies("pine"));  // in the project, on no tree
    EXPECT_FALSE(p.usesSpecies("maple")); // not in the project at all
}

// A tree added without a seed gets one from the project seed and the trees before it, below
// the seed limit; the menus, the Python APIs and the document's duplicate all use this one
// definition, and the values are part of the byte-identical guarantee (pinned here).
TEST(Project, NewTreeSeedsDependOnlyOnTheProjectSeedAndTheCount) {
    doc::Project p;
    p.seed = 42;
    EXPECT_EQ(p.newTreeSeed(0), doc::treeSeed(mixSeed(42, 1)));
    EXPECT_EQ(p.newTreeSeed(0), 478109794u); // what every release so far gave
    EXPECT_NE(p.newTreeSeed(0), p.newTreeSeed(1));
    for (std::size_t n = 0; n < 100; ++n)
        EXPECT_LT(p.newTreeSeed(n), doc::kTreeSeedLimit);
    doc::Project q = p;
    q.instances.resize(3); // the count is the caller's: the trees themselves do not matter
    EXPECT_EQ(q.newTreeSeed(5), p.newTreeSeed(5));
    q.seed = 43;
    EXPECT_NE(q.newTreeSeed(5), p.newTreeSeed(5));
}

// Issue 30: format 2 gives trees and domains stable ids. A format-1 file is upgraded on load
// (trees 1, 2, ... in file order, as the editor numbered them; domains 1, 2, ...), says so,
// and saves as format 2 with the ids and the next tree id.
TEST(Project, Format1UpgradesToStableIds) {
    const std::string v1 = R"({ "format": "sylva-project", "format_version": 1, "seed": 7,
      "species": [ { "name": "alder", "file": "a.json" } ],
      "domains": [ { "shape": "rectangle", "min": [0, 0], "max": [9, 9], "counts": { "alder": 3 } },
                   { "shape": "rectangle", "min": [20, 0], "max": [29, 9], "counts": { "alder": 3 } } ],
      "instances": [ { "species": "alder", "position": [0, 0, 0], "seed": 3 },
                     { "species": "alder", "position": [5, 0, 0], "seed": 4 } ] })";
    doc::LoadReport report;
    const doc::Project p = doc::parseProject(QByteArray::fromStdString(v1), "old.sylva", &report);
    ASSERT_EQ(report.upgrades.size(), 1u);
    EXPECT_NE(report.upgrades[0].find("stable ids"), std::string::npos) << report.upgrades[0];
    EXPECT_EQ(p.instances[0].id, 1u);
    EXPECT_EQ(p.instances[1].id, 2u);
    EXPECT_EQ(p.nextTreeId, 3u);
    EXPECT_EQ(p.domains[0].id, 1u);
    EXPECT_EQ(p.domains[1].id, 2u);
    EXPECT_EQ(p.species[0].variants, doc::kDefaultVariants);
    const QByteArray saved = doc::serializeProject(p);
    EXPECT_TRUE(saved.contains("\"format_version\": 2")) << saved.toStdString();
    EXPECT_TRUE(saved.contains("\"next_tree_id\": 3"));
    EXPECT_TRUE(saved.contains("\"variants\": 8"));
    doc::LoadReport again;
    EXPECT_EQ(doc::parseProject(saved, "old.sylva", &again).instances, p.instances);
    EXPECT_TRUE(again.upgrades.empty());
    // The ids reach the engine's scene.
    const std::string v2 = R"({ "format": "sylva-project", "format_version": 2,
      "species": [ { "name": "alder", "graph": {"nodes": [], "output": ""}, "variants": 3 } ],
      "domains": [ { "id": 40, "shape": "rectangle", "min": [0, 0], "max": [9, 9] } ],
      "instances": [ { "id": 12, "species": "alder" }, { "species": "alder" } ],
      "next_tree_id": 20 })";
    const doc::Project q = doc::parseProject(QByteArray::fromStdString(v2), "new.sylva");
    EXPECT_EQ(q.instances[0].id, 12u);
    EXPECT_EQ(q.instances[1].id, 20u); // a hand-written tree without an id gets the next one
    EXPECT_EQ(q.nextTreeId, 21u);
    EXPECT_EQ(q.domains[0].id, 40u);
    EXPECT_EQ(q.species[0].variants, 3);
}

TEST(Project, IdsAndVariantsAreChecked) {
    const std::string head = R"({ "format": "sylva-project", "format_version": 2,
      "species": [ { "name": "a", "file": "a.json" )";
    EXPECT_NE(errorOf(head + R"(} ], "instances": [ { "id": 3, "species": "a" },
      { "id": 3, "species": "a" } ] })")
                  .find("instances[0] and instances[1] have the same id 3"),
              std::string::npos);
    EXPECT_NE(errorOf(head + R"(} ], "domains": [ { "id": 2, "min": [0, 0], "max": [1, 1] },
      { "id": 2, "min": [0, 0], "max": [1, 1] } ] })")
                  .find("domains[0] and domains[1] have the same id 2"),
              std::string::npos);
    EXPECT_NE(errorOf(head + R"(} ], "instances": [ { "id": 1.5, "species": "a" } ] })")
                  .find("instances[0].id must be a whole number in [1, 999999999]"),
              std::string::npos);
    EXPECT_NE(errorOf(head + R"(, "variants": 257 } ] })")
                  .find("species[0].variants must be a whole number in [0, 256]"),
              std::string::npos);
    EXPECT_NE(errorOf(head + R"(} ], "next_tree_id": 0 })").find("next_tree_id must be"),
              std::string::npos);
}

// Trees built in memory (scripts) get the ids saving would give: after every id in use and
// never an id twice.
TEST(Project, AssignIdsFillsGapsAndDuplicates) {
    doc::Project p;
    p.instances.resize(4);
    p.instances[0].id = 5;
    p.instances[2].id = 5;
    p.domains.resize(2);
    p.domains[1].id = 9;
    doc::assignIds(p);
    EXPECT_EQ(p.instances[0].id, 5u);
    EXPECT_EQ(p.instances[1].id, 6u);
    EXPECT_EQ(p.instances[2].id, 7u);
    EXPECT_EQ(p.instances[3].id, 8u);
    EXPECT_EQ(p.nextTreeId, 9u);
    EXPECT_EQ(p.domains[0].id, 10u);
    EXPECT_EQ(p.domains[1].id, 9u);
}
