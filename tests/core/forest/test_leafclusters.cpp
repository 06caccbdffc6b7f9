// Issue #33: leaf clusters. Each broadleaf of the species library is meshed with its cluster
// cards (leaf_cluster_size, the atlas from make_textures.py) and with one card a leaf; the
// clusters must cost at least 4x fewer leaf triangles and cover the same silhouette: IoU >= 0.92
// of the pixel centres covered, seen from the side (as test_crownshape) and from a camera
// above and in front (the gallery's view), by the CPU rasterizer of coverageraster.h.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "coverageraster.h"
#include "engine/graph/graph.h"
#include "engine/mesh/leafclusters.h"
#include "engine/util/image.h"
#include "presetfile.h"

using namespace sylva;

namespace {

const std::filesystem::path kPresets = SYLVA_PRESETS_DIR;

std::size_t leafTriangles(const mesh::Mesh& m) {
    std::size_t n = 0;
    for (const mesh::Submesh& s : m.submeshes)
        if (s.material == "leaf") n += s.indexCount / 3;
    return n;
}

// Side (orthographic, along -Z) and camera (perspective, from above and in front) views of the
// tree framed by its bounds; the same cameras for both meshes.
std::array<test::RasterCamera, 2> views(const mesh::Mesh& m) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : m.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 c = 0.5f * (lo + hi);
    const float r = 0.5f * glm::length(hi - lo);
    test::RasterCamera side;
    side.width = side.height = 400;
    side.viewProj = glm::ortho(c.x - r, c.x + r, c.y - r, c.y + r, -1e4f, 1e4f);
    const test::RasterCamera cam = test::RasterCamera::lookAt(
        c + glm::normalize(glm::vec3(0.8f, 0.45f, 1.0f)) * (2.6f * r), c, 40.0, 480, 480);
    return {side, cam};
}

struct ClusterMeasure {
    std::size_t perLeaf = 0, clustered = 0; ///< leaf-card triangles
    double ratio = 0.0, iou[2] = {0, 0}, cover[2] = {0, 0};
};

// The species meshed with its cluster cards and with one card a leaf, seed 1.
ClusterMeasure measureClusters(const char* species) {
    ClusterMeasure r;
    graph::SpeciesGraph g = sylva::testing::loadPreset(kPresets / (std::string(species) + ".json"));
    std::string meshNode;
    for (const graph::NodeDesc& n : g.nodes)
        if (n.type == "tube_mesh") meshNode = n.id;
    EXPECT_FALSE(meshNode.empty()) << species;
    graph::Evaluator clustered(g);
    const std::shared_ptr<const mesh::Mesh> withClusters = clustered.evaluate(1).mesh;
    graph::Evaluator single(g);
    single.setParam(meshNode, "leaf_cluster_size", Value(0));
    const std::shared_ptr<const mesh::Mesh> perLeaf = single.evaluate(1).mesh;
    EXPECT_TRUE(withClusters && perLeaf) << species;
    if (!withClusters || !perLeaf) return r;
    r.perLeaf = leafTriangles(*perLeaf);
    r.clustered = leafTriangles(*withClusters);
    r.ratio =
        static_cast<double>(r.perLeaf) / static_cast<double>(std::max<std::size_t>(r.clustered, 1));
    const auto cams = views(*perLeaf);
    std::vector<std::uint8_t> scratch;
    // Conservative, as crownshape.h's silhouettes: a pixel any card touches is covered, so
    // that the measure is the crown's silhouette, not where pixel centres fall among leaves
    // of a few pixels (with pixel centres the IoU was 0.75-0.9 at the same coverage).
    constexpr bool conservative = true;
    for (int v = 0; v < 2; ++v) {
        const test::Mask a =
            test::coverage(*perLeaf, glm::mat4(1.0f), cams[v], scratch, conservative);
        const test::Mask b =
            test::coverage(*withClusters, glm::mat4(1.0f), cams[v], scratch, conservative);
        r.iou[v] = test::iou(a, b);
        r.cover[v] = static_cast<double>(b.size()) / static_cast<double>(a.size());
    }
    std::printf("| %s | %zu | %zu | %.1f | %.3f | %.3f | %.2f / %.2f |\n", species, r.perLeaf,
                r.clustered, r.ratio, r.iou[0], r.iou[1], r.cover[0], r.cover[1]);
    std::fflush(stdout);
    return r;
}

void printHeader() {
    std::printf("| species | leaf triangles, one card a leaf | with clusters | ratio | IoU side "
                "| IoU camera | covered, side / camera |\n|---|---|---|---|---|---|---|\n");
}

} // namespace

