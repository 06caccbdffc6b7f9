#include "engine/util/memorypolicy.h"

#include <algorithm>
#include <climits>
#include <cstdlib> // defines __GLIBC__ where glibc is the C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace sylva {

namespace {
// glibc refuses thresholds above HEAP_MAX_SIZE / 2, which is 32 MiB on 64-bit systems.
constexpr int kMaxMmapThreshold = 32 * 1024 * 1024;
} // namespace

void keepFreedMemoryUpTo(std::size_t retainBytes) {
#if defined(__GLIBC__)
    ::mallopt(M_MMAP_THRESHOLD, kMaxMmapThreshold);
    ::mallopt(M_TRIM_THRESHOLD, static_cast<int>(std::min<std::size_t>(retainBytes, INT_MAX)));
#else
    (void)retainBytes;
#endif
}

void keepFreedMemory() {
#if defined(__GLIBC__)
    ::mallopt(M_MMAP_THRESHOLD, kMaxMmapThreshold);
    // -1 disables trimming the top of the heap (the glibc manual's documented value).
    ::mallopt(M_TRIM_THRESHOLD, -1);
#endif
}

} // namespace sylva
