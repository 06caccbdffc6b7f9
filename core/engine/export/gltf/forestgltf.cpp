#include "engine/export/gltf/forestgltf.h"

#include <cmath>
#include <string>

#include "engine/util/error.h"

namespace sylva::exporter::gltf {

namespace fs = std::filesystem;

namespace {
constexpr const char* kInstancing = "EXT_mesh_gpu_instancing";

std::string cellName(const std::pair<int, int>& cell) {
    return "cell_" + std::to_string(cell.first) + "_" + std::to_string(cell.second);
}
} // namespace

ForestGltfWriter::ForestGltfWriter(fs::path path, GltfFormat format, Progress& progress,
                                   ForestGltfOptions options, std::vector<Material> materials)
    : mBuilder(std::move(path), format, progress, options.durability), mOptions(options),
      mMaterials(mBuilder, std::move(materials), options.shippedTextures,
                 format == GltfFormat::Glb) {
    if (!(mOptions.cellSize > 0.0f) || !std::isfinite(mOptions.cellSize))
        throw InvalidInput("glTF cell size must be a positive number of metres, got " +
                           std::to_string(mOptions.cellSize));
}

std::pair<int, int> ForestGltfWriter::cellOf(const glm::vec3& p) const {
    // Clamped so that a tree kilometres away still lands in a cell instead of overflowing int.
    const auto index = [&](float v) {
        const double c = std::floor(static_cast<double>(v) / mOptions.cellSize);
        return static_cast<int>(std::clamp(c, -1.0e9, 1.0e9));
    };
    return {index(p.x), index(p.z)};
}

int ForestGltfWriter::addVariant(const std::string& name, const mesh::Mesh& mesh) {
    mMaterials.describe(mesh);
    const int index = mesh.empty() ? -1 : gltf::addTreeMesh(mBuilder, mesh, name, mMaterials);
    mVariants.emplace_back(name, index);
    return static_cast<int>(mVariants.size() - 1);
}

void ForestGltfWriter::addInstance(int variant, std::uint64_t id, const glm::vec3& position,
                                   const glm::quat& rotation, const glm::vec3& scale) {
    if (variant < 0 || static_cast<std::size_t>(variant) >= mVariants.size())
        throw InvalidInput("glTF export: instance " + std::to_string(id) + " names variant " +
                           std::to_string(variant) + " of " + std::to_string(mVariants.size()));
    mCells[cellOf(position)].instances[variant].push_back({id, position, rotation, scale});
    ++mInstanceCount;
}

int ForestGltfWriter::addTreeMesh(const std::string& name, const mesh::Mesh& mesh) {
    mMaterials.describe(mesh);
    mTreeMeshes.push_back(mesh.empty() ? -1 : gltf::addTreeMesh(mBuilder, mesh, name, mMaterials));
    return static_cast<int>(mTreeMeshes.size() - 1);
}

void ForestGltfWriter::addTree(const std::string& name, std::uint64_t id, int treeMesh,
                               const glm::vec3& position, const glm::quat& rotation,
                               const glm::vec3& scale) {
    if (treeMesh < 0 || static_cast<std::size_t>(treeMesh) >= mTreeMeshes.size())
        throw InvalidInput("glTF export: tree '" + name + "' names mesh " +
                           std::to_string(treeMesh) + " of " + std::to_string(mTreeMeshes.size()));
    mCells[cellOf(position)].trees.push_back({name,
                                              id,
                                              mTreeMeshes[static_cast<std::size_t>(treeMesh)],
                                              {id, position, rotation, scale}});
}

std::vector<fs::path> ForestGltfWriter::commit() {
    Node root;
    root.name = "sylva";
    const int rootNode = mBuilder.addNode(root);
    std::vector<glm::vec3> translations;
    std::vector<glm::quat> rotations;
    std::vector<glm::vec3> scales;
    for (const auto& [key, cell] : mCells) {
        Node cellNode;
        cellNode.name = cellName(key);
        const int cellIndex = mBuilder.addNode(cellNode);
        mBuilder.addChild(rootNode, cellIndex);
        for (const auto& [variant, placed] : cell.instances) {
            const auto& [variantName, mesh] = mVariants[static_cast<std::size_t>(variant)];
            // The node stands at its first instance: a reader without the extension draws
            // the variant once there, at a real tree's place, instead of at the cell's corner.
            const glm::vec3 origin = placed.front().position;
            translations.clear();
            rotations.clear();
            scales.clear();
            Json ids = Json::array();
            for (const Placed& p : placed) {
                translations.push_back(p.position - origin);
                rotations.push_back(glm::normalize(p.rotation));
                scales.push_back(p.scale);
                ids.push_back(p.id);
            }
            Node n;
            n.name = variantName + "_" + cellNode.name;
            n.mesh = mesh;
            n.translation = origin;
            // A variant without geometry (nothing grew) keeps its ids on a node without a mesh:
            // the extension needs a mesh to instance.
            if (mesh >= 0)
                n.extensions[kInstancing]["attributes"] = {
                    {"TRANSLATION", mBuilder.addVec3(translations, Target::None)},
                    {"ROTATION", mBuilder.addQuats(rotations)},
                    {"SCALE", mBuilder.addVec3(scales, Target::None)}};
            n.extras = {{"sylva_variant", variantName}, {"sylva_ids", std::move(ids)}};
            mBuilder.addChild(cellIndex, mBuilder.addNode(n));
        }
        for (const UniqueTree& t : cell.trees) {
            Node n;
            n.name = t.name;
            n.mesh = t.mesh;
            n.translation = t.where.position;
            n.rotation = glm::normalize(t.where.rotation);
            n.scale = t.where.scale;
            n.extras = {{"sylva_id", t.id}};
            mBuilder.addChild(cellIndex, mBuilder.addNode(n));
        }
    }
    if (mInstanceCount > 0) mBuilder.useExtension(kInstancing);
    mBuilder.addScene("sylva", {rootNode});
    return mBuilder.finish();
}

} // namespace sylva::exporter::gltf
