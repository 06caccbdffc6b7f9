#include "engine/mesh/season.h"

#include <filesystem>

#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

namespace sylva::mesh {

std::string_view seasonName(Season season) {
    switch (season) {
    case Season::Spring:
        return "spring";
    case Season::Summer:
        return "summer";
    case Season::Autumn:
        return "autumn";
    case Season::Winter:
        return "winter";
    }
    return "summer";
}

Season parseSeason(std::string_view name) {
    for (Season s : kAllSeasons)
        if (name == seasonName(s)) return s;
    if (name == "fall") return Season::Autumn;
    throw InvalidInput("season must be spring, summer, autumn or winter, got \"" +
                       std::string(name) + "\"");
}

SeasonLook seasonLook(Season season, bool deciduous) {
    if (!deciduous) return {};
    switch (season) {
    case Season::Spring:
        // Fresh leaves: not all buds have broken, and those that have are still small.
        return {0.7, 0.75};
    case Season::Autumn:
        return {0.75, 1.0};
    case Season::Winter:
        return {0.0, 1.0};
    case Season::Summer:
        break;
    }
    return {};
}

std::vector<skel::Leaf> seasonLeaves(const std::vector<skel::Leaf>& leaves, Season season,
                                     bool deciduous, std::uint64_t seed) {
    const SeasonLook look = seasonLook(season, deciduous);
    if (look.leafFraction >= 1.0 && look.leafScale == 1.0) return leaves;
    std::vector<skel::Leaf> kept;
    if (look.leafFraction <= 0.0) return kept;
    kept.reserve(static_cast<std::size_t>(static_cast<double>(leaves.size()) * look.leafFraction) +
                 1);
    const std::uint64_t stream = mixSeed(seed, salt::kSeason);
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        Rng rng(mixSeed(stream, i));
        if (rng.uniform() >= look.leafFraction) continue;
        skel::Leaf leaf = leaves[i];
        leaf.size *= static_cast<float>(look.leafScale);
        kept.push_back(leaf);
    }
    return kept;
}

std::string seasonTextureFile(const std::string& summerTexture, Season season) {
    if (summerTexture.empty() || season == Season::Summer) return summerTexture;
    const std::filesystem::path summer(summerTexture);
    std::filesystem::path seasonal = summer;
    seasonal.replace_filename(summer.stem().string() + "_" + std::string(seasonName(season)) +
                              summer.extension().string());
    std::error_code ec;
    return std::filesystem::is_regular_file(seasonal, ec) ? seasonal.string() : summerTexture;
}

} // namespace sylva::mesh