TEST(LeafClusters, GroupsReachTheMeanSizeAndKeepEveryLeafOnce) {
    std::vector<skel::Leaf> leaves;
    for (int i = 0; i < 600; ++i) {
        skel::Leaf l;
        l.position = glm::vec3(0.07f * (i % 10), 0.05f * ((i / 10) % 6), 0.09f * (i / 60));
        l.size = 0.1f;
        leaves.push_back(l);
    }
    const auto groups = mesh::groupLeaves(leaves, 1.0, 6);
    EXPECT_LE(groups.size() * 6, leaves.size());
    std::vector<int> seen(leaves.size(), 0);
    for (const auto& g : groups)
        for (std::uint32_t i : g)
            ++seen[i];
    for (int s : seen)
        EXPECT_EQ(s, 1);
    EXPECT_EQ(mesh::groupLeaves(leaves, 1.0, 0).size(), leaves.size());
    // Cards: four vertices each, UVs inside one tile of the atlas, deterministic.
    mesh::Mesh a, b;
    mesh::LeafClusterSettings cs;
    cs.leavesPerCard = 6;
    cs.seed = 3;
    const std::size_t cards = mesh::appendLeafClusterCards(a, leaves, {}, cs);
    mesh::appendLeafClusterCards(b, leaves, {}, cs);
    EXPECT_EQ(cards, groups.size());
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.vertexCount(), 4 * cards);
    // Every spray tile is used (seven sprays, 4 x 2 atlas), and a card's four corners lie in one.
    const glm::vec2 grid(mesh::kClusterAtlasColumns, mesh::kClusterAtlasRows);
    std::vector<int> used(mesh::kClusterAtlasColumns * mesh::kClusterAtlasRows, 0);
    for (std::size_t k = 0; k < cards; ++k) {
        const glm::vec2 t = glm::floor(a.uvs[4 * k] * grid);
        for (int c = 1; c < 4; ++c)
            EXPECT_EQ(glm::floor(a.uvs[4 * k + c] * grid), t);
        ++used[static_cast<std::size_t>(t.y * grid.x + t.x)];
    }
    for (int tile = 0; tile < mesh::kClusterSprays; ++tile)
        EXPECT_GT(used[static_cast<std::size_t>(tile)], 0) << "spray tile " << tile;
    cs.leavesPerCard = 65;
    EXPECT_THROW(mesh::appendLeafClusterCards(a, leaves, {}, cs), InvalidInput);
}

// Issue #33: crossed cluster cards (the Scots pine's tufts): every card of two or more
// leaves comes with a second one of the same size along the same centre line, at right
// angles to it, showing another spray; a leaf alone keeps one card.
TEST(LeafClusters, CrossedCardsShareTheCentreLineAtRightAngles) {
    std::vector<skel::Leaf> leaves;
    for (int i = 0; i < 300; ++i) {
        skel::Leaf l;
        l.position = glm::vec3(0.07f * (i % 10), 0.05f * ((i / 10) % 6), 0.09f * (i / 60));
        l.orientation = glm::angleAxis(0.3f * static_cast<float>(i), glm::vec3(0.3f, 1, 0.2f));
        l.size = 0.1f;
        leaves.push_back(l);
    }
    skel::Leaf alone;
    alone.position = glm::vec3(50.0f);
    alone.size = 0.1f;
    leaves.push_back(alone);
    mesh::LeafClusterSettings cs;
    cs.leavesPerCard = 6;
    cs.seed = 3;
    mesh::Mesh flat, crossed;
    const std::size_t groups = mesh::appendLeafClusterCards(flat, leaves, {}, cs);
    cs.crossed = true;
    const std::size_t cards = mesh::appendLeafClusterCards(crossed, leaves, {}, cs);
    std::size_t singles = 0;
    for (const auto& g : mesh::groupLeaves(leaves, 1.0, 6))
        singles += g.size() == 1;
    EXPECT_GE(singles, 1u);
    EXPECT_EQ(cards, 2 * groups - singles); // a leaf alone has one card
    ASSERT_EQ(crossed.vertexCount(), 4 * cards);
    std::size_t f = 0, c = 0, pairs = 0;
    const glm::vec2 grid(mesh::kClusterAtlasColumns, mesh::kClusterAtlasRows);
    while (f < flat.vertexCount()) {
        // The first card of each group is the flat one, as it was.
        for (int k = 0; k < 4; ++k)
            EXPECT_EQ(crossed.positions[c + k], flat.positions[f + k]);
        const glm::vec3* p = &crossed.positions[c];
        if (glm::floor(crossed.uvs[c] * grid) == glm::vec2(3, 1)) { // the single-leaf tile
            f += 4;
            c += 4;
            continue;
        }
        const glm::vec3* q = &crossed.positions[c + 4];
        EXPECT_LT(glm::length(0.5f * (p[0] + p[1]) - 0.5f * (q[0] + q[1])), 1e-5f);
        EXPECT_LT(glm::length(0.5f * (p[2] + p[3]) - 0.5f * (q[2] + q[3])), 1e-5f);
        EXPECT_NEAR(glm::length(p[0] - p[1]), glm::length(q[0] - q[1]), 1e-5f);
        EXPECT_NEAR(glm::dot(glm::normalize(p[0] - p[1]), glm::normalize(q[0] - q[1])), 0.0f,
                    1e-4f);
        EXPECT_NE(glm::floor(crossed.uvs[c] * grid), glm::floor(crossed.uvs[c + 4] * grid));
        // Its normal faces as its winding does.
        const glm::vec3 face = glm::cross(q[1] - q[0], q[2] - q[0]);
        EXPECT_GT(glm::dot(face, crossed.normals[c + 4]), 0.0f);
        ++pairs;
        f += 4;
        c += 8;
    }
    EXPECT_EQ(pairs, groups - singles);
}

