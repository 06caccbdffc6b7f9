// Issue #43: hand edits of single branches in a project: the file (format 3), and every forest
// build applying them after growth (pruning lowers the segment count and the wood volume,
// bending moves the tip, an edit of a missing branch is reported and the project still builds).
#include "document/project.h"
#include "document/scenebuild.h"
#include "engine/forest/forestbuild.h"
#include "engine/forest/treecache.h"
#include "engine/skeleton/branches.h"
#include "engine/util/error.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace sylva;

namespace {

std::string errorOf(const std::string& json) {
    try {
        doc::parseProject(QByteArray::fromStdString(json), "p.sylva");
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "";
}

const std::string kHead = R"({ "format": "sylva-project", "format_version": 3,
  "species": [ { "name": "a", "file": "a.json" } ],
  "instances": [ { "id": 1, "species": "a", "branch_edits": )";

doc::Project birch() {
    doc::Project p;
    doc::ProjectSpecies s;
    s.name = "birch";
    s.file = SYLVA_SOURCE_DIR "/presets/silver-birch.json";
    p.species.push_back(s);
    doc::ProjectInstance t;
    t.id = 1;
    t.species = "birch";
    t.seed = 11;
    t.rotation = 40.0;
    t.position = {3.0f, 0.0f, -2.0f};
    p.instances.push_back(t);
    p.nextTreeId = 2;
    return p;
}

struct Built {
    forest::ForestStats stats;
    std::shared_ptr<const skel::Skeleton> skeleton;
    glm::mat4 transform{1.0f};
    forest::TreeMetrics metrics;
};

Built build(const doc::Project& p) {
    forest::ForestOptions options;
    options.buildMeshes = false;
    Built out;
    const forest::ForestScene scene = doc::makeForestScene(p);
    out.stats =
        forest::buildForest(scene, options, [&](const std::vector<forest::ForestTree>& batch) {
            for (const forest::ForestTree& t : batch) {
                out.skeleton = t.skeleton;
                out.transform = t.instance.transform();
                out.metrics = t.metrics;
            }
        });
    return out;
}

const skel::Branch& branch(const std::vector<skel::Branch>& bs, const std::string& id) {
    auto it = std::find_if(bs.begin(), bs.end(), [&](const skel::Branch& b) { return b.id == id; });
    EXPECT_NE(it, bs.end()) << id;
    return *it;
}

} // namespace

TEST(BranchEdits, SavedAsFormat3AndReadBack) {
    doc::Project p = birch();
    EXPECT_TRUE(doc::serializeProject(p).contains("\"format_version\": 2"));
    skel::BranchEdit prune;
    prune.branch = "0.3";
    prune.prune = true;
    skel::BranchEdit bend;
    bend.branch = "0.1";
    bend.bend = glm::vec3(1.0f, 0.5f, 0.0f);
    bend.length = 0.8f;
    bend.radius = 1.2f;
    bend.lock = true;
    p.instances[0].branchEdits = {prune, bend};
    const QByteArray saved = doc::serializeProject(p);
    EXPECT_TRUE(saved.contains("\"format_version\": 3")) << saved.toStdString();
    EXPECT_TRUE(saved.contains("\"branch_edits\"")) << saved.toStdString();
    EXPECT_TRUE(saved.contains("\"length\": 0.8")) << saved.toStdString();
    doc::LoadReport report;
    const doc::Project back = doc::parseProject(saved, "p.sylva", &report);
    EXPECT_EQ(back.instances[0].branchEdits, p.instances[0].branchEdits);
    EXPECT_TRUE(report.upgrades.empty());
    EXPECT_EQ(doc::serializeProject(back), saved);
}

TEST(BranchEdits, MalformedEditsAreRefusedWithTheirPlace) {
    EXPECT_NE(
        errorOf(kHead + R"([ { "branch": "0.1", "length": 30 } ] } ] })")
            .find("p.sylva:3:82: error: instances[0].branch_edits[0].length 30 is out of range "
                  "[0.05, 20]"),
        std::string::npos)
        << errorOf(kHead + R"([ { "branch": "0.1", "length": 30 } ] } ] })");
    EXPECT_NE(errorOf(kHead + R"([ { "branch": "0.1", "radius": 0.01 } ] } ] })")
                  .find("branch_edits[0].radius 0.01 is out of range [0.05, 20]"),
              std::string::npos);
    EXPECT_NE(
        errorOf(kHead + R"([ { "branch": "0.1" }, { "branch": "0.2", "bend": [0, 0, 0] } ] } ] })")
            .find("branch_edits[1].bend must be a non-zero direction"),
        std::string::npos);
    EXPECT_NE(errorOf(kHead + R"([ { "prune": true } ] } ] })").find("needs a \"branch\""),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + R"([ { "branch": "0.x" } ] } ] })").find("is not a branch id"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + R"([ { "branch": "0", "prune": true } ] } ] })")
                  .find("is a trunk and cannot be pruned"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + R"([ { "branch": "0.1", "bent": [0, 1, 0] } ] } ] })")
                  .find("unknown key \"bent\""),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + R"([ { "branch": "0.1" }, { "branch": "0.1" } ] } ] })")
                  .find("branch 0.1 is edited twice"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + R"({ "branch": "0.1" } } ] })").find("branch_edits"),
              std::string::npos);
}

