#include "clishared.h"
#include "cliargs.h"

#include "engine/util/error.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace sylva::cli {

void appendJsonNumber(std::string& out, const char* key, double value, bool comma) {
    char buf[32];
    // Counts as integers: the shortest form of 100000.0 is "1e+05", which scripts read as a float.
    const bool integral = value > -9.0e15 && value < 9.0e15 &&
                          value == static_cast<double>(static_cast<long long>(value));
    const auto end = integral
                         ? std::to_chars(buf, buf + sizeof buf, static_cast<long long>(value)).ptr
                         : std::to_chars(buf, buf + sizeof buf, value).ptr;
    out += '"';
    out += key;
    out += "\":";
    out.append(buf, end);
    if (comma) out += ',';
}

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

std::string metricsJson(const forest::SceneMetrics& m) {
    std::string json = "{";
    appendJsonNumber(json, "trees", static_cast<double>(m.trees));
    appendJsonNumber(json, "mean_height_m", m.meanHeightM);
    appendJsonNumber(json, "mean_dbh_m", m.meanDbhM);
    appendJsonNumber(json, "mean_crown_width_m", m.meanCrownWidthM);
    appendJsonNumber(json, "wood_volume_m3", m.woodVolumeM3);
    appendJsonNumber(json, "dry_biomass_kg", m.dryBiomassKg);
    appendJsonNumber(json, "carbon_kg", m.carbonKg);
    appendJsonNumber(json, "co2_kg", m.co2Kg);
    appendJsonNumber(json, "chave_agb_kg", m.chaveAgbKg, false);
    return json + "}";
}

const std::vector<std::string> kWindValueOptions = {
    "--wind-direction", "--wind-strength", "--wind-gustiness", "--wind-frequency",
    "--clip-length",    "--clip-fps",      "--bones"};

exporter::WindExportOptions windOptions(const Args& args) {
    exporter::WindExportOptions o;
    auto number = [&](const char* name, float& into) {
        const auto text = args.value(name);
        if (!text) return;
        char* end = nullptr;
        const double v = std::strtod(text->c_str(), &end);
        if (end == text->c_str() || *end != '\0')
            throw UsageError(std::string(name) + " expects a number, got '" + *text + "'");
        into = static_cast<float>(v);
    };
    if (const auto d = args.value("--wind-direction")) {
        glm::vec3 v;
        char extra = 0;
        if (std::sscanf(d->c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &extra) != 3)
            throw UsageError("--wind-direction expects x,y,z, got '" + *d + "'");
        o.wind.direction = v;
    }
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
