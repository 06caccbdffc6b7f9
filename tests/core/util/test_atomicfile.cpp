#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

fs::path freshDir(const char* name) {
    fs::path dir = fs::temp_directory_path() / (std::string("sylva-test-") + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}
} // namespace

TEST(AtomicFile, WritesWholeFile) {
    const fs::path dir = freshDir("atomic-write");
    sylva::writeFileAtomically(dir / "a.txt", "hello");
    EXPECT_EQ(slurp(dir / "a.txt"), "hello");
    sylva::writeFileAtomically(dir / "a.txt", "replaced");
    EXPECT_EQ(slurp(dir / "a.txt"), "replaced");
    // Only the target remains: no temporaries left behind.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicFile, AbandonedWriteLeavesOldContentAndNoTemporary) {
    const fs::path dir = freshDir("atomic-abandon");
    sylva::writeFileAtomically(dir / "b.txt", "original");
    {
        sylva::AtomicFile file(dir / "b.txt");
        file.write("half of a new");
        // no commit(): simulates an exception in the middle of a writer
    }
    EXPECT_EQ(slurp(dir / "b.txt"), "original");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicFile, UnwritableFolderThrowsIoError) {
    EXPECT_THROW(sylva::writeFileAtomically("/nonexistent-folder/x.txt", "x"), sylva::IoError);
}

TEST(Error, DiagnosticFormat) {
    sylva::Diagnostic d{"tree.lsys", 3, 7, "unbalanced ']'"};
    EXPECT_EQ(d.format(), "tree.lsys:3:7: error: unbalanced ']'");
    sylva::InvalidInput e(std::vector<sylva::Diagnostic>{d});
    EXPECT_STREQ(e.what(), "tree.lsys:3:7: error: unbalanced ']'");
    EXPECT_THROW(sylva::requireRange("resolution", 2, 3, 64), sylva::InvalidInput);
    try {
        sylva::requireRange("resolution", 2, 3, 64);
    } catch (const sylva::InvalidInput& ex) {
        EXPECT_EQ(std::string(ex.what()), "resolution must be in [3, 64], got 2");
    }
    EXPECT_NO_THROW(sylva::requireRange("resolution", 8, 3, 64));
}
