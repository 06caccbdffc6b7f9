#pragma once

#include <cstdio>
#include <filesystem>
#include <string_view>

namespace sylva {

/// Writes a whole file atomically: the bytes go to a temporary file in the same folder,
/// which is renamed over \p path only when everything was written and flushed. On any
/// failure the temporary is removed and IoError is thrown; \p path is never half-written.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

/// RAII helper for streaming writers: open() creates the temporary, commit() renames it into
/// place, and the destructor removes the temporary if commit() was never reached.
class AtomicFile {
public:
    explicit AtomicFile(std::filesystem::path path);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// Appends bytes; throws IoError on a short write.
    void write(std::string_view bytes);
    /// Flushes, closes and renames the temporary over the target path.
    void commit();
    const std::filesystem::path& temporaryPath() const { return mTemp; }

private:
    std::filesystem::path mPath;
    std::filesystem::path mTemp;
    std::FILE* mFile = nullptr;
    bool mCommitted = false;
};

} // namespace sylva
