#include "engine.h"

#include <cstdlib>

#include "convert.h"
#include "project.h"
#include "types.h"

#include "engine/graph/graph.h"

namespace sylva::python {

void bindEngine(py::module_& m) {
    registerErrorTranslator();
    graph::registerBuiltinNodeTypes();
    // Exports copy the bark and leaf textures from here; the engine otherwise looks beside the
    // executable, which is python3 or Blender.
    if (const std::string res = resourcesDir(); !res.empty())
        ::setenv("SYLVA_RESOURCES_DIR", res.c_str(), 0);

    m.attr("__version__") = SYLVA_VERSION;
    m.def("presets_dir", &presetsDir, "the folder of the shipped species presets (*.json)");
    m.def("resources_dir", &resourcesDir, "the folder of the shipped textures (textures/)");
    bindSpecies(m);
    bindTree(m);
    bindForest(m);
}

} // namespace sylva::python
