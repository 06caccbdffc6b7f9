#pragma once

// What the binding files share: the Python-side wrappers of engine results.
#include <memory>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "engine/export/windexport.h"
#include "engine/forest/metrics.h"
#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"

namespace sylva::python {

/// sylva.Mesh: a tree's triangle mesh (shared, read-only), arrays made on access.
struct MeshRef {
    std::shared_ptr<const mesh::Mesh> mesh;
};

/// sylva.Skeleton: a tree's skeleton (shared, read-only).
struct SkeletonRef {
    std::shared_ptr<const skel::Skeleton> skeleton;
};

/// A tree's metrics as a dict (units in the key names, as `sylva-cli stats`).
pybind11::dict metricsDict(const forest::TreeMetrics& m);

/// Wind export settings from Python keyword arguments over \p base (None: keep base's),
/// checked with their ranges (InvalidInput names the range).
exporter::WindExportOptions
windExportOptions(const pybind11::object& direction, const pybind11::object& strength,
                  const pybind11::object& gustiness, const pybind11::object& frequency,
                  const pybind11::object& bones, const pybind11::object& clipLength,
                  const pybind11::object& fps, exporter::WindExportOptions base = {});

void bindSpecies(pybind11::module_& m);
void bindForest(pybind11::module_& m);

} // namespace sylva::python
