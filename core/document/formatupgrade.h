#pragma once

#include <functional>
#include <string>
#include <vector>

#include "engine/util/value.h"

namespace sylva::doc {

/// One step of a file format's upgrade chain: rewrites the raw JSON of version `from` into
/// version `from + 1`. Steps run in order before the file is deserialized, so loaders only ever
/// see the current version (the Glaxnimate approach; version checks live nowhere else).
struct UpgradeStep {
    int from = 0;
    std::string description; ///< reported on load; empty: a step that only allows new keys
    std::function<void(sylva::Value::Object&)> apply;
};

/// Result of running a chain.
struct UpgradeReport {
    int fileVersion = 0;               ///< version found in the file
    std::vector<std::string> applied;  ///< descriptions of the steps that ran
    std::vector<std::string> warnings; ///< e.g. "written by a newer Sylva"
};

/// Checks `format` and `format_version` of \p root and applies \p steps up to \p current.
/// Throws InvalidInput (naming \p fileName) when the format name is wrong or the version is
/// missing/invalid. A file newer than \p current is refused when \p refuseNewer, otherwise it
/// loads with a warning (unknown keys are ignored).
UpgradeReport upgradeFormat(sylva::Value::Object& root, const std::string& formatName, int current,
                            const std::vector<UpgradeStep>& steps, const std::string& fileName,
                            bool refuseNewer);

} // namespace sylva::doc
