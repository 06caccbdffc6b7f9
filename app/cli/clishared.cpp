#include "clishared.h"
#include "cliargs.h"

#include "engine/util/error.h"

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

const std::vector<std::string> kWindValueOptions = {
    "--wind-direction", "--wind-strength", "--wind-gustiness", "--wind-frequency",
    "--clip-length",    "--clip-fps",      "--bones"};

namespace {

float numberOption(const Args& args, const char* name, float fallback) {
    const auto text = args.value(name);
    if (!text) return fallback;
    char* end = nullptr;
    const double v = std::strtod(text->c_str(), &end);
    if (end == text->c_str() || *end != '\0')
        throw UsageError(std::string(name) + " expects a number, got '" + *text + "'");
    return static_cast<float>(v);
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

doc::WindOverride windOverride(const Args& args) {
    doc::WindOverride o;
    o.direction = directionOption(args);
    auto number = [&args](const char* name, std::optional<float>& into) {
        if (args.value(name)) into = numberOption(args, name, 0.0f);
    };
    number("--wind-strength", o.strength);
    number("--wind-gustiness", o.gustiness);
    number("--wind-frequency", o.frequency);
    number("--clip-length", o.clipLength);
    number("--clip-fps", o.clipFps);
    if (const auto bones = args.integer("--bones", 2, 1024)) o.bones = static_cast<int>(*bones);
    return o;
}

exporter::WindExportOptions windOptions(const Args& args) {
    exporter::WindExportOptions o;
    auto number = [&](const char* name, float& into) { into = numberOption(args, name, into); };
    if (const auto d = directionOption(args)) o.wind.direction = *d;
    number("--wind-strength", o.wind.strength);
    number("--wind-gustiness", o.wind.gustiness);
    number("--wind-frequency", o.wind.frequency);
    number("--clip-length", o.wind.period);
    number("--clip-fps", o.rig.fps);
    if (const auto bones = args.integer("--bones", 2, 1024))
        o.rig.maxBones = static_cast<int>(*bones);
    wind::validate(o.wind);
    wind::validate(o.rig);
    return o;
}

} // namespace sylva::cli
