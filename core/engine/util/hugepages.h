#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace sylva {

/// Asks the kernel to back [data, data + bytes) with transparent huge pages when it is first
/// touched. Large fresh buffers (skeleton and mesh arrays of millions of elements) otherwise
/// take one page fault per 4 KiB, which on the VMs we measured costs more than filling them.
/// Only a hint: a no-op off Linux, where THP is disabled, or for ranges below 2 MiB.
inline void adviseHugePages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = std::uintptr_t(1) << 21;
    if (bytes < 2 * kHuge) return;
    const auto begin = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t last = (begin + bytes) & ~(kHuge - 1);
    if (last > first)
        ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE); // NOLINT
#else
    (void)data;
    (void)bytes;
#endif
}

/// adviseHugePages() over a vector's whole capacity (call right after reserve()).
template <class T> void adviseHugePages(const std::vector<T>& v) {
    adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

} // namespace sylva
