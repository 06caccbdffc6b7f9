// The first, straightforward tube mesher; see referencetubemesh.cpp.
#pragma once

#include "engine/mesh/tubemesh.h"

namespace sylva::mesh::reference {

/// Same contract as mesh::appendTubes (and, by test, the same bytes).
void appendTubesReference(Mesh& out, const skel::Skeleton& skeleton, const TubeSettings& settings,
                          Progress& progress = noProgress());

/// tubeRadii of the first version.
std::vector<float> tubeRadiiReference(const skel::Skeleton& skeleton, const TubeSettings& settings);

} // namespace sylva::mesh::reference
