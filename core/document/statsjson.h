#pragma once

#include <string>

#include "engine/forest/metrics.h"

namespace sylva::doc {

/// Appends `"key":value` (an integer as such, else the shortest round-trip number) and a comma
/// unless \p comma is false: the statistics every front door reports (sylva-cli's --stats,
/// Python's export statistics).
void appendJsonNumber(std::string& out, const char* key, double value, bool comma = true);

/// The scene metrics as one JSON object (units in the key names).
std::string metricsJson(const forest::SceneMetrics& metrics);

} // namespace sylva::doc
