#include "cliargs.h"
#include "clishared.h"
#include "commands.h"
#include "terminalprogress.h"
#include "usage.h"

#include "document/project.h"
#include "document/projectexport.h"
#include "engine/export/formats.h"
#include "engine/placement/placement.h"
#include "engine/util/error.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <omp.h>
#include <optional>

namespace sylva::cli {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

glm::vec3 parseVec3(const std::string& text, const std::string& option) {
    glm::vec3 v;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &extra) != 3)
        throw UsageError(option + " expects x,y,z (metres), got '" + text + "'");
    return v;
}

} // namespace

int runForest(const std::vector<std::string>& argv) {
    std::vector<std::string> valueOptions{"-o",        "--output", "--camera",
                                          "--threads", "--tile",   "--season"};
    valueOptions.insert(valueOptions.end(), windValueOptions().begin(), windValueOptions().end());
    const Args args(argv, valueOptions,
                    {"--stats", "--no-lod", "--no-adapt", "--no-neighbours", "--no-instancing",
                     "--grow-unique", "--instance-tables", "--naive-placement", "--fsync",
                     "--full-precision", "--assimp-gltf", "--wind", "--no-wind"});
    if (args.positional().size() != 1) throw UsageError(commandUsageLine("forest"));
    auto output = args.value("-o");
    if (!output) output = args.value("--output");
    if (!output) throw UsageError("forest needs an output file: -o out.obj");
    // What the output's format can carry (the format table); an unknown extension is the
    // export's error.
    const exporter::FormatRow* format = exporter::findFormat(*output);
    if (format && !format->instanceTables && args.flag("--instance-tables"))
        throw UsageError(
            "--instance-tables is for " +
            exporter::extensionList([](const exporter::FormatRow& r) { return r.instanceTables; }) +
            ": a " + format->extension + " holds its instances itself");
    if (auto threads = args.integer("--threads", 1, 1024))
        omp_set_num_threads(static_cast<int>(*threads));
    // The flags only translate into the request every front door makes (document/projectexport).
    doc::ExportRequest request;
    request.path = *output;
    if (auto tile = args.value("--tile")) {
        try {
            std::tie(request.tile, request.tileCount) = placement::parseTileSpec(*tile);
        } catch (const InvalidInput& e) {
            throw UsageError(e.what());
        }
    }
    request.lod = !args.flag("--no-lod");
    request.adapt = !args.flag("--no-adapt");
    request.neighbours = !args.flag("--no-neighbours");
    request.instancing = !args.flag("--no-instancing");
    request.adaptVariants = !args.flag("--grow-unique");
    request.naivePlacement = args.flag("--naive-placement");
    if (args.flag("--wind") && args.flag("--no-wind"))
        throw UsageError("--wind and --no-wind contradict each other");
    if (args.flag("--wind")) request.wind = true;
    if (args.flag("--no-wind")) request.wind = false;
    if (args.flag("--wind") && format && format->wind == exporter::WindSupport::None)
        throw UsageError("--wind writes " +
                         exporter::extensionList([](const exporter::FormatRow& r) {
                             return r.wind != exporter::WindSupport::None;
                         }) +
                         " (with its .wind.csv), not " + format->extension);
    request.windOverride = windOverride(args);
    request.fullPrecision = args.flag("--full-precision");
    request.fsync = args.flag("--fsync");
    request.instanceTables = args.flag("--instance-tables");
    request.assimpGltf = args.flag("--assimp-gltf");
    if (auto name = args.value("--season")) request.season = parseSeasonOption(*name);
    if (auto camera = args.value("--camera")) request.camera = parseVec3(*camera, "--camera");

    const auto start = Clock::now();
    const doc::Project project = loadProjectOrScene(args.positional()[0]);
    const double readMs = msSince(start);
    // Ctrl-C is caught from here on, before the exporter creates its temporary file.
    TerminalProgress progress;
    doc::ExportReport report;
    try {
        report = doc::exportProject(project, request, progress);
    } catch (const Cancelled&) {
        progress.finish();
        std::fprintf(stderr, "sylva-cli: interrupted; no output written\n");
        return kInterrupted;
    }
    progress.finish();
    report.loadMs += readMs;
    report.totalMs = msSince(start);
    for (const placement::Shortfall& s : report.stats.shortfalls)
        std::fprintf(stderr,
                     "sylva-cli: warning: domain %zu: placed %zu of %zu '%s' (no room left)\n",
                     s.domain + 1, s.placed, s.requested, report.species[s.species].c_str());
    for (const std::string& w : report.stats.warnings)
        std::fprintf(stderr, "sylva-cli: warning: %s\n", w.c_str());
    if (args.flag("--stats")) {
        const std::string json = doc::exportStatsJson(report, omp_get_max_threads()) + "\n";
        std::fwrite(json.data(), 1, json.size(), stdout);
    }
    return kOk;
}

} // namespace sylva::cli
