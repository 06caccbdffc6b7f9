// Context-sensitive rules: bracket-aware matching (ABOP §1.8), ignored symbols, parameters,
// and rule priority. Every expected word is derived by hand.
#include <gtest/gtest.h>

#include "lsystemtest.h"

using namespace sylva::lsys::test;

TEST(Context, AbopSection18Example) {
    // ABOP p. 32: in ABC[DE][SG[HI[JK]L]MNO], S has left context BC (its path to the root,
    // skipping the branch [DE]) and right context G[H]M (I[JK]L is the rest of H's branch).
    const std::string axiom = "axiom: ABC[DE][SG[HI[JK]L]MNO]\n";
    EXPECT_EQ(expand(axiom + "BC < S > G[H]M -> X\n", 1), "ABC[DE][XG[HI[JK]L]MNO]");
    EXPECT_EQ(expand(axiom + "BC < S -> X\n", 1), "ABC[DE][XG[HI[JK]L]MNO]");
    EXPECT_EQ(expand(axiom + "S > G[H]M -> X\n", 1), "ABC[DE][XG[HI[JK]L]MNO]");
    // E is in a sibling branch, not on S's path; I is inside H's branch, not after G.
    EXPECT_EQ(expand(axiom + "E < S -> X\n", 1), "ABC[DE][SG[HI[JK]L]MNO]");
    EXPECT_EQ(expand(axiom + "S > GI -> X\n", 1), "ABC[DE][SG[HI[JK]L]MNO]");
    // M's left context skips the branch [HI[JK]L] back to G, then S, then C.
    EXPECT_EQ(expand(axiom + "CSG < M -> X\n", 1), "ABC[DE][SG[HI[JK]L]XNO]");
    // L's left context is I (skipping [JK]), then H.
    EXPECT_EQ(expand(axiom + "HI < L -> X\n", 1), "ABC[DE][SG[HI[JK]X]MNO]");
}

TEST(Context, RightContextSkipsBranchesUnlessThePatternDescends) {
    EXPECT_EQ(expand("axiom: A[B]C\nA > C -> X\n", 1), "X[B]C");
    EXPECT_EQ(expand("axiom: A[B]C\nA > B -> X\n", 1), "A[B]C");
    EXPECT_EQ(expand("axiom: A[B]C\nA > [B] -> X\n", 1), "X[B]C");
    EXPECT_EQ(expand("axiom: A[B]C\nA > [B]C -> X\n", 1), "X[B]C");
    EXPECT_EQ(expand("axiom: A[BD]C\nA > [B]C -> X\n", 1), "X[BD]C");
    EXPECT_EQ(expand("axiom: A[B]D\nA > [B]C -> X\n", 1), "A[B]D");
    // '[' in the pattern may match any of the sibling branches at that point.
    EXPECT_EQ(expand("axiom: A[B][C]D\nA > [C] -> X\n", 1), "X[B][C]D");
    // A branch's end is the end of the right context.
    EXPECT_EQ(expand("axiom: [A]B\nA > B -> X\n", 1), "[A]B");
}

TEST(Context, AcropetalSignalThroughBranches) {
    // ABOP fig. 1.31-style signal: b moves from a module to everything whose left context is b.
    const std::string g = "axiom: b[a]a[a]a\nb < a -> b\nb -> a\n";
    EXPECT_EQ(expand(g, 1), "a[b]b[a]a");
    EXPECT_EQ(expand(g, 2), "a[a]a[b]b");
    EXPECT_EQ(expand(g, 3), "a[a]a[a]a");
}

TEST(Context, BasipetalSignalWithRightContext) {
    // A signal x at a branch tip travels down to the root through [ ] descents.
    const std::string g = "axiom: aa[ax]a\na > x -> x\na > [x] -> x\nx -> a\n";
    EXPECT_EQ(expand(g, 1), "aa[xa]a");
    EXPECT_EQ(expand(g, 2), "ax[aa]a");
    EXPECT_EQ(expand(g, 3), "xa[aa]a");
}

TEST(Context, IgnoredSymbolsAreTransparent) {
    const std::string rules = "b < a -> b\nb -> a\n";
    EXPECT_EQ(expand("axiom: b+a-a\n" + rules, 1), "a+a-a");
    EXPECT_EQ(expand("ignore: + -\naxiom: b+a-a\n" + rules, 1), "a+b-a");
    EXPECT_EQ(expand("ignore: + -\naxiom: b+a-a\n" + rules, 2), "a+a-b");
    // Right context and branches with ignored symbols: F and / are skipped, ] still ends.
    EXPECT_EQ(expand("ignore: F /\naxiom: a F[/F b]/c\na > [b]c -> X\n", 1), "XF[/Fb]/c");
    // A pattern may name an ignored symbol explicitly.
    EXPECT_EQ(expand("ignore: +\naxiom: +a\n+ < a -> X\n", 1), "+X");
}

TEST(Context, ContextSensitiveRulesComeFirst) {
    const std::string g = "axiom: baa\na -> c\nb < a -> d\n";
    EXPECT_EQ(expand(g, 1), "bdc");
    // Among context-sensitive rules, file order decides.
    EXPECT_EQ(expand("axiom: bac\nb < a -> X\na > c -> Y\n", 1), "bXc");
    EXPECT_EQ(expand("axiom: bac\na > c -> Y\nb < a -> X\n", 1), "bYc");
}

TEST(Context, ParametricContextBindsFormals) {
    EXPECT_EQ(expand("axiom: A(1)B(2)C(3)\nA(x) < B(y) > C(z) -> B(x + y * 10 + z * 100)\n", 1),
              "A(1)B(321)C(3)");
    // Conditions see the context's parameters.
    const std::string g = "axiom: A(5)B(2)\nA(x) < B(y) : x > y -> B(x)\n";
    EXPECT_EQ(expand(g, 1), "A(5)B(5)");
    EXPECT_EQ(expand("axiom: A(1)B(2)\nA(x) < B(y) : x > y -> B(x)\n", 1), "A(1)B(2)");
    // Multi-module left context binds in string order.
    EXPECT_EQ(expand("axiom: A(1)A(2)B(0)\nA(x)A(y) < B(z) -> B(x - y)\n", 1), "A(1)A(2)B(-1)");
}
