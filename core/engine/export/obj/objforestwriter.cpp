#include "engine/export/obj/objforestwriter.h"

#include <glm/gtc/matrix_transform.hpp>

#include "engine/util/error.h"

namespace sylva::exporter {

namespace fs = std::filesystem;

ObjForestWriter::ObjForestWriter(fs::path path, const ForestWriterOptions& options)
    : mPath(std::move(path)) {
    ObjOptions obj = options.compact ? ObjOptions::compact() : ObjOptions{};
    obj.mtllib = mPath.stem().string() + ".mtl";
    obj.fsync = options.fsync;
    mWriter = std::make_unique<ObjStreamWriter>(mPath, obj);
}

void ObjForestWriter::setVariants(const std::vector<ExportVariant>& variants) {
    for (const ExportVariant& v : variants)
        if (!v.mesh) throw InvalidInput("variant '" + v.name + "' has no mesh");
}

void ObjForestWriter::add(const std::vector<ExportTree>& trees) {
    std::vector<ObjObject> objects;
    objects.reserve(trees.size());
    for (const ExportTree& t : trees) {
        addMaterialsOf(*t.mesh, mMaterials);
        glm::mat4 m = glm::translate(glm::mat4(1.0f), t.position);
        m = glm::rotate(m, t.rotationY, glm::vec3(0, 1, 0));
        m = glm::scale(m, glm::vec3(t.scale));
        objects.push_back({t.name, t.mesh.get(), m});
    }
    mWriter->add(objects);
}

std::vector<fs::path> ObjForestWriter::commit() {
    const fs::path dir = mPath.parent_path().empty() ? fs::path(".") : mPath.parent_path();
    const fs::path mtl = dir / (mPath.stem().string() + ".mtl");
    writeMtlFile(mtl, mMaterials);
    mWriter->commit();
    std::vector<fs::path> written{mPath, mtl};
    const fs::path res = resourcesDir();
    if (copyTextures(mMaterials, res.empty() ? fs::path() : res / "textures", dir) > 0)
        written.push_back(dir / "textures");
    return written;
}

} // namespace sylva::exporter
