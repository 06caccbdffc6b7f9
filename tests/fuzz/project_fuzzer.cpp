// Fuzzes the project loader (JSON, the format upgrade chain, every key), the reference scene
// import and the project -> ForestScene conversion. Any bytes load or throw InvalidInput; a
// project that loads saves to a file that loads back equal (but for the app_version stamp)
// and saves again to the same bytes. The same bytes are also imported
// as a reference scene description (through a file, as the CLI does). Projects whose species
// are all inline and that name no file are converted to a ForestScene too.
#include "fuzztempfile.h"

#include "document/project.h"
#include "document/scenebuild.h"
#include "engine/graph/graph.h"
#include "engine/util/error.h"

#include <QByteArray>
#include <QString>

#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace {

bool namesNoFile(const sylva::doc::Project& p) {
    for (const auto& s : p.species)
        if (!s.graph) return false;
    for (const auto& d : p.domains)
        if (d.shape == "terrain") return false;
    return p.obstacles.empty();
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    sylva::graph::registerBuiltinNodeTypes();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const QString name = QStringLiteral("/nonexistent/sylva-fuzz/fuzz.sylva");
    try {
        doc::LoadReport report;
        doc::Project project = doc::parseProject(bytes, name, &report);
        const QByteArray saved = doc::serializeProject(project);
        const doc::Project again = doc::parseProject(saved, name);
        project.appVersion = again.appVersion; // saving stamps this version when there is none
        if (!(again == project) || doc::serializeProject(again) != saved) std::abort();
        if (namesNoFile(project)) (void)doc::makeForestScene(project);
    } catch (const InvalidInput&) {
    }
    try {
        const auto file = fuzz::writeTempInput(data, size, ".scene.json");
        (void)doc::importReferenceScene(QString::fromStdString(file.string()));
    } catch (const InvalidInput&) {
    }
    return 0;
}
