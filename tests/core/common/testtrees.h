#pragma once

#include <utility>
#include <vector>

#include "engine/lsystem/turtle.h"
#include "engine/mesh/leafplacement.h"
#include "engine/mesh/treemesh.h"
#include "engine/skeleton/skeleton.h"
#include "testwords.h"

namespace sylva::testing {

/// A small branching tree (testTreeWord(5), 30°, 0.5 m steps) with leaves on its twigs under
/// 5 cm radius: the mesh tests' common subject.
inline skel::Skeleton leafyTree() {
    lsys::TurtleSettings t;
    t.angleDegrees = 30;
    t.step = 0.5;
    t.width = 0.3;
    skel::Skeleton s = lsys::interpret(makeWord(testTreeWord(5)), t);
    mesh::LeafPlacement p;
    p.maxBranchRadius = 0.05;
    s.leaves = mesh::placeLeaves(s, p);
    return s;
}

/// The distance LOD's mesh at the start of each of \p settings' bands (what a forest draws
/// there; the levels the dropped mesh::buildLodChain made, built by the live path).
inline std::vector<std::pair<double, mesh::Mesh>>
bandLevels(const skel::Skeleton& s, const mesh::TreeMeshSettings& settings) {
    std::vector<std::pair<double, mesh::Mesh>> levels;
    for (const mesh::LodBand& band : settings.lod.bands) {
        mesh::TreeMeshSettings at = settings;
        at.useLod = true;
        at.cameraDistance = band.distance;
        levels.emplace_back(band.distance, mesh::buildTreeMesh(s, at));
    }
    return levels;
}

} // namespace sylva::testing
