// Fuzzes the binary FBX repair and the ASCII unit rewrite: any bytes are repaired or rejected
// with InvalidInput, and a repaired file is itself well-formed (repairing it again succeeds).
#include "engine/export/fbx/fbxfix.h"
#include "engine/util/error.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        const std::string repaired = sylva::exporter::repairAssimpFbxBinary(bytes, 100.0);
        (void)sylva::exporter::repairAssimpFbxBinary(repaired, 1.0);
    } catch (const sylva::InvalidInput&) {
    }
    (void)sylva::exporter::setFbxAsciiUnitScale(std::string(bytes), 100.0);
    return 0;
}
