// Node parameters are read through their specs (issue 42): a default and a range are stated
// once, in the node's table, and the reading uses them.
#include <gtest/gtest.h>

#include <stdexcept>

#include "engine/growth/selforganizing.h"
#include "engine/nodes/paramspecs.h"
#include "engine/nodes/selforganizingnode.h"

using namespace sylva;

namespace {

std::vector<graph::ParamSpec> table() {
    using namespace sylva::nodes;
    return {number("length", 2.5, 0, 10, "m", "A length"), integer("count", 4, 1, 8, "A count"),
            boolean("on", true, "A switch"),
            choice("shape", "round", {"round", "square"}, "A shape"),
            number("derived", nullptr, -1, 1, "", "Unset: derived by the node")};
}

} // namespace

TEST(ParamReader, AbsentValuesAreTheSpecsDefaults) {
    const std::vector<graph::ParamSpec> specs = table();
    const Value none = Value::Object{};
    const nodes::ParamReader read(specs, none);
    EXPECT_EQ(read.number("length"), 2.5);
    EXPECT_EQ(read.integer("count"), 4);
    EXPECT_TRUE(read.boolean("on"));
    EXPECT_EQ(read.text("shape"), "round");
    EXPECT_EQ(read.numberOr("derived", 0.25), 0.25);
}

TEST(ParamReader, GivenValuesAreReadAndCheckedAgainstTheSpecsRange) {
    const std::vector<graph::ParamSpec> specs = table();
    const Value given = Value::Object{{"length", 7.0}, {"count", 8}, {"derived", -0.5}};
    const nodes::ParamReader read(specs, given);
    EXPECT_EQ(read.number("length"), 7.0);
    EXPECT_EQ(read.integer("count"), 8);
    EXPECT_EQ(read.numberOr("derived", 0.25), -0.5);

    const Value wrong = Value::Object{{"length", 12.0}, {"count", 2.5}, {"derived", 3.0}};
    const nodes::ParamReader bad(specs, wrong);
    EXPECT_THROW(
        {
            try {
                bad.number("length");
            } catch (const InvalidInput& e) {
                EXPECT_NE(std::string(e.what()).find("length must be in [0, 10] m"),
                          std::string::npos)
                    << e.what();
                throw;
            }
        },
        InvalidInput);
    EXPECT_THROW(bad.integer("count"), InvalidInput); // a whole number
    EXPECT_THROW(bad.numberOr("derived", 0.0), InvalidInput);
    EXPECT_THROW(bad.requireIn("length", -1.0), InvalidInput);
}

TEST(ParamReader, ANameOutsideTheTableOrADefaultNobodyStatedIsAProgrammingError) {
    const std::vector<graph::ParamSpec> specs = table();
    const Value none = Value::Object{};
    const nodes::ParamReader read(specs, none);
    EXPECT_THROW(read.number("width"), std::logic_error);
    EXPECT_THROW(read.number("derived"), std::logic_error);
}

TEST(ParamReader, SelfOrganizingDefaultsAreTheTablesAndTheGrowthStructs) {
    // The node reads its defaults from its table; the growth module has its own for callers
    // that use it directly. They are the same numbers.
    const growth::SelfOrganizingParams fromTable =
        growth::selfOrganizingParamsFrom(Value::Object{});
    const growth::SelfOrganizingParams plain;
    EXPECT_EQ(fromTable.cycles, plain.cycles);
    EXPECT_EQ(fromTable.markers, plain.markers);
    EXPECT_EQ(fromTable.alpha, plain.alpha);
    EXPECT_EQ(fromTable.lambda, plain.lambda);
    EXPECT_EQ(fromTable.perceptionAngle, plain.perceptionAngle);
    EXPECT_EQ(fromTable.shadowB, plain.shadowB);
    EXPECT_EQ(fromTable.internodeLength, plain.internodeLength);
    EXPECT_EQ(fromTable.tipRadius, plain.tipRadius);
    EXPECT_EQ(fromTable.leafSize, plain.leafSize);
    EXPECT_EQ(fromTable.leafAge, plain.leafAge);
    EXPECT_EQ(fromTable.maxInternodes, plain.maxInternodes);
    EXPECT_EQ(fromTable.environment, plain.environment);
    EXPECT_EQ(fromTable.allocation, plain.allocation);
}
