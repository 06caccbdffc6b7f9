#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../common/testwords.h"
#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"
#include "engine/lsystem/turtle.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "referenceturtle.h"

using sylva::lsys::interpret;
using sylva::lsys::TurtleSettings;
using sylva::testing::makeWord;

namespace {

sylva::skel::Skeleton run(const std::string& text, TurtleSettings settings = {}) {
    return interpret(makeWord(text), settings);
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

} // namespace

TEST(Turtle, TurnLeftEndsAtMinusX) {
    const auto s = run("F+F");
    ASSERT_EQ(s.size(), 3u);
    expectNear(s.position[0], {0, 0, 0});
    expectNear(s.position[1], {0, 1, 0});
    expectNear(s.position[2], {-1, 1, 0});
    EXPECT_EQ(s.parent[0], -1);
    EXPECT_EQ(s.parent[1], 0);
    EXPECT_EQ(s.parent[2], 1);
}

TEST(Turtle, RotationSigns) {
    expectNear(run("F-F").position.back(), {1, 1, 0});
    expectNear(run("F&F").position.back(), {0, 1, -1}); // pitch down: towards -up
    expectNear(run("F^F").position.back(), {0, 1, 1});
    // Roll left by 90 moves left onto -up, so turning left then heads -Z.
    expectNear(run("F\\+F").position.back(), {0, 1, -1});
    expectNear(run("F/+F").position.back(), {0, 1, 1});
    expectNear(run("F|F").position.back(), {0, 0, 0});
}

TEST(Turtle, FrameFollowsConvention) {
    const auto s = run("F+F");
    const glm::quat q = s.orientation[2];
    expectNear(sylva::skel::headingOf(q), {-1, 0, 0});
    expectNear(sylva::skel::leftOf(q), {0, -1, 0});
    expectNear(sylva::skel::upOf(q), {0, 0, 1});
}

TEST(Turtle, ParametersOverrideDefaults) {
    expectNear(run("F(2)").position.back(), {0, 2, 0});
    const float h = static_cast<float>(std::sqrt(0.5));
    expectNear(run("+(45)F").position.back(), {-h, h, 0});
    TurtleSettings settings;
    settings.angleDegrees = 45.0;
    settings.step = 3.0;
    expectNear(run("+F", settings).position.back(), {-3 * h, 3 * h, 0});
}

TEST(Turtle, PushPopMakesLateralBranch) {
    const auto s = run("F[+F]F");
    ASSERT_EQ(s.size(), 4u);
    expectNear(s.position[2], {-1, 1, 0});
    EXPECT_EQ(s.parent[2], 1);
    EXPECT_EQ(s.order[2], 1);
    expectNear(s.position[3], {0, 2, 0});
    EXPECT_EQ(s.parent[3], 1);
    EXPECT_EQ(s.order[3], 0);
    EXPECT_TRUE(s.flags[1] & sylva::skel::kFork);
    EXPECT_TRUE(s.flags[2] & sylva::skel::kTip);
    EXPECT_TRUE(s.flags[3] & sylva::skel::kTip);
}

TEST(Turtle, MoveStartsNewRoot) {
    const auto s = run("FfF");
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s.parent[2], -1);
    expectNear(s.position[2], {0, 2, 0});
    expectNear(s.position[3], {0, 3, 0});
    EXPECT_EQ(s.parent[3], 2);
}

TEST(Turtle, CutSkipsRestOfBranch) {
    const auto s = run("F[+F%F[F]F]F");
    ASSERT_EQ(s.size(), 4u);
    expectNear(s.position[3], {0, 2, 0});
    EXPECT_EQ(s.parent[3], 1);
    // At top level % cuts to the end of the word; parameters after it are skipped too.
    const auto t = run("F(2)%F(5)[F(7)]");
    ASSERT_EQ(t.size(), 2u);
    expectNear(t.position[1], {0, 2, 0});
}

TEST(Turtle, WidthWithAndWithoutParameter) {
    const auto s = run("F!F!(0.5)F");
    ASSERT_EQ(s.size(), 4u);
    EXPECT_FLOAT_EQ(s.radius[0], 0.05f);
    EXPECT_FLOAT_EQ(s.radius[1], 0.05f);
    EXPECT_FLOAT_EQ(s.radius[2], 0.035f);
    EXPECT_FLOAT_EQ(s.radius[3], 0.25f);
    // Width is part of the pushed state.
    const auto t = run("F[!F]F");
    EXPECT_FLOAT_EQ(t.radius[2], 0.035f);
    EXPECT_FLOAT_EQ(t.radius[3], 0.05f);
}

