#pragma once

// A per-process scratch file for harnesses whose entry point reads a path (Assimp, the
// reference scene import): the input is written there and read back by the code under test.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace sylva::fuzz {

/// Writes \p data to `<tmp>/sylva-fuzz-<pid>/input<extension>` and returns the path.
inline std::filesystem::path writeTempInput(const std::uint8_t* data, std::size_t size,
                                            const std::string& extension) {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() /
                 ("sylva-fuzz-" + std::to_string(static_cast<long>(::getpid())));
        std::filesystem::create_directories(d);
        return d;
    }();
    const std::filesystem::path file = dir / ("input" + extension);
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) std::abort(); // the harness itself failed, not the code under test
    return file;
}

} // namespace sylva::fuzz
