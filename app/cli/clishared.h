#pragma once

#include <string>

#include "cliargs.h"
#include "document/project.h"
#include "document/projectexport.h"
#include "document/statsjson.h"
#include "engine/export/windexport.h"
#include "engine/forest/metrics.h"
#include "engine/mesh/season.h"

namespace sylva::cli {

using doc::appendJsonNumber; // document/statsjson.h: shared with Python's statistics
using doc::metricsJson;

/// A `.sylva` project, or the reference implementation's scene description (it has "plants"
/// and no "format"); warnings of the loader go to stderr.
doc::Project loadProjectOrScene(const std::string& path);

/// The season --season names; UsageError naming the allowed values for any other.
mesh::Season parseSeasonOption(const std::string& name);

/// The wind options every exporting command takes (value options, then flags), for Args.
const std::vector<std::string>& windValueOptions();
/// `--wind-direction x,y,z`, `--wind-strength`, `--wind-gustiness`, `--wind-frequency`,
/// `--clip-length`, `--clip-fps`, `--bones` (docs/cli.md); UsageError for a malformed value,
/// InvalidInput (with the range) for one out of range: the wind settings' ranges are the project
/// settings' spec (doc::settings), each checked as its option is read.
exporter::WindExportOptions windOptions(const Args& args);
/// The same options as settings over a project's wind (`sylva-cli forest --wind`: the project's
/// wind is the default, each flag given overrides its setting); UsageError as windOptions.
doc::WindOverride windOverride(const Args& args);

} // namespace sylva::cli
