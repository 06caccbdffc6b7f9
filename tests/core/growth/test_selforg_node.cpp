// The `self_organizing` node and the presets that use it.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "engine/graph/graph.h"
#include "engine/growth/selforganizing.h"
#include "engine/nodes/selforganizingnode.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::growth;

namespace {
bool sameSkeleton(const skel::Skeleton& a, const skel::Skeleton& b) {
    return a.position == b.position && a.parent == b.parent && a.radius == b.radius &&
           a.order == b.order && a.flags == b.flags && a.leaves.size() == b.leaves.size();
}
} // namespace

TEST(SelfOrgNode, NodeReadsParamsAndSeed) {
    graph::NodeRegistry registry;
    registerSelfOrganizingNode(registry);
    const graph::NodeType* type = registry.find("self_organizing");
    ASSERT_NE(type, nullptr);
    graph::NodeDesc desc;
    desc.id = "grow";
    desc.type = "self_organizing";
    sylva::Value::Object o;
    o["cycles"] = 6;
    o["environment"] = "space_colonization";
    o["markers"] = 3000;
    o["crown_radius"] = 1.0;
    o["crown_top"] = 3.0;
    o["seed"] = 5;
    desc.params = sylva::Value(o);
    const std::filesystem::path base = ".";
    const std::string file = "test.species";
    graph::NodeContext ctx{desc, desc.params, {}, 0, false, base, file, noProgress()};
    const graph::NodeOutput out = type->evaluate(ctx);
    ASSERT_TRUE(out.skeleton);
    EXPECT_EQ(out.stats.at("internodes") + 1, static_cast<double>(out.skeleton->size()));
    EXPECT_EQ(out.stats.at("cycles"), 6);
    EXPECT_TRUE(out.stats.count("shed"));
    EXPECT_TRUE(out.timingsMs.count("grow"));
    SelfOrganizingParams direct = selfOrganizingParamsFrom(desc.params);
    EXPECT_TRUE(sameSkeleton(*out.skeleton, growSelfOrganizing(direct, 5)));
    // An overridden seed wins over the parameter.
    graph::NodeContext over{desc, desc.params, {}, 77, true, base, file, noProgress()};
    EXPECT_TRUE(sameSkeleton(*type->evaluate(over).skeleton, growSelfOrganizing(direct, 77)));

    sylva::Value bad = desc.params;
    bad.objectRef()["environment"] = "sunlight";
    graph::NodeContext badCtx{desc, bad, {}, 0, false, base, file, noProgress()};
    try {
        type->evaluate(badCtx);
        FAIL();
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("space_colonization"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("grow"), std::string::npos);
    }
    bad = desc.params;
    bad.objectRef()["lambda"] = -0.5;
    graph::NodeContext rangeCtx{desc, bad, {}, 0, false, base, file, noProgress()};
    EXPECT_THROW(type->evaluate(rangeCtx), InvalidInput);
    bad = desc.params;
    bad.objectRef()["max_internodes"] = 20;
    graph::NodeContext limitCtx{desc, bad, {}, 0, false, base, file, noProgress()};
    EXPECT_THROW(type->evaluate(limitCtx), LimitExceeded);
}

TEST(SelfOrgNode, PresetsParseAndValidate) {
    for (const char* name : {"so-broadleaf.json", "so-conifer.json", "so-shrub.json"}) {
        std::ifstream in(std::string(SYLVA_PRESETS_DIR) + "/" + name);
        ASSERT_TRUE(in) << name;
        std::stringstream text;
        text << in.rdbuf();
        const sylva::Value doc = sylva::Value::parseJson(text.str(), name);
        const sylva::Value* nodes = doc.find("graph")->find("nodes");
        ASSERT_NE(nodes, nullptr);
        bool found = false;
        for (const sylva::Value& n : nodes->toArray())
            if (n.string("type", "") == "self_organizing") {
                const sylva::Value* params = n.find("params");
                ASSERT_NE(params, nullptr);
                for (const auto& [key, value] : params->toObject()) {
                    const auto& names = selfOrganizingParamNames();
                    EXPECT_NE(std::find(names.begin(), names.end(), key), names.end()) << key;
                }
                EXPECT_NO_THROW(selfOrganizingParamsFrom(*params)) << name;
                found = true;
            }
        EXPECT_TRUE(found) << name;
    }
}
