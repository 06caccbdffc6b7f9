#include "engine/export/windexport.h"

#include <algorithm>
#include <cstring>
#include <map>

#include "engine/export/exportnames.h"
#include "engine/export/formats.h"
#include "engine/export/materials.h"
#include "engine/export/obj/objwriter.h"
#include "engine/export/treeexport.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"
#include "engine/wind/windelements.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

WindExporter::WindExporter(fs::path path, WindExportOptions options, Progress& progress)
    : mPath(std::move(path)), mOptions(options), mProgress(progress) {
    wind::validate(mOptions.wind);
    wind::validate(mOptions.rig);
    const FormatRow* format = findFormat(mPath);
    if (!format || format->wind == WindSupport::None)
        throw InvalidInput("wind export writes " + extensionList([](const FormatRow& r) {
                               return r.wind != WindSupport::None;
                           }) +
                           ", not '" + mPath.extension().string() + "'");
    mFormat = format->format;
}

WindExporter::~WindExporter() = default;

void WindExporter::add(const std::vector<WindExportTree>& trees) {
    for (const WindExportTree& t : trees) {
        if (!t.mesh || !t.skeleton)
            throw InvalidInput("wind export of '" + t.name + "' needs its mesh and skeleton");
        if (t.mesh->empty()) continue; // nothing to draw or rig (a tree pruned away)
        mTrees.push_back(t);
    }
}

namespace {

std::shared_ptr<const mesh::Mesh> withWindData(const WindExportTree& tree) {
    if (tree.mesh->wind.size() == tree.mesh->positions.size() && !tree.mesh->positions.empty())
        return tree.mesh;
    auto copy = std::make_shared<mesh::Mesh>(*tree.mesh);
    wind::addWindData(*copy, *tree.skeleton);
    return copy;
}

} // namespace

std::shared_ptr<const mesh::Mesh> WindExporter::windMesh(const WindExportTree& tree) {
    std::shared_ptr<const mesh::Mesh>& cached = mWindMeshes[tree.mesh.get()];
    if (!cached) cached = withWindData(tree);
    return cached;
}

WindExporter::Prepared WindExporter::prepare(const WindExportTree& tree,
                                             const WindExportOptions& options) {
    return prepare(tree, withWindData(tree), options);
}

WindExporter::Prepared WindExporter::prepare(const WindExportTree& tree,
                                             std::shared_ptr<const mesh::Mesh> withWind,
                                             const WindExportOptions& options) {
    const wind::WindElements elements = wind::buildWindElements(*tree.skeleton);
    Prepared p;
    p.mesh = std::move(withWind);
    p.rig = wind::buildRig(elements, *tree.skeleton, options.rig);
    p.weights = wind::skinWeights(p.rig, elements, *p.mesh);
    p.clip = wind::bakeClip(p.rig, elements, options.wind, options.rig);
    p.pivotPainter = buildPivotPainter(elements, *tree.skeleton, *p.mesh);
    return p;
}

std::vector<fs::path> WindExporter::commit() {
    std::vector<fs::path> written;
    // The rig's writers; a format with the table only (OBJ: its caller writes the geometry)
    // gets the table.
    switch (mFormat) {
    case Format::Glb:
    case Format::Gltf:
        written = writeGltf();
        break;
    case Format::Fbx:
        written = writeFbx();
        break;
    case Format::Obj:
    case Format::Usda:
        break;
    }
    writeTable();
    written.push_back(mPath.parent_path() / (mPath.stem().string() + ".wind.csv"));
    return written;
}

std::vector<fs::path> WindExporter::writePivotPainterFiles(
    const std::vector<std::pair<std::string, const Prepared*>>& prepared) {
    std::vector<fs::path> written;
    for (const auto& [name, p] : prepared) {
        mProgress.checkCancelled();
        // One tree: <stem>_pivot_index.exr; several unique meshes: <stem>_<tree>_pivot_index.exr.
        const std::string stem = prepared.size() == 1
                                     ? mPath.stem().string()
                                     : mPath.stem().string() + "_" + fileSafeName(name);
        for (const fs::path& f : writePivotPainter(mPath.parent_path() / stem, p->pivotPainter))
            written.push_back(f);
    }
    return written;
}

void WindExporter::writeTable() {
    // object,vertex,x,y,z then the 32 floats of mesh::WindVertex in their order.
    std::string out = "object,vertex,x,y,z";
    for (int k = 0; k < 3; ++k)
        out += ",pivot" + std::to_string(k) + "_x,pivot" + std::to_string(k) + "_y,pivot" +
               std::to_string(k) + "_z,pivot" + std::to_string(k) + "_u";
    for (int k = 0; k < 3; ++k)
        out += ",branch" + std::to_string(k) + "_x,branch" + std::to_string(k) + "_y,branch" +
               std::to_string(k) + "_z,branch" + std::to_string(k) + "_stiffness";
    out += ",phase0,phase1,phase2,phase_flutter,level,flutter_weight,reserved0,reserved1\n";
    // Streamed in blocks (the table of a 1,000-tree forest is gigabytes: held whole, it ran
    // out of memory).
    AtomicFile file(mPath.parent_path() / (mPath.stem().string() + ".wind.csv"),
                    Durability::Durable);
    constexpr std::size_t kBlock = std::size_t{4} << 20;
    char buf[48];
    for (const WindExportTree& tree : mTrees) {
        mProgress.checkCancelled();
        const std::shared_ptr<const mesh::Mesh> m = windMesh(tree);
        for (std::size_t i = 0; i < m->positions.size(); ++i) {
            out += tree.name;
            out += ',';
            out += std::to_string(i);
            auto put = [&](float v) {
                out += ',';
                out.append(buf, formatFixed(buf, v, 6));
            };
            for (int c = 0; c < 3; ++c)
                put(m->positions[i][c]);
            const float* w = &m->wind[i].pivot[0].x;
            for (int c = 0; c < 32; ++c)
                put(w[c]);
            out += '\n';
            if (out.size() >= kBlock) {
                file.write(out);
                out.clear();
            }
        }
    }
    file.write(out);
    file.commit();
}

} // namespace sylva::exporter
