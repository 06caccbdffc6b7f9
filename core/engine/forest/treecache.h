#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>

#include "engine/forest/forestbuild.h"

namespace sylva::forest {

/// Finished trees kept between builds of one scene, so that an editor's regeneration after an
/// edit regrows only the trees whose inputs changed. A tree's key hashes everything its result
/// depends on: the species graph (nodes, parameters with the files they name made absolute and
/// canonical, inputs, traits; not the folder, so a project saved elsewhere keeps its trees), the
/// instance (id, position, rotation, scale, growth stage, seed), the neighbouring crowns it
/// adapts to, the obstacles' identity (ForestOptions::obstaclesKey), the light, the camera
/// distance when LOD is on, and the build options. Files a graph reads (grammar files) are not
/// hashed: call clear() when one changes on disk. Self-organizing trees grow together in one stand
/// and are never cached. Variants are kept by (species graph, seed, options). Thread-safe:
/// buildForest reads and writes it from its worker threads.
class TreeCache {
public:
    /// Starts a build: counters reset; entries not used by this build are dropped by
    /// endBuild(), so the cache never holds more than the last scene's trees.
    void beginBuild();
    void endBuild();
    void clear();

    std::optional<ForestTree> findTree(std::uint64_t key);
    void storeTree(std::uint64_t key, const ForestTree& tree);
    std::optional<ForestVariant> findVariant(std::uint64_t key);
    void storeVariant(std::uint64_t key, const ForestVariant& variant);
    std::optional<CrownShape> findCrown(std::uint64_t key);
    void storeCrown(std::uint64_t key, const CrownShape& crown);
    /// A tree's skeleton as grown, by its key without its branch edits: a branch edit re-applies
    /// the edits to it (then adapts and meshes) instead of growing the tree again (issue 43: an
    /// edit on screen within 50 ms). Null when not kept.
    std::shared_ptr<const skel::Skeleton> findGrown(std::uint64_t key);
    void storeGrown(std::uint64_t key, std::shared_ptr<const skel::Skeleton> grown);
    /// Trees of the current (or last) build whose skeleton as grown was taken from the cache.
    std::size_t grownHits() const;

    /// Trees taken from the cache and trees grown during the current (or last) build. An
    /// instanced tree takes its variant's mesh or level and never asks the cache: it counts
    /// in neither (its variant counts in variantHits()/variantMisses()).
    std::size_t hits() const;
    std::size_t misses() const;
    /// Variants taken from the cache and variants grown during the current (or last) build.
    std::size_t variantHits() const;
    std::size_t variantMisses() const;
    std::size_t size() const;

private:
    template <typename T> struct Entry {
        T value;
        std::uint64_t build = 0;
    };
    mutable std::mutex mMutex;
    std::uint64_t mBuild = 0;
    std::size_t mHits = 0, mMisses = 0;
    std::size_t mVariantHits = 0, mVariantMisses = 0, mGrownHits = 0;
    std::unordered_map<std::uint64_t, Entry<ForestTree>> mTrees;
    std::unordered_map<std::uint64_t, Entry<ForestVariant>> mVariants;
    std::unordered_map<std::uint64_t, Entry<CrownShape>> mCrowns;
    std::unordered_map<std::uint64_t, Entry<std::shared_ptr<const skel::Skeleton>>> mGrown;
};

/// 64-bit FNV-1a of a species graph's content (see TreeCache).
std::uint64_t speciesHash(const graph::SpeciesGraph& graph);

} // namespace sylva::forest
