#pragma once

// A per-process scratch file for harnesses whose entry point reads a path (Assimp, the
// reference scene import): the input is written there and read back by the code under test.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <unistd.h>

namespace sylva::fuzz {

/// The process's scratch folder `<tmp>/sylva-fuzz-<pid>/`, removed when the process exits
/// normally (libFuzzer ends a run with exit(); a crash leaves it beside its finding).
struct TempInputDir {
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("sylva-fuzz-" + std::to_string(static_cast<long>(::getpid())));
    TempInputDir() { std::filesystem::create_directories(path); }
    ~TempInputDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
    TempInputDir(const TempInputDir&) = delete;
    TempInputDir& operator=(const TempInputDir&) = delete;
};

/// Writes \p data to `<tmp>/sylva-fuzz-<pid>/input<extension>` and returns the path.
inline std::filesystem::path writeTempInput(const std::uint8_t* data, std::size_t size,
                                            const std::string& extension) {
    static const TempInputDir dir;
    const std::filesystem::path file = dir.path / ("input" + extension);
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) std::abort(); // the harness itself failed, not the code under test
    return file;
}

} // namespace sylva::fuzz
