#include "engine/lsystem/grammarcache.h"

#include <deque>
#include <fstream>
#include <mutex>
#include <sstream>

#include "engine/util/error.h"
#include "engine/util/fileversion.h"

namespace sylva::lsys {

namespace {

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
    const std::optional<FileVersion> before = fileVersionOf(path);
    std::string key = path.string();
    if (before)
        if (auto g = cache().find(key, *before)) return g;
    const std::string text = readTextFile(path);
    auto g = std::make_shared<const Grammar>(parseGrammar(text, key));
    // Kept only when the file did not change while it was read and is settled (a later write
    // in place cannot share its time: see settled()).
    const std::optional<FileVersion> after = fileVersionOf(path);
    if (before && after && *after == *before && settled(*after))
        cache().add(std::move(key), *after, g);
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
