#include "engine/util/fileversion.h"

#include <chrono>

#include <sys/stat.h>

namespace sylva {

namespace {
constexpr std::int64_t kRacySeconds = 2;
} // namespace

std::optional<FileVersion> fileVersionOf(const std::filesystem::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
    FileVersion v;
    v.device = static_cast<std::uint64_t>(st.st_dev);
    v.inode = static_cast<std::uint64_t>(st.st_ino);
    v.size = static_cast<std::uint64_t>(st.st_size);
    v.seconds = static_cast<std::int64_t>(st.st_mtim.tv_sec);
    v.nanoseconds = static_cast<std::int64_t>(st.st_mtim.tv_nsec);
    return v;
}

bool settled(const FileVersion& v) {
    const auto now = std::chrono::duration_cast<std::chrono::seconds>(
                         std::chrono::system_clock::now().time_since_epoch())
                         .count();
    return now - v.seconds > kRacySeconds;
}

} // namespace sylva
