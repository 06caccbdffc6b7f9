#pragma once
// Loops whose OpenMP region starts only when they run in parallel. `#pragma omp parallel for
// if (parallel)` is not that: a region whose if fails still starts a team of one and ends it at
// a barrier, a futex call each time (~115 a tree of presets/so-broadleaf.json; 45 an English
// oak's colonization before its search stopped doing it, docs/perf/geometry.md).
#include <cstdint>

namespace sylva {

/// body(k) for k in [0, count): over OpenMP's threads in static chunks when \p parallel, else
/// in order on this thread.
template <class Body> void forEachIndex(std::int64_t count, bool parallel, const Body& body) {
    if (parallel) {
#pragma omp parallel for schedule(static)
        for (std::int64_t k = 0; k < count; ++k)
            body(k);
    } else {
        for (std::int64_t k = 0; k < count; ++k)
            body(k);
    }
}

/// The same, the threads taking dynamic chunks of \p chunk indices (uneven work per index).
template <class Body>
void forEachIndexDynamic(std::int64_t count, bool parallel, int chunk, const Body& body) {
    if (parallel) {
#pragma omp parallel for schedule(dynamic, chunk)
        for (std::int64_t k = 0; k < count; ++k)
            body(k);
    } else {
        for (std::int64_t k = 0; k < count; ++k)
            body(k);
    }
}

} // namespace sylva
