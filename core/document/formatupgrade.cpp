#include "document/formatupgrade.h"

#include "engine/util/error.h"

#include <cmath>

namespace sylva::doc {

UpgradeReport upgradeFormat(sylva::Value::Object& root, const std::string& formatName, int current,
                            const std::vector<UpgradeStep>& steps, const std::string& fileName,
                            bool refuseNewer) {
    const std::string where = fileName.empty() ? std::string() : fileName + ": ";
    auto format = root.find("format");
    if (format == root.end() || !format->second.isString() ||
        format->second.toString() != formatName)
        throw InvalidInput(where + "not a " + formatName + " file (\"format\": \"" + formatName +
                           "\" is missing)");
    auto version = root.find("format_version");
    if (version == root.end() || !version->second.isNumber() ||
        version->second.toNumber() != std::floor(version->second.toNumber()) ||
        version->second.toNumber() < 1 || version->second.toNumber() > 1e9) // fits an int
        throw InvalidInput(where +
                           "\"format_version\" must be a whole number from 1 to 1000000000");

    UpgradeReport report;
    report.fileVersion = static_cast<int>(version->second.toNumber());
    if (report.fileVersion > current) {
        const std::string message = "written by a newer Sylva (format_version " +
                                    std::to_string(report.fileVersion) +
                                    ", this build reads up to " + std::to_string(current) + ")";
        if (refuseNewer) throw InvalidInput(where + message + "; please update Sylva");
        report.warnings.push_back(where + message + "; unknown settings are ignored");
        return report;
    }
    for (int v = report.fileVersion; v < current; ++v) {
        const UpgradeStep* step = nullptr;
        for (const UpgradeStep& s : steps)
            if (s.from == v) step = &s;
        if (!step)
            throw InvalidInput(where + "no upgrade from format_version " + std::to_string(v));
        step->apply(root);
        // A step with no description only allows new keys: nothing a user needs to hear of.
        if (!step->description.empty()) report.applied.push_back(step->description);
    }
    root["format_version"] = sylva::Value(current);
    return report;
}

} // namespace sylva::doc
