#pragma once

#include "engine/lsystem/turtle.h"
#include "engine/mesh/leafplacement.h"
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

} // namespace sylva::testing
