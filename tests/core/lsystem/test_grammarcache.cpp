// lsys::parsedGrammarFile / parsedGrammarText: a grammar parsed once for each version of its
// file, and parsed again whenever the file changes.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "engine/lsystem/grammarcache.h"
#include "engine/util/error.h"

using namespace sylva;
namespace fs = std::filesystem;

namespace {

fs::path freshFile(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() /
        ("sylva_grammarcache_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    fs::create_directories(dir);
    return dir / name;
}

// Writes in place (same inode) and dates the file \p age ago.
void write(const fs::path& p, const std::string& text, std::chrono::seconds age) {
    {
        std::ofstream out(p, std::ios::binary | std::ios::in | std::ios::out | std::ios::trunc);
        if (!out)
            std::ofstream(p, std::ios::binary) << text;
        else
            out << text;
    }
    fs::last_write_time(p, fs::file_time_type::clock::now() - age);
}

} // namespace

TEST(GrammarCache, SameFileVersionIsParsedOnce) {
    const fs::path p = freshFile("a.lsys");
    write(p, "generations: 2\naxiom: F\nF -> FF\n", std::chrono::seconds(60));
    const auto a = lsys::parsedGrammarFile(p);
    const auto b = lsys::parsedGrammarFile(p);
    EXPECT_EQ(a.get(), b.get());
    EXPECT_EQ(a->generations, 2);
    EXPECT_EQ(a->fileName, p.string());
    fs::remove_all(p.parent_path());
}

TEST(GrammarCache, AFileWrittenInPlaceWithTheSameSizeIsParsedAgain) {
    const fs::path p = freshFile("b.lsys");
    write(p, "generations: 2\naxiom: F\nF -> FF\n", std::chrono::seconds(60));
    const auto a = lsys::parsedGrammarFile(p);
    write(p, "generations: 3\naxiom: F\nF -> FF\n", std::chrono::seconds(30)); // same size
    const auto b = lsys::parsedGrammarFile(p);
    EXPECT_NE(a.get(), b.get());
    EXPECT_EQ(b->generations, 3);
    // The same bytes dated otherwise: another version, parsed again.
    fs::last_write_time(p, fs::file_time_type::clock::now() - std::chrono::seconds(20));
    EXPECT_NE(lsys::parsedGrammarFile(p).get(), b.get());
    fs::remove_all(p.parent_path());
}

TEST(GrammarCache, AFileJustWrittenIsNotKept) {
    // Its time may not tell a second write within the clock's tick apart: parsed every call.
    const fs::path p = freshFile("c.lsys");
    write(p, "generations: 1\naxiom: F\nF -> FF\n", std::chrono::seconds(0));
    const auto a = lsys::parsedGrammarFile(p);
    const auto b = lsys::parsedGrammarFile(p);
    EXPECT_NE(a.get(), b.get());
    EXPECT_EQ(b->generations, 1);
    fs::remove_all(p.parent_path());
}

TEST(GrammarCache, ErrorsAreNotKept) {
    const fs::path p = freshFile("d.lsys");
    write(p, "axiom: F\nF -> F(\n", std::chrono::seconds(60));
    try {
        (void)lsys::parsedGrammarFile(p);
        FAIL() << "a bad grammar parsed";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("d.lsys:2:"), std::string::npos) << e.what();
    }
    // Mended and dated as before (another size): the mended grammar.
    write(p, "axiom: F\nF -> FF\n", std::chrono::seconds(60));
    EXPECT_EQ(lsys::parsedGrammarFile(p)->rules.size(), 1u);
    fs::remove_all(p.parent_path());
    EXPECT_THROW((void)lsys::parsedGrammarFile(p), IoError);
}

TEST(GrammarCache, InlineTextIsKeptByTextAndName) {
    const std::string text = "axiom: F\nF -> F+F\n";
    const auto a = lsys::parsedGrammarText(text, "<inline>");
    EXPECT_EQ(a.get(), lsys::parsedGrammarText(text, "<inline>").get());
    EXPECT_NE(a.get(), lsys::parsedGrammarText(text, "other.sylva").get());
    const auto c = lsys::parsedGrammarText("axiom: F\nF -> F-F\n", "<inline>");
    EXPECT_NE(a.get(), c.get());
    EXPECT_EQ(c->rules.size(), 1u);
}
