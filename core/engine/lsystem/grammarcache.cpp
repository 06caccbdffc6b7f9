#include "engine/lsystem/grammarcache.h"

#include <chrono>
#include <deque>
#include <fstream>
#include <mutex>
#include <sstream>

#include <sys/stat.h>

#include "engine/util/error.h"

namespace sylva::lsys {

namespace {

constexpr std::int64_t kRacySeconds = 2;

/// What a file's stat() says about its contents: another write gives another modification
/// time (nanoseconds), size or (a save by rename) inode.
struct FileVersion {
    std::uint64_t device = 0, inode = 0, size = 0;
    std::int64_t seconds = 0, nanoseconds = 0;
    bool operator==(const FileVersion&) const = default;
};

bool versionOf(const std::filesystem::path& path, FileVersion& v) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
    v.device = static_cast<std::uint64_t>(st.st_dev);
    v.inode = static_cast<std::uint64_t>(st.st_ino);
    v.size = static_cast<std::uint64_t>(st.st_size);
    v.seconds = static_cast<std::int64_t>(st.st_mtim.tv_sec);
    v.nanoseconds = static_cast<std::int64_t>(st.st_mtim.tv_nsec);
    return true;
}

std::string readTextFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError("cannot read " + path.string());
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Entry {
    std::string key; ///< the path, or the file name and text of an inline grammar
    FileVersion version;
    std::shared_ptr<const Grammar> grammar;
};

class Cache {
public:
    std::shared_ptr<const Grammar> find(const std::string& key, const FileVersion& version) {
        const std::lock_guard lock(mMutex);
        for (const Entry& e : mEntries)
            if (e.version == version && e.key == key) return e.grammar;
        return nullptr;
    }
    void add(std::string key, const FileVersion& version, std::shared_ptr<const Grammar> g) {
        const std::lock_guard lock(mMutex);
        std::erase_if(mEntries, [&key](const Entry& e) { return e.key == key; });
        if (mEntries.size() >= kGrammarCacheEntries) mEntries.pop_front();
        mEntries.push_back({std::move(key), version, std::move(g)});
    }

private:
    std::mutex mMutex;
    std::deque<Entry> mEntries;
};

Cache& cache() {
    static Cache c;
    return c;
}

} // namespace

std::shared_ptr<const Grammar> parsedGrammarFile(const std::filesystem::path& path) {
    FileVersion before;
    const bool known = versionOf(path, before);
    std::string key = path.string();
    if (known)
        if (auto g = cache().find(key, before)) return g;
    const std::string text = readTextFile(path);
    auto g = std::make_shared<const Grammar>(parseGrammar(text, key));
    // Kept only when the file did not change while it was read, and was last written more
    // than kRacySeconds ago: file times move in clock ticks of a few milliseconds, so a second
    // write in place within the tick of the version read here could leave size and time as
    // they were ("racy git"); a version that old cannot share its time with a later write.
    FileVersion after;
    const auto now = std::chrono::duration_cast<std::chrono::seconds>(
                         std::chrono::system_clock::now().time_since_epoch())
                         .count();
    if (known && versionOf(path, after) && after == before && now - after.seconds > kRacySeconds)
        cache().add(std::move(key), after, g);
    return g;
}

std::shared_ptr<const Grammar> parsedGrammarText(const std::string& text,
                                                 const std::string& fileName) {
    std::string key = fileName;
    key += '\0';
    key += text;
    if (auto g = cache().find(key, FileVersion{})) return g;
    auto g = std::make_shared<const Grammar>(parseGrammar(text, fileName));
    cache().add(std::move(key), FileVersion{}, g);
    return g;
}

} // namespace sylva::lsys
