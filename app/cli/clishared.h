#pragma once

#include <string>

#include "cliargs.h"
#include "document/project.h"
#include "engine/export/windexport.h"
#include "engine/forest/metrics.h"
#include "engine/mesh/season.h"

namespace sylva::cli {

/// Appends `"key":value` (an integer as such, else the shortest round-trip number) and a comma
/// unless \p comma is false.
void appendJsonNumber(std::string& out, const char* key, double value, bool comma = true);

/// A `.sylva` project, or the reference implementation's scene description (it has "plants"
/// and no "format"); warnings of the loader go to stderr.
doc::Project loadProjectOrScene(const std::string& path);

/// The season --season names; UsageError naming the allowed values for any other.
mesh::Season parseSeasonOption(const std::string& name);

/// The scene metrics as one JSON object (units in the key names).
std::string metricsJson(const forest::SceneMetrics& metrics);

/// The wind options every exporting command takes (value options, then flags), for Args.
extern const std::vector<std::string> kWindValueOptions;
/// `--wind-direction x,y,z`, `--wind-strength`, `--wind-gustiness`, `--wind-frequency`,
/// `--clip-length`, `--clip-fps`, `--bones` (docs/cli.md); UsageError for a malformed value,
/// InvalidInput (with the range) for one out of range.
exporter::WindExportOptions windOptions(const Args& args);

} // namespace sylva::cli
