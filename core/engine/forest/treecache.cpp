#include "engine/forest/treecache.h"

#include <cstring>

#include "engine/graph/fileparams.h"

namespace sylva::forest {

namespace {

class Fnv {
public:
    void bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i) {
            mHash ^= p[i];
            mHash *= 0x100000001b3ull;
        }
    }
    void text(const std::string& s) {
        bytes(s.data(), s.size());
        bytes("\0", 1); // separator: "ab"+"c" differs from "a"+"bc"
    }
    template <typename T> void pod(const T& v) { bytes(&v, sizeof v); }
    std::uint64_t value() const { return mHash; }

private:
    std::uint64_t mHash = 0xcbf29ce484222325ull;
};

} // namespace

std::uint64_t speciesHash(const graph::SpeciesGraph& g) {
    Fnv h;
    h.text(g.name);
    h.text(g.output);
    // Not the folder itself: the files the parameters name, each spelled one way. A project
    // saved into another folder names the same species file, grammar and meshes through other
    // relative paths, and must not regrow its trees for that; another file is another tree.
    // (The folder matters only through them: graph::isFileParam is the rule for both.)
    h.pod(g.traits.woodDensity);
    h.pod(g.traits.carbonFraction);
    h.pod(g.traits.crownRadius);
    for (const graph::NodeDesc& n : g.nodes) {
        h.text(n.id);
        h.text(n.type);
        h.text(graph::withCanonicalFiles(n.params, g.baseDir).toJson());
        for (const std::string& input : n.inputs)
            h.text(input);
        h.text("|");
    }
    return h.value();
}

void TreeCache::beginBuild() {
    std::lock_guard lock(mMutex);
    ++mBuild;
    mHits = mMisses = 0;
    mVariantHits = mVariantMisses = mGrownHits = 0;
}

void TreeCache::endBuild() {
    std::lock_guard lock(mMutex);
    std::erase_if(mTrees, [this](const auto& kv) { return kv.second.build != mBuild; });
    std::erase_if(mVariants, [this](const auto& kv) { return kv.second.build != mBuild; });
    std::erase_if(mCrowns, [this](const auto& kv) { return kv.second.build != mBuild; });
    std::erase_if(mGrown, [this](const auto& kv) { return kv.second.build != mBuild; });
}

void TreeCache::clear() {
    std::lock_guard lock(mMutex);
    mTrees.clear();
    mVariants.clear();
    mCrowns.clear();
    mGrown.clear();
}

std::shared_ptr<const skel::Skeleton> TreeCache::findGrown(std::uint64_t key) {
    std::lock_guard lock(mMutex);
    auto it = mGrown.find(key);
    if (it == mGrown.end()) return nullptr;
    it->second.build = mBuild;
    ++mGrownHits;
    return it->second.value;
}

std::size_t TreeCache::grownHits() const {
    std::lock_guard lock(mMutex);
    return mGrownHits;
}

void TreeCache::storeGrown(std::uint64_t key, std::shared_ptr<const skel::Skeleton> grown) {
    std::lock_guard lock(mMutex);
    mGrown[key] = {std::move(grown), mBuild};
}

std::optional<ForestTree> TreeCache::findTree(std::uint64_t key) {
    std::lock_guard lock(mMutex);
    auto it = mTrees.find(key);
    if (it == mTrees.end()) {
        ++mMisses;
        return std::nullopt;
    }
    ++mHits;
    it->second.build = mBuild;
    return it->second.value;
}

void TreeCache::storeTree(std::uint64_t key, const ForestTree& tree) {
    std::lock_guard lock(mMutex);
    mTrees[key] = {tree, mBuild};
}

std::optional<ForestVariant> TreeCache::findVariant(std::uint64_t key) {
    std::lock_guard lock(mMutex);
    auto it = mVariants.find(key);
    if (it == mVariants.end()) {
        ++mVariantMisses;
        return std::nullopt;
    }
    ++mVariantHits;
    it->second.build = mBuild;
    return it->second.value;
}

void TreeCache::storeVariant(std::uint64_t key, const ForestVariant& variant) {
    std::lock_guard lock(mMutex);
    mVariants[key] = {variant, mBuild};
}

std::optional<CrownShape> TreeCache::findCrown(std::uint64_t key) {
    std::lock_guard lock(mMutex);
    auto it = mCrowns.find(key);
    if (it == mCrowns.end()) return std::nullopt;
    it->second.build = mBuild;
    return it->second.value;
}

void TreeCache::storeCrown(std::uint64_t key, const CrownShape& crown) {
    std::lock_guard lock(mMutex);
    mCrowns[key] = {crown, mBuild};
}

std::size_t TreeCache::hits() const {
    std::lock_guard lock(mMutex);
    return mHits;
}

std::size_t TreeCache::misses() const {
    std::lock_guard lock(mMutex);
    return mMisses;
}

std::size_t TreeCache::variantHits() const {
    std::lock_guard lock(mMutex);
    return mVariantHits;
}

std::size_t TreeCache::variantMisses() const {
    std::lock_guard lock(mMutex);
    return mVariantMisses;
}

std::size_t TreeCache::size() const {
    std::lock_guard lock(mMutex);
    return mTrees.size();
}

} // namespace sylva::forest
