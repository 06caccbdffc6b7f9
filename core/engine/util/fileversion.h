#pragma once
// Which version of a file is on disk, from one stat(): what the engine's caches of files read
// (parsed grammars, obstacle scenes) key their entries on.
#include <cstdint>
#include <filesystem>
#include <optional>

namespace sylva {

/// What a file's stat() says about its contents: another write gives another modification
/// time (nanoseconds), size or (a save by rename) inode.
struct FileVersion {
    std::uint64_t device = 0, inode = 0, size = 0;
    std::int64_t seconds = 0, nanoseconds = 0;
    bool operator==(const FileVersion&) const = default;
};

/// The version of the regular file \p path; nothing when it is missing, not a regular file or
/// cannot be stat()ed.
std::optional<FileVersion> fileVersionOf(const std::filesystem::path& path);

/// Whether \p v was written long enough ago (more than two seconds) that a later write cannot
/// share its modification time: file times move in clock ticks of a few milliseconds, so a
/// second write in place within the tick of \p v could leave its size and time as they were
/// ("racy git"). A cache that must never serve such a rewrite keeps only settled versions.
bool settled(const FileVersion& v);

} // namespace sylva