TEST(BranchEdits, MalformedEditsSayFileLineAndColumn) {
    // The entry, or the key the message names, where it is written.
    const std::string text = R"({ "format": "sylva-project", "format_version": 3,
  "species": [ { "name": "a", "file": "a.json" } ],
  "instances": [
    { "id": 1, "species": "a", "branch_edits": [
        { "branch": "0.1" },
        { "branch": "0.2",
          "radius": 40 } ] },
    { "id": 2, "species": "a", "branch_edits": [ { "prune": true } ] } ] })";
    EXPECT_NE(errorOf(text).find("p.sylva:7:11: error: instances[0].branch_edits[1].radius 40 is "
                                 "out of range [0.05, 20]"),
              std::string::npos)
        << errorOf(text);
    std::string second = text;
    second.replace(second.find("\"radius\": 40"), 12, "\"radius\": 2 ");
    EXPECT_NE(errorOf(second).find("p.sylva:8:50: error: instances[1].branch_edits[0] needs a "
                                   "\"branch\""),
              std::string::npos)
        << errorOf(second);
}

TEST(BranchEdits, AnEditReappliesToTheKeptGrownTree) {
    // With a TreeCache (the editor's), a branch edit re-applies the edits to the skeleton as
    // grown instead of growing the tree again; the result is the same as a build from scratch.
    doc::Project p = birch();
    forest::TreeCache cache;
    forest::ForestOptions options;
    options.buildMeshes = false;
    options.keepGrown = true;
    options.cache = &cache;
    auto run = [&](const doc::Project& project, forest::ForestOptions o) {
        std::shared_ptr<const skel::Skeleton> out;
        forest::buildForest(doc::makeForestScene(project), o,
                            [&](const std::vector<forest::ForestTree>& batch) {
                                for (const forest::ForestTree& t : batch)
                                    out = t.skeleton;
                            });
        return out;
    };
    run(p, options);
    EXPECT_EQ(cache.grownHits(), 0u);
    skel::BranchEdit e;
    e.branch = "0.2";
    e.bend = glm::vec3(0.0f, 1.0f, 1.0f);
    p.instances[0].branchEdits = {e};
    const std::shared_ptr<const skel::Skeleton> edited = run(p, options);
    EXPECT_EQ(cache.grownHits(), 1u);
    e.bend = glm::vec3(1.0f, 1.0f, 0.0f);
    p.instances[0].branchEdits = {e};
    const std::shared_ptr<const skel::Skeleton> again = run(p, options);
    EXPECT_EQ(cache.grownHits(), 1u); // counted per build
    forest::ForestOptions fresh = options;
    fresh.cache = nullptr;
    const std::shared_ptr<const skel::Skeleton> scratch = run(p, fresh);
    ASSERT_TRUE(again && scratch);
    EXPECT_EQ(again->position, scratch->position);
    EXPECT_EQ(again->radius, scratch->radius);
    EXPECT_NE(edited->position, again->position);
}