TEST(Turtle, LevelLeftMakesLeftHorizontal) {
    const auto s = run("+(90)/(30)&(20)$F");
    const glm::quat q = s.orientation.back();
    const glm::vec3 h = sylva::skel::headingOf(q);
    const glm::vec3 l = sylva::skel::leftOf(q);
    const glm::vec3 u = sylva::skel::upOf(q);
    EXPECT_NEAR(l.y, 0.0f, 1e-6f);
    EXPECT_GT(u.y, 0.0f);
    // $ only rolls: the heading is the one before it.
    const auto before = run("+(90)/(30)&(20)F");
    expectNear(h, sylva::skel::headingOf(before.orientation.back()));
    expectNear(s.position.back() - s.position[s.parent.back()], h);
    EXPECT_NEAR(glm::dot(h, l), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(h, u), 0.0f, 1e-6f);
}

TEST(Turtle, LeavesFromJ) {
    TurtleSettings settings;
    settings.leafSize = 0.2;
    const auto s = run("FJ(0.3)[+FJ]", settings);
    ASSERT_EQ(s.leaves.size(), 2u);
    EXPECT_FLOAT_EQ(s.leaves[0].size, 0.3f);
    EXPECT_EQ(s.leaves[0].node, 1);
    expectNear(s.leaves[0].position, {0, 1, 0});
    EXPECT_FLOAT_EQ(s.leaves[1].size, 0.2f);
    EXPECT_EQ(s.leaves[1].node, 2);
    expectNear(s.leaves[1].position, {-1, 1, 0});
    expectNear(sylva::skel::headingOf(s.leaves[1].orientation), {-1, 0, 0});
}

// Oracle: ABOP's H, L, U vectors rotated explicitly, on random words.
TEST(Turtle, MatchesVectorTurtleOnRandomWords) {
    const std::string alphabet = "FF+-&^\\/|$[]f!";
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        sylva::Rng rng(seed);
        std::string text;
        int depth = 0;
        for (int i = 0; i < 300; ++i) {
            char c = alphabet[rng.below(alphabet.size())];
            if (c == ']' && depth == 0) c = 'F';
            depth += c == '[' ? 1 : c == ']' ? -1 : 0;
            text.push_back(c);
        }
        TurtleSettings settings;
        settings.angleDegrees = 10.0 + 40.0 * rng.uniform();
        const auto s = run(text, settings);

        struct V {
            glm::dvec3 p{0}, h{0, 1, 0}, l{-1, 0, 0}, u{0, 0, 1};
        };
        const double d = settings.angleDegrees * std::numbers::pi / 180.0;
        const double cd = std::cos(d), sd = std::sin(d);
        V t;
        std::vector<V> stack;
        std::vector<glm::dvec3> drawn;
        for (char c : text) {
            V o = t;
            switch (c) {
            case 'F':
                t.p += t.h;
                drawn.push_back(t.p);
                break;
            case 'f':
                t.p += t.h;
                break;
            case '+':
                t.h = o.h * cd + o.l * sd;
                t.l = -o.h * sd + o.l * cd;
                break;
            case '-':
                t.h = o.h * cd - o.l * sd;
                t.l = o.h * sd + o.l * cd;
                break;
            case '&':
                t.h = o.h * cd - o.u * sd;
                t.u = o.h * sd + o.u * cd;
                break;
            case '^':
                t.h = o.h * cd + o.u * sd;
                t.u = -o.h * sd + o.u * cd;
                break;
            case '\\':
                t.u = o.u * cd + o.l * sd;
                t.l = o.l * cd - o.u * sd;
                break;
            case '/':
                t.u = o.u * cd - o.l * sd;
                t.l = o.l * cd + o.u * sd;
                break;
            case '|':
                t.h = -o.h;
                t.l = -o.l;
                break;
            case '$': {
                glm::dvec3 l = glm::cross(glm::dvec3(0, 1, 0), o.h);
                if (glm::length(l) > 1e-9) {
                    t.l = glm::normalize(l);
                    t.u = glm::cross(o.h, t.l);
                }
                break;
            }
            case '[':
                stack.push_back(t);
                break;
            case ']':
                t = stack.back();
                stack.pop_back();
                break;
            default:
                break;
            }
        }
        // Every F appends exactly one node after its (optional) root; compare the F end points.
        std::vector<glm::vec3> ends;
        for (std::size_t i = 0; i < s.size(); ++i)
            if (s.parent[i] >= 0) ends.push_back(s.position[i]);
        ASSERT_EQ(ends.size(), drawn.size()) << "seed " << seed;
        for (std::size_t i = 0; i < ends.size(); ++i)
            expectNear(ends[i], glm::vec3(drawn[i]), 1e-3f);
    }
}

TEST(Turtle, SkeletonIsValid) {
    const auto s = run("F[+F[-F]F]f[&F]F(0.5)J");
    EXPECT_NO_THROW(s.validate());
}

