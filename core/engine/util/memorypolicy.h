#pragma once

#include <cstddef>

namespace sylva {

/// Keeps the memory the process frees for its own later allocations instead of handing it
/// back to the kernel at once.
///
/// Generating a tree allocates large arrays (a 1 M-segment skeleton is ~46 MB, its mesh
/// several hundred MB) and frees them when the next tree or the next edit replaces it. With
/// glibc's defaults every such array is a fresh mmap whose pages the kernel faults in and
/// zeroes again: a quarter of the turtle's time on a 1 M-segment word (31 instead of 23 ns per
/// segment, docs/perf/geometry.md). This raises glibc's mmap threshold to its maximum
/// (32 MiB) and stops it from trimming the heap, so repeated generation in the editor, the
/// CLI's forests and the benchmarks reuse pages already faulted in. The price is that the
/// resident size stays at its peak until the process ends.
///
/// Call once at start-up, before any large allocation (the apps' main() and the benchmark
/// programs do). A no-op outside glibc.
void keepFreedMemory();

/// The same for a library loaded into someone else's process (`import sylva` in Python or
/// Blender): the mmap threshold raised as above, but the top of the heap handed back once more
/// than \p retainBytes of it is free, so a host keeps at most that much that it did not ask
/// for. Trees of the size of an English oak then reuse their pages (measured through Python:
/// 5.6-5.9 -> 5.4-5.5 ms a tree). A no-op outside glibc.
void keepFreedMemoryUpTo(std::size_t retainBytes);

} // namespace sylva
