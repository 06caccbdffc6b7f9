#include "engine/export/obj/objlodchain.h"

#include "engine/export/obj/objwriter.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

void writeObjLodChain(const LodChainWrite& w, GameLodFiles& files, std::vector<fs::path>& written) {
    const fs::path& dir = w.dir;
    const std::string& base = w.base;
    const mesh::BudgetLodChain& chain = w.chain;
    const std::vector<Material>& materials = w.materials;
    Progress& progress = w.progress;
    files.mtl = dir / (base + ".mtl");
    writeMtlFile(files.mtl, materials);
    written.push_back(files.mtl);
    ObjOptions obj;
    obj.mtllib = files.mtl.filename().string();
    for (std::size_t i = 0; i < chain.levels.size(); ++i) {
        writeObjFile(files.levels[i].obj, {{files.levels[i].name, &chain.levels[i].mesh}}, obj);
        written.push_back(files.levels[i].obj);
        progress.checkCancelled();
    }
}

} // namespace sylva::exporter
