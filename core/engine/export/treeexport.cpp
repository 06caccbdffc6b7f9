#include "engine/export/treeexport.h"

#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

namespace {

ForestWriterOptions fromObjChoices(ObjChoices obj) {
    ForestWriterOptions o;
    o.fsync = obj.fsync;
    o.compact = obj.compact;
    return o;
}

} // namespace

TreeExporter::TreeExporter(fs::path path, ObjChoices obj)
    : TreeExporter(std::move(path), fromObjChoices(obj)) {}

TreeExporter::TreeExporter(fs::path path, ForestWriterOptions options)
    : mPath(std::move(path)), mFormat(formatFor(mPath)), mOptions(std::move(options)) {
    // Like other exporters, write into a folder that does not exist yet (out/forest.obj).
    if (const fs::path dir = mPath.parent_path(); !dir.empty()) {
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (ec) throw IoError("cannot create " + dir.string() + ": " + ec.message());
    }
    mWriter = mFormat.makeWriter(mPath, mOptions);
}

TreeExporter::~TreeExporter() = default;

void TreeExporter::setProgress(Progress& progress) {
    mProgress = &progress;
    mWriter->setProgress(progress);
}

void TreeExporter::setInstanceTables(bool on) {
    if (on && !mFormat.instanceTables)
        throw InvalidInput(std::string("instance tables are for ") +
                           extensionList([](const FormatRow& r) { return r.instanceTables; }) +
                           ": a " + mFormat.extension + " holds its instances itself");
    if (on && !mTables) mTables.emplace();
    if (!on) mTables.reset();
}

void TreeExporter::setAssimpGltf(bool on) {
    if (mOptions.assimpGltf == on) return;
    mOptions.assimpGltf = on;
    mWriter = mFormat.makeWriter(mPath, mOptions);
    mWriter->setProgress(*mProgress);
}

void TreeExporter::addVariants(const std::vector<ExportVariant>& variants) {
    mWriter->setVariants(variants);
}

void TreeExporter::add(const std::vector<ExportTree>& trees) {
    mWriter->add(trees);
    if (mTables) mTables->add(trees);
}

std::vector<fs::path> TreeExporter::commit() {
    mProgress->checkCancelled();
    std::vector<fs::path> written = mWriter->commit();
    if (mTables) {
        const fs::path dir = mPath.parent_path().empty() ? fs::path(".") : mPath.parent_path();
        const fs::path json = dir / (mPath.stem().string() + ".instances.json");
        const fs::path csv = dir / (mPath.stem().string() + ".instances.csv");
        writeFileAtomically(json, formatInstancesJson(mTables->scene()));
        writeFileAtomically(csv, formatInstancesCsv(mTables->scene()));
        written.push_back(json);
        written.push_back(csv);
    }
    return written;
}

} // namespace sylva::exporter
