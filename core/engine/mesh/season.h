#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "engine/skeleton/skeleton.h"

namespace sylva::mesh {

/// The time of year a tree is shown in. Summer is the look every species had before seasons
/// existed (full leaves, the leaf texture as drawn), so it is the default everywhere.
enum class Season : std::uint8_t { Spring, Summer, Autumn, Winter };

inline constexpr Season kAllSeasons[] = {Season::Spring, Season::Summer, Season::Autumn,
                                         Season::Winter};

/// "spring", "summer", "autumn", "winter".
std::string_view seasonName(Season season);
/// The season named \p name (lower case as seasonName writes it; "fall" is autumn).
/// \throw InvalidInput naming the allowed values.
Season parseSeason(std::string_view name);

/// How a season changes a species' leaves. Evergreen species (conifers, palms, the shrubs) keep
/// their summer look all year; deciduous ones flush smaller and fewer leaves in spring, lose
/// some in autumn and are bare in winter.
struct SeasonLook {
    double leafFraction = 1.0; ///< of the summer leaves kept, 0..1
    double leafScale = 1.0;    ///< card length factor of the kept leaves
};
SeasonLook seasonLook(Season season, bool deciduous);

/// The leaves a tree shows in \p season: a deterministic choice from \p seed, made per leaf so
/// that the same leaves survive whatever else changes (no area compensation: an autumn crown
/// is really thinner). Returns \p leaves unchanged for summer and for evergreen species.
std::vector<skel::Leaf> seasonLeaves(const std::vector<skel::Leaf>& leaves, Season season,
                                     bool deciduous, std::uint64_t seed);

/// The leaf texture a season uses: "<stem>_<season>.png" beside \p summerTexture when that
/// file exists (make_textures.py draws them for the library from each species'
/// autumn_color), else \p summerTexture itself. Summer and an empty path give \p summerTexture.
std::string seasonTextureFile(const std::string& summerTexture, Season season);

} // namespace sylva::mesh