TEST(LeafClusters, BroadleavesCostAQuarterOfTheLeafTrianglesAtTheSameSilhouette) {
    graph::registerBuiltinNodeTypes();
    printHeader();
    for (const char* species : {"english-oak", "european-beech", "norway-maple", "silver-birch",
                                "lombardy-poplar", "weeping-willow"}) {
        const ClusterMeasure m = measureClusters(species);
        EXPECT_GE(m.ratio, 4.0) << species;
        // 0.92, a margin over the 0.9 (the oak and the poplar were at 0.902 and 0.903
        // before their crowns were grown fuller: larger lit clusters, inner clusters, more
        // leaves a twig; a lacy crown's every edge is a fringe a cluster card cannot follow).
        EXPECT_GE(m.iou[0], 0.92) << species << " from the side";
        EXPECT_GE(m.iou[1], 0.92) << species << " from the camera";
    }
}

// Issue #33: the conifers and the privet carry needle (or leaf) sprays from their own cluster
// atlases (make_textures.py: the pine's and the spruce's drawn needle by needle), at the same
// silhouette as one card a shoot and at a quarter of its leaf triangles. (The rhododendron's
// card is already a rosette under a truss, one a shoot tip; it keeps one card a rosette.)
TEST(LeafClusters, ConifersAndShrubsCarrySpraysAtTheSameSilhouette) {
    graph::registerBuiltinNodeTypes();
    printHeader();
    for (const char* species : {"scots-pine", "norway-spruce", "italian-cypress", "privet-hedge"}) {
        const ClusterMeasure m = measureClusters(species);
        EXPECT_GE(m.ratio, 4.0) << species;
        EXPECT_GE(m.iou[0], 0.9) << species << " from the side";
        EXPECT_GE(m.iou[1], 0.9) << species << " from the camera";
    }
}

// Issue #33: the Norway spruce's bark. Its hanging side shoots, a centimetre thick inside
// their needle sprays, get no bark below bare_twig_radius and four sides below twig_radius:
// at least 2.5x fewer triangles than every twig an 8-sided tube, at the same silhouette.
TEST(LeafClusters, SpruceTwigsCostLessBarkAtTheSameSilhouette) {
    graph::registerBuiltinNodeTypes();
    graph::SpeciesGraph g = sylva::testing::loadPreset(kPresets / "norway-spruce.json");
    graph::Evaluator lean(g);
    const std::shared_ptr<const mesh::Mesh> a = lean.evaluate(1).mesh;
    graph::Evaluator full(g);
    full.setParam("mesh", "twig_radius", Value(0));
    full.setParam("mesh", "bare_twig_radius", Value(0));
    const std::shared_ptr<const mesh::Mesh> b = full.evaluate(1).mesh;
    ASSERT_TRUE(a && b);
    EXPECT_EQ(leafTriangles(*a), leafTriangles(*b));
    const double ratio =
        static_cast<double>(b->triangleCount()) / static_cast<double>(a->triangleCount());
    const auto cams = views(*b);
    std::vector<std::uint8_t> scratch;
    double iou[2];
    for (int v = 0; v < 2; ++v)
        iou[v] = test::iou(test::coverage(*b, glm::mat4(1.0f), cams[v], scratch, true),
                           test::coverage(*a, glm::mat4(1.0f), cams[v], scratch, true));
    std::printf("norway-spruce: %zu triangles with every twig, %zu lean (%.1fx); IoU side %.4f, "
                "camera %.4f\n",
                b->triangleCount(), a->triangleCount(), ratio, iou[0], iou[1]);
    EXPECT_GE(ratio, 2.5);
    EXPECT_GE(iou[0], 0.98);
    EXPECT_GE(iou[1], 0.98);
}