TEST(BranchEdits, EveryBuildAppliesThemAfterGrowth) {
    const doc::Project plain = birch();
    const Built before = build(plain);
    const std::vector<skel::Branch> branches = skel::branchesOf(*before.skeleton);
    // The longest limb: pruned, the tree loses its segments and wood.
    const skel::Branch* limb = nullptr;
    for (const skel::Branch& b : branches)
        if (b.order == 1 && (!limb || b.length > limb->length)) limb = &b;
    ASSERT_TRUE(limb);
    std::size_t carried = 0;
    for (const skel::Branch& b : branches)
        carried += b.id.rfind(limb->id + ".", 0) == 0 ? 1 : 0;

    doc::Project pruned = plain;
    skel::BranchEdit cut;
    cut.branch = limb->id;
    cut.prune = true;
    pruned.instances[0].branchEdits = {cut};
    const Built afterPrune = build(pruned);
    EXPECT_LT(afterPrune.skeleton->segmentCount(), before.skeleton->segmentCount());
    EXPECT_EQ(skel::branchesOf(*afterPrune.skeleton).size(), branches.size() - 1 - carried);
    EXPECT_LT(afterPrune.metrics.woodVolumeM3, before.metrics.woodVolumeM3);
    EXPECT_LT(afterPrune.stats.metrics.dryBiomassKg, before.stats.metrics.dryBiomassKg);
    EXPECT_EQ(afterPrune.stats.branchEdits, 1u);
    EXPECT_EQ(afterPrune.stats.orphanedEdits, 0u);

    // Bent straight up in the world (the tree stands turned by 40 degrees): its tip moves and
    // its base -> tip points up.
    doc::Project bent = plain;
    skel::BranchEdit up;
    up.branch = limb->id;
    up.bend = glm::vec3(0.0f, 2.0f, 0.0f);
    bent.instances[0].branchEdits = {up};
    const Built afterBend = build(bent);
    const std::vector<skel::Branch> bentBranches = skel::branchesOf(*afterBend.skeleton);
    const skel::Branch& moved = branch(bentBranches, limb->id);
    const glm::vec3 base = glm::vec3(afterBend.transform * glm::vec4(moved.base, 1.0f));
    const glm::vec3 tip = glm::vec3(afterBend.transform * glm::vec4(moved.tip, 1.0f));
    EXPECT_GT(glm::length(moved.tip - limb->tip), 0.1f);
    EXPECT_NEAR(glm::normalize(tip - base).y, 1.0f, 1e-4f);
    EXPECT_EQ(afterBend.skeleton->size(), before.skeleton->size());

    // A branch the tree does not have: reported, the project still builds, nothing changes.
    doc::Project orphan = plain;
    skel::BranchEdit missing;
    missing.branch = "0.999.4";
    missing.length = 2.0f;
    orphan.instances[0].branchEdits = {missing};
    const Built afterOrphan = build(orphan);
    EXPECT_EQ(afterOrphan.stats.orphanedEdits, 1u);
    ASSERT_EQ(afterOrphan.stats.warnings.size(), 1u);
    EXPECT_NE(afterOrphan.stats.warnings[0].find("tree 1: the edit of branch 0.999.4"),
              std::string::npos)
        << afterOrphan.stats.warnings[0];
    EXPECT_EQ(afterOrphan.skeleton->position, before.skeleton->position);
    EXPECT_TRUE(before.stats.warnings.empty());
}

TEST(BranchEdits, ALockedBranchIsSavedAndKeptThroughAnotherSeed) {
    doc::Project p = birch();
    const Built grown = build(p);
    const std::vector<skel::Branch> branches = skel::branchesOf(*grown.skeleton);
    const skel::Branch* limb = nullptr;
    for (const skel::Branch& b : branches)
        if (b.order == 1 && (!limb || b.length > limb->length)) limb = &b;
    ASSERT_TRUE(limb);
    skel::BranchEdit lock;
    lock.branch = limb->id;
    lock.length = 0.7f;
    skel::lockBranch(*grown.skeleton, {}, lock);
    ASSERT_GT(lock.locked.size(), 3u);
    p.instances[0].branchEdits = {lock};
    // The kept geometry goes through the file exactly.
    const QByteArray saved = doc::serializeProject(p);
    EXPECT_TRUE(saved.contains("\"locked\"")) << saved.left(2000).toStdString();
    const doc::Project back = doc::parseProject(saved, "p.sylva");
    EXPECT_EQ(back.instances[0].branchEdits, p.instances[0].branchEdits);
    EXPECT_EQ(doc::serializeProject(back), saved);
    // Regrown from another seed (another topology): the locked branch is there, node for node.
    p.instances[0].seed = 12;
    const Built regrown = build(p);
    EXPECT_EQ(regrown.stats.orphanedEdits, 0u);
    const skel::Skeleton& s = *regrown.skeleton;
    const std::size_t n = lock.locked.size();
    ASSERT_GT(s.size(), n);
    const std::size_t first = s.size() - n; // grafted nodes come last
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 d = s.position[first + i] - s.position[first];
        const glm::vec3 kept = lock.locked[i].offset - lock.locked[0].offset;
        EXPECT_NEAR(glm::length(d - kept), 0.0f, 1e-4f) << i;
        EXPECT_EQ(s.radius[first + i], lock.locked[i].radius);
    }
    // Malformed kept geometry: refused with its place.
    const std::string bad =
        kHead + R"([ { "branch": "0.1", "lock": true, "locked": { "base": [0, 1, 0],
        "nodes": [ [3, 1, 0.1, 0, 0, 0, 0, 0, 0, 1] ] } } ] } ] })";
    EXPECT_NE(errorOf(bad).find("instances[0].branch_edits[0]: branch 0.1: locked node 0"),
              std::string::npos)
        << errorOf(bad);
    const std::string unlocked =
        kHead + R"([ { "branch": "0.1", "locked": { "nodes": [] } } ] } ] })";
    EXPECT_NE(errorOf(unlocked).find("belongs to a locked edit"), std::string::npos)
        << errorOf(unlocked);
}
