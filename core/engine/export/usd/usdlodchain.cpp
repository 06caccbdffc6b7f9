#include "engine/export/usd/usdlodchain.h"

#include <algorithm>
#include <map>
#include <set>

#include "engine/export/usd/usdformat.h"
#include "engine/export/usd/usdmesh.h"
#include "engine/util/error.h"

namespace sylva::exporter::usd {

namespace {

void appendDouble(std::string& out, double v) {
    appendFloat(out, static_cast<float>(v));
}

void appendVec3(std::string& out, const glm::vec3& v) {
    out += '(';
    appendFloat(out, v.x);
    out += ", ";
    appendFloat(out, v.y);
    out += ", ";
    appendFloat(out, v.z);
    out += ')';
}

} // namespace

std::string formatLodChainStage(const mesh::BudgetLodChain& chain, const UsdLodChainNames& names,
                                Progress& progress) {
    if (chain.levels.empty()) throw InvalidInput("a USD LOD chain needs at least one level");
    if (names.levelNames.size() != chain.levels.size())
        throw InvalidInput("a USD LOD chain needs one name per level");
    const bool impostor = chain.impostor && !names.impostorColor.empty();
    const std::string root = primName(names.prim);
    const std::string scope = "/" + root + "/Materials";

    // Material prims by name, sorted, as the forest stage names them; the impostor's own.
    std::map<std::string, std::string> prims;
    std::set<std::string> used;
    std::vector<Material> materials = names.materials;
    Material card;
    if (impostor) {
        card.name = names.impostorName;
        card.diffuse = glm::vec3(0.25f, 0.35f, 0.15f);
        card.diffuseTexture = names.impostorColor;
        card.normalTexture = names.impostorNormal;
        card.twoSided = true;
        card.alphaMask = true;
        materials.push_back(card);
    }
    std::vector<std::pair<std::string, const Material*>> sorted;
    for (const Material& m : materials) {
        if (prims.count(m.name)) continue;
        std::string prim = primName(m.name);
        for (int k = 2; !used.insert(prim).second; ++k)
            prim = primName(m.name) + "_" + std::to_string(k);
        prims.emplace(m.name, prim);
        sorted.emplace_back(prim, &m);
    }
    std::sort(sorted.begin(), sorted.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    const MaterialPathOf levelMaterial = [&](const mesh::Submesh& run) {
        const auto it = prims.find(materialName(run));
        if (it == prims.end())
            throw InvalidInput("material '" + materialName(run) + "' of a LOD level is not given");
        return scope + "/" + it->second;
    };

    std::string out;
    out += "#usda 1.0\n(\n    customLayerData = {\n        string generator = \"Sylva\"\n";
    out += "        string sylvaFormat = \"sylva-lod-chain\"\n    }\n";
    out += "    defaultPrim = \"" + root + "\"\n    metersPerUnit = 1\n    upAxis = \"Y\"\n)\n\n";
    out += "def Xform \"" + root + "\" (\n    kind = \"component\"\n";
    out += "    variants = {\n        string lod = \"LOD0\"\n    }\n";
    out += "    prepend variantSets = \"lod\"\n)\n{\n";
    out += "    custom string sylva:species = " + usdString(names.species) + "\n";
    out += "    custom float3 sylva:boundingSphere:centre = ";
    appendVec3(out, chain.centre);
    out += "\n    custom float sylva:boundingSphere:radius = ";
    appendFloat(out, chain.radius);
    out += "\n\n    variantSet \"lod\" = {\n";
    for (std::size_t i = 0; i < chain.levels.size(); ++i) {
        const mesh::BudgetLevel& l = chain.levels[i];
        const std::string variant = "LOD" + std::to_string(i);
        out += "        \"" + variant + "\" {\n";
        out += "            def Xform \"" + variant + "\"\n            {\n";
        out +=
            "                custom string sylva:name = " + usdString(names.levelNames[i]) + "\n";
        out += "                custom int sylva:triangles = " +
               std::to_string(l.mesh.triangleCount()) + "\n";
        out += "                custom double sylva:switchDistance = ";
        appendDouble(out, l.distance);
        out += "\n                custom double sylva:screenSize = ";
        appendDouble(out, l.screenSize);
        out += "\n\n";
        appendMeshPrims(out, l.mesh, 16, true, levelMaterial);
        out += "            }\n        }\n";
        progress.checkCancelled();
    }
    if (impostor) {
        const mesh::Impostor& imp = *chain.impostor;
        const std::string cardPath = scope + "/" + prims.at(card.name);
        out += "        \"impostor\" {\n";
        out += "            def Xform \"impostor\"\n            {\n";
        out += "                custom string sylva:name = " + usdString(names.impostorName) + "\n";
        out += "                custom double sylva:switchDistance = ";
        appendDouble(out, chain.impostorDistance);
        out += "\n                custom double sylva:screenSize = ";
        appendDouble(out, chain.impostorScreenSize);
        out += "\n                custom string sylva:impostor:layout = \"";
        out += imp.settings.hemisphere ? "hemi-octahedral\"\n" : "octahedral\"\n";
        out += "                custom int sylva:impostor:grid = " +
               std::to_string(imp.settings.grid) + "\n";
        out += "                custom int sylva:impostor:cellPixels = " +
               std::to_string(imp.settings.cellPixels) + "\n";
        out += "                custom float3 sylva:impostor:centre = ";
        appendVec3(out, imp.centre);
        out += "\n                custom float sylva:impostor:radius = ";
        appendFloat(out, imp.radius);
        out += "\n                custom asset sylva:impostor:colorMap = @" + names.impostorColor +
               "@\n";
        out += "                custom asset sylva:impostor:normalMap = @" + names.impostorNormal +
               "@\n";
        out += "                custom asset sylva:impostor:depthMap = @" + names.impostorDepth +
               "@\n";
        out += "                custom string sylva:impostor:spec = \"docs/lods.md\"\n\n";
        appendMeshPrims(out, mesh::impostorCard(imp), 16, false,
                        [&](const mesh::Submesh&) { return cardPath; });
        out += "            }\n        }\n";
    }
    out += "    }\n\n";
    appendMaterialScope(out, scope, sorted);
    out += "}\n";
    return out;
}

} // namespace sylva::exporter::usd
