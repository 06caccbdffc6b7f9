// Fuzzes the engine's JSON reader (sylva::Value, behind species and project files): any text
// parses or throws InvalidInput, and what parses prints to canonical JSON that parses back to
// an equal value and prints identically again (compact and indented forms).
#include "engine/util/error.h"
#include "engine/util/value.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using sylva::Value;
    const std::string text(reinterpret_cast<const char*>(data), size);
    Value value;
    try {
        value = Value::parseJson(text, "fuzz.json");
    } catch (const sylva::InvalidInput&) {
        return 0;
    }
    const std::string compact = value.toJson();
    const Value again = Value::parseJson(compact, "compact.json");
    if (!(again == value) || again.toJson() != compact) std::abort();
    const Value pretty = Value::parseJson(value.toPrettyJson(), "pretty.json");
    if (!(pretty == value)) std::abort();
    (void)value.hash();
    (void)Value::parseLoose(text);
    return 0;
}
