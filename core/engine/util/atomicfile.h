#pragma once

#include <cstdio>
#include <filesystem>
#include <string_view>

namespace sylva {

/// Writes a whole file atomically: the bytes go to a temporary file in the same folder,
/// which is renamed over \p path only when everything was written and flushed. On any
/// failure the temporary is removed and IoError is thrown; \p path is never half-written.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

/// Whether commit() waits for the bytes to reach the disk (fsync) before the rename.
///
/// Both modes are atomic for readers: the target path shows the old file or the complete new
/// one, never a part. Durable also survives a power cut right after commit(), at the price of
/// waiting for the disk: for a multi-gigabyte forest export that wait is most of the time
/// (docs/perf/geometry.md). Documents (projects, species, small sidecars) are always durable;
/// large regenerable exports default to Atomic and take Durable on request (`--fsync`).
enum class Durability { Atomic, Durable };

/// RAII helper for streaming writers: open() creates the temporary, commit() renames it into
/// place, and the destructor removes the temporary if commit() was never reached.
class AtomicFile {
public:
    explicit AtomicFile(std::filesystem::path path, Durability durability = Durability::Durable);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// Appends bytes; throws IoError on a short write.
    void write(std::string_view bytes);
    /// Flushes what write() buffered and returns the temporary's descriptor, positioned at its
    /// end, for copies the kernel makes (copy_file_range); write() may follow. \throw IoError
    int flushedDescriptor();
    /// Flushes, closes and renames the temporary over the target path.
    void commit();
    const std::filesystem::path& temporaryPath() const { return mTemp; }

private:
    std::filesystem::path mPath;
    std::filesystem::path mTemp;
    std::FILE* mFile = nullptr;
    Durability mDurability;
    bool mCommitted = false;
};

} // namespace sylva
