#include "engine/util/error.h"
#include "engine/util/value.h"

#include <gtest/gtest.h>

#include <string>

using sylva::Value;

TEST(Value, JsonRoundTripIsCanonical) {
    const std::string text = R"({"b":[1,2.5,-3e-7,true,null],"a":{"z":"x\"y\n","y":{}},"c":0.1})";
    const Value v = Value::parseJson(text);
    // Keys sorted, shortest round-trip numbers.
    EXPECT_EQ(v.toJson(), R"({"a":{"y":{},"z":"x\"y\n"},"b":[1,2.5,-3e-07,true,null],"c":0.1})");
    EXPECT_EQ(Value::parseJson(v.toJson()), v);
    EXPECT_EQ(Value::parseJson(v.toJson()).hash(), v.hash());
}

TEST(Value, UnicodeEscapes) {
    EXPECT_EQ(Value::parseJson(R"("\u00e9\ud83c\udf33")").toString(), "\xC3\xA9\xF0\x9F\x8C\xB3");
}

TEST(Value, SyntaxErrorsCarryLineAndColumn) {
    try {
        Value::parseJson("{\n  \"a\": 1,\n  \"b\": ]\n}", "s.json");
        FAIL() << "no error";
    } catch (const sylva::InvalidInput& e) {
        ASSERT_EQ(e.diagnostics().size(), 1u);
        EXPECT_EQ(e.diagnostics()[0].line, 3);
        EXPECT_EQ(e.diagnostics()[0].column, 8);
        EXPECT_EQ(e.diagnostics()[0].file, "s.json");
    }
    EXPECT_THROW(Value::parseJson(R"({"a":1,"a":2})"), sylva::InvalidInput);
    EXPECT_THROW(Value::parseJson(R"([1,2)"), sylva::InvalidInput);
    EXPECT_THROW(Value::parseJson(R"("abc)"), sylva::InvalidInput);
    EXPECT_THROW(Value::parseJson("1 2"), sylva::InvalidInput);
}

TEST(Value, BadNumbersAreNamedWithTheirColumn) {
    auto message = [](const std::string& text) {
        try {
            (void)Value::parseJson(text, "n.json");
        } catch (const sylva::InvalidInput& e) {
            EXPECT_EQ(e.diagnostics().at(0).column, 7) << text;
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(R"({"a": 1e400})").find("number '1e400' is out of range"), std::string::npos);
    EXPECT_NE(message(R"({"a": 1.2.3})").find("malformed number '1.2.3'"), std::string::npos);
    EXPECT_NE(message(R"({"a": -})").find("malformed number '-'"), std::string::npos);
    // Strict JSON: no leading zeros, digits on both sides of '.', an exponent has digits.
    for (const char* bad : {"02", "-01", "2.", "2.e3", "1e", "1e+", "-.5", "1-2"})
        EXPECT_NE(message(std::string(R"({"a": )") + bad + "}")
                      .find(std::string("malformed number '") + bad + "'"),
                  std::string::npos)
            << bad;
    for (const char* good : {"0", "-0", "10", "0.5", "-0.25", "1e3", "1E-3", "2.5e+2"})
        EXPECT_EQ(message(std::string(R"({"a": )") + good + "}"), "no error") << good;
}

TEST(Value, TypedGettersNameTheKey) {
    const Value v = Value::parseJson(R"({"n":3,"s":"x","f":2.5})");
    EXPECT_EQ(v.integer("n", 0), 3);
    EXPECT_EQ(v.integer("missing", 7), 7);
    EXPECT_EQ(v.string("s", ""), "x");
    try {
        (void)v.integer("f", 0);
        FAIL();
    } catch (const sylva::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("f must be a whole number"), std::string::npos);
    }
    try {
        (void)v.number("s", 0);
        FAIL();
    } catch (const sylva::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("s must be a number"), std::string::npos);
    }
}

TEST(Value, LooseParsing) {
    EXPECT_TRUE(Value::parseLoose("3").isNumber());
    EXPECT_TRUE(Value::parseLoose("[1,2]").isArray());
    EXPECT_EQ(Value::parseLoose("ternary.lsys").toString(), "ternary.lsys");
}

// Species, projects and --set values nest at most 256 levels (the reader is recursive).
TEST(Value, JsonNestingIsLimited) {
    EXPECT_NO_THROW(Value::parseJson(std::string(200, '[') + std::string(200, ']')));
    try {
        Value::parseJson(std::string(300, '[') + std::string(300, ']'), "deep.json");
        FAIL() << "no limit";
    } catch (const sylva::InvalidInput& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("JSON nested too deeply"), std::string::npos) << m;
        EXPECT_NE(m.find("deep.json:1:"), std::string::npos) << m;
    }
    EXPECT_THROW(Value::parseJson(std::string(100000, '[')), sylva::InvalidInput);
}
