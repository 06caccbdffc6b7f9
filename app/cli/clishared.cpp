#include "clishared.h"
#include "cliargs.h"

#include "document/projectsettings.h"
#include "engine/util/error.h"
#include "engine/wind/windmodel.h"

#include <cstdio>
#include <cstdlib>
#include <optional>

namespace sylva::cli {

doc::Project loadProjectOrScene(const std::string& path) {
    doc::LoadReport report;
    doc::Project project = doc::loadProjectOrScene(QString::fromStdString(path), &report);
    for (const std::string& w : report.warnings)
        std::fprintf(stderr, "sylva-cli: warning: %s\n", w.c_str());
    return project;
}

mesh::Season parseSeasonOption(const std::string& name) {
    try {
        return mesh::parseSeason(name);
    } catch (const InvalidInput& e) {
        throw UsageError(std::string("--season: ") + e.what());
    }
}

namespace {

/// The project's wind settings a command-line option overrides: the option's name and range are
/// the settings spec's (document/projectsettings), so the usage, the parser and the editor's
/// Properties agree.
struct WindSettingOption {
    const doc::SettingSpec& spec;
    float wind::WindSettings::*setting;
    std::optional<float> doc::WindOverride::*override;
};
const WindSettingOption kWindSettingOptions[] = {
    {doc::settings::kWindStrength, &wind::WindSettings::strength, &doc::WindOverride::strength},
    {doc::settings::kWindGustiness, &wind::WindSettings::gustiness, &doc::WindOverride::gustiness},
    {doc::settings::kWindFrequency, &wind::WindSettings::frequency, &doc::WindOverride::frequency}};

std::optional<float> numberOption(const Args& args, const char* name) {
    const auto text = args.value(name);
    if (!text) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(text->c_str(), &end);
    if (end == text->c_str() || *end != '\0')
        throw UsageError(std::string(name) + " expects a number, got '" + *text + "'");
    return static_cast<float>(v);
}

/// A setting's option, checked against the spec's range: InvalidInput "--wind-strength:
/// wind.strength must be in [0, 2], got 3" (exit status 1, as every value out of range).
std::optional<float> settingOption(const Args& args, const doc::SettingSpec& spec) {
    const std::optional<float> v = numberOption(args, spec.cliOption);
    if (!v) return v;
    try {
        spec.check(*v);
    } catch (const InvalidInput& e) {
        throw InvalidInput(std::string(spec.cliOption) + ": " + e.what());
    }
    return v;
}

std::optional<glm::vec3> directionOption(const Args& args) {
    const auto d = args.value("--wind-direction");
    if (!d) return std::nullopt;
    glm::vec3 v;
    char extra = 0;
    if (std::sscanf(d->c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &extra) != 3)
        throw UsageError("--wind-direction expects x,y,z, got '" + *d + "'");
    return v;
}

} // namespace

const std::vector<std::string>& windValueOptions() {
    // Made on first use: the specs are another translation unit's statics.
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n{"--wind-direction"};
        for (const WindSettingOption& o : kWindSettingOptions)
            n.emplace_back(o.spec.cliOption);
        n.insert(n.end(), {"--clip-length", "--clip-fps", "--bones"});
        return n;
    }();
    return names;
}

doc::WindOverride windOverride(const Args& args) {
    doc::WindOverride o;
    o.direction = directionOption(args);
    for (const WindSettingOption& setting : kWindSettingOptions)
        o.*setting.override = settingOption(args, setting.spec);
    o.clipLength = numberOption(args, "--clip-length");
    o.clipFps = numberOption(args, "--clip-fps");
    if (const auto bones = args.integer("--bones", 2, 1024)) o.bones = static_cast<int>(*bones);
    return o;
}

exporter::WindExportOptions windOptions(const Args& args) {
    exporter::WindExportOptions o;
    if (const auto d = directionOption(args)) o.wind.direction = *d;
    for (const WindSettingOption& setting : kWindSettingOptions)
        if (const auto v = settingOption(args, setting.spec)) o.wind.*setting.setting = *v;
    if (const auto v = numberOption(args, "--clip-length")) o.wind.period = *v;
    if (const auto v = numberOption(args, "--clip-fps")) o.rig.fps = *v;
    if (const auto bones = args.integer("--bones", 2, 1024))
        o.rig.maxBones = static_cast<int>(*bones);
    wind::validate(o.wind);
    wind::validate(o.rig);
    return o;
}

} // namespace sylva::cli