namespace {

// Tile \p k of a cluster atlas (numbered from the bottom left along rows; image rows run down).
struct Tile {
    int x0, y0, size;
};
Tile atlasTile(const Image& atlas, int k) {
    const int size = atlas.width / mesh::kClusterAtlasColumns;
    const int col = k % mesh::kClusterAtlasColumns, row = k / mesh::kClusterAtlasColumns;
    return {col * size, (mesh::kClusterAtlasRows - 1 - row) * size, size};
}

} // namespace

// Issue #33: every cluster atlas has seven sprays that differ from each other (the cards of a
// crown do not repeat one picture) in the engine's 4 x 2 layout, and a deciduous species'
// autumn atlas mixes tones: its sprays' mean red / green differ, where its summer sprays' are
// one green.
TEST(LeafClusters, AtlasesHaveSevenDifferentSpraysAndAutumnMixesTones) {
    for (const char* species :
         {"english-oak", "european-beech", "norway-maple", "silver-birch", "lombardy-poplar",
          "weeping-willow", "scots-pine", "norway-spruce", "italian-cypress", "privet-hedge"}) {
        const Image atlas =
            readPng(kPresets / "textures" / (std::string(species) + "_leafcluster.png"));
        ASSERT_EQ(atlas.width, 1024) << species;
        ASSERT_EQ(atlas.height, 512) << species;
        std::vector<std::vector<std::uint8_t>> masks;
        for (int k = 0; k < mesh::kClusterSprays; ++k) {
            const Tile t = atlasTile(atlas, k);
            std::vector<std::uint8_t> m(static_cast<std::size_t>(t.size) * t.size);
            std::size_t covered = 0;
            for (int y = 0; y < t.size; ++y)
                for (int x = 0; x < t.size; ++x) {
                    const bool in = atlas.at(t.x0 + x, t.y0 + y)[3] >= 128;
                    m[static_cast<std::size_t>(y) * t.size + x] = in;
                    covered += in;
                }
            EXPECT_GT(covered, m.size() / 10) << species << " spray " << k << " is nearly empty";
            masks.push_back(std::move(m));
        }
        for (std::size_t a = 0; a < masks.size(); ++a)
            for (std::size_t b = a + 1; b < masks.size(); ++b) {
                std::size_t both = 0, either = 0;
                for (std::size_t i = 0; i < masks[a].size(); ++i) {
                    both += masks[a][i] && masks[b][i];
                    either += masks[a][i] || masks[b][i];
                }
                EXPECT_LT(static_cast<double>(both) / static_cast<double>(either), 0.8)
                    << species << " sprays " << a << " and " << b << " are alike";
            }
    }
    // Mean red / green of each spray's opaque texels; their spread across the seven sprays.
    const auto spread = [](const Image& atlas) {
        double lo = 1e9, hi = -1e9;
        for (int k = 0; k < mesh::kClusterSprays; ++k) {
            const Tile t = atlasTile(atlas, k);
            double r = 0.0, g = 0.0;
            for (int y = 0; y < t.size; ++y)
                for (int x = 0; x < t.size; ++x) {
                    const std::uint8_t* p = atlas.at(t.x0 + x, t.y0 + y);
                    if (p[3] < 128) continue;
                    r += p[0];
                    g += p[1];
                }
            lo = std::min(lo, r / std::max(g, 1.0));
            hi = std::max(hi, r / std::max(g, 1.0));
        }
        return hi - lo;
    };
    std::printf("| species | red/green spread of the sprays, summer | autumn |\n|---|---|---|\n");
    for (const char* species : {"english-oak", "european-beech", "norway-maple", "silver-birch",
                                "lombardy-poplar", "weeping-willow"}) {
        const std::filesystem::path stem = kPresets / "textures" / species;
        const double summer = spread(readPng(stem.string() + "_leafcluster.png"));
        const double autumn = spread(readPng(stem.string() + "_leafcluster_autumn.png"));
        std::printf("| %s | %.3f | %.3f |\n", species, summer, autumn);
        EXPECT_GT(autumn, 0.1) << species << ": the autumn sprays are one tone";
        EXPECT_GT(autumn, 2.0 * summer) << species;
    }
}
