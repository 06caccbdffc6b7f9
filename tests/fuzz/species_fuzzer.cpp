// Fuzzes the species loader (JSON, format upgrade chain, graph description) and graph
// validation: any bytes load or throw InvalidInput; a species that loads validates or throws
// InvalidInput, and saving it gives a file that loads back to the same bytes when saved again.
#include "document/speciesfile.h"
#include "engine/graph/graph.h"
#include "engine/util/error.h"

#include <QByteArray>
#include <QString>

#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    sylva::graph::registerBuiltinNodeTypes();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const QString baseDir = QStringLiteral("/nonexistent/sylva-fuzz");
    sylva::graph::SpeciesGraph species;
    try {
        species = sylva::doc::parseSpecies(bytes, QStringLiteral("fuzz.json"), baseDir);
    } catch (const sylva::InvalidInput&) {
        return 0;
    }
    const QByteArray saved = sylva::doc::serializeSpecies(species);
    const sylva::graph::SpeciesGraph again =
        sylva::doc::parseSpecies(saved, QStringLiteral("saved.json"), baseDir);
    if (sylva::doc::serializeSpecies(again) != saved) std::abort();
    try {
        sylva::graph::Evaluator evaluator(species);
        evaluator.validate();
        (void)species.skeletonSource();
    } catch (const sylva::InvalidInput&) {
    }
    return 0;
}