namespace {

// Exact comparison with the straightforward turtle (== on floats, so only an exact zero's sign
// may differ).
void expectSameSkeleton(const sylva::skel::Skeleton& a, const sylva::skel::Skeleton& b,
                        const std::string& what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a.parent[i], b.parent[i]) << what << " node " << i;
        ASSERT_EQ(a.order[i], b.order[i]) << what << " node " << i;
        ASSERT_EQ(a.flags[i], b.flags[i]) << what << " node " << i;
        ASSERT_EQ(a.radius[i], b.radius[i]) << what << " node " << i;
        for (int k = 0; k < 3; ++k)
            ASSERT_EQ(a.position[i][k], b.position[i][k]) << what << " node " << i;
        for (int k = 0; k < 4; ++k)
            ASSERT_EQ(a.orientation[i][k], b.orientation[i][k]) << what << " node " << i;
    }
    ASSERT_EQ(a.leaves.size(), b.leaves.size()) << what;
    for (std::size_t i = 0; i < a.leaves.size(); ++i) {
        EXPECT_EQ(a.leaves[i].node, b.leaves[i].node) << what;
        EXPECT_EQ(a.leaves[i].size, b.leaves[i].size) << what;
        EXPECT_EQ(a.leaves[i].position, b.leaves[i].position) << what;
        EXPECT_EQ(a.leaves[i].orientation, b.leaves[i].orientation) << what;
    }
}

} // namespace

// Oracle: the optimized interpreter gives the same floats as the first, straightforward one,
// on random words with every turtle symbol, parameters or not, cuts, moves and leaves.
TEST(Turtle, MatchesStraightforwardTurtleExactly) {
    const std::string alphabet = "FFFF+-&^\\/|$[[]]f!%JAB";
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        sylva::Rng rng(seed);
        const bool params = seed % 2 == 0;
        std::string text;
        int depth = 0;
        for (int i = 0; i < 400; ++i) {
            char c = alphabet[rng.below(alphabet.size())];
            if (c == ']' && depth == 0) c = 'F';
            if (c == '%' && rng.below(4) != 0) c = '+'; // rare cuts keep most of the word
            depth += c == '[' ? 1 : c == ']' ? -1 : 0;
            text.push_back(c);
            if (params && c != '[' && c != ']' && c != '%' && c != '$' && c != '|' &&
                rng.below(2) == 0) {
                // Appended piecewise: GCC 12 reports a false -Wrestrict on "(" + string + ")".
                text.push_back('(');
                text.append(std::to_string(0.1 + 60.0 * rng.uniform()));
                text.push_back(')');
            }
        }
        TurtleSettings settings;
        settings.angleDegrees = 5.0 + 80.0 * rng.uniform();
        settings.step = 0.2 + rng.uniform();
        settings.width = 0.05 + 0.3 * rng.uniform();
        const auto word = makeWord(text);
        expectSameSkeleton(interpret(word, settings),
                           sylva::lsys::reference::interpretReference(word, settings),
                           "seed " + std::to_string(seed));
    }
    // The ABOP word of the benchmark, smaller: the context-free fast path.
    const auto abop = makeWord(sylva::testing::rewrite("F[&F][^F]", 'F', "F[+F]F[-F]F", 5));
    TurtleSettings settings;
    settings.angleDegrees = 25.7;
    expectSameSkeleton(interpret(abop, settings),
                       sylva::lsys::reference::interpretReference(abop, settings), "abop");
}

TEST(Turtle, SourceLinesFollowTheRuleOfEachF) {
    // Generation 2 of "A -> F[+F]B" (line 2), "B -> F" (line 3): F[+F]F, the last F from line 3.
    const sylva::lsys::Grammar g = sylva::lsys::parseGrammar("axiom: A\nA -> F[+F]B\nB -> F\n");
    sylva::lsys::DeriveOptions o;
    o.generations = 2;
    o.traceRules = true;
    const sylva::lsys::ModuleString word = sylva::lsys::derive(g, o);
    const auto traced = interpret(word, {});
    // Root and first F, the branch's F, the last F.
    EXPECT_EQ(traced.sourceLine, (std::vector<std::int32_t>{2, 2, 2, 3}));
    EXPECT_NO_THROW(traced.validate());
    o.traceRules = false;
    const auto plain = interpret(sylva::lsys::derive(g, o), {});
    EXPECT_TRUE(plain.sourceLine.empty());
    EXPECT_EQ(plain.position, traced.position);
    // Origins that do not match the word are refused, not read past their end.
    sylva::lsys::ModuleString broken = word;
    broken.origins.pop_back();
    EXPECT_THROW(interpret(broken, {}), sylva::InvalidInput);
}
