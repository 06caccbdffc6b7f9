#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace sylva::doc {

/// One step of a path into a JSON document: an object's key or an array's index.
using JsonStep = std::variant<std::string, std::size_t>;

/// Line and column (1-based; columns count bytes) where a place in a JSON text starts.
struct JsonPlace {
    int line = 1;
    int column = 1;
};

/// Where the value at \p path starts in \p text (for a path ending in a key: where the key is
/// written), or the deepest step of it that exists. For errors found after parsing (a file's
/// values out of range) to be reported as file:line:col. Never throws; text that is not JSON
/// gives the place the walk stopped.
JsonPlace locateJson(const std::string& text, const std::vector<JsonStep>& path);

} // namespace sylva::doc
