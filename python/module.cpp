// `import sylva`: the engine's bindings as an extension module for Debian's python3 (and so
// for Debian's Blender).
#include <cstdlib>
#include <cstring>

#include "engine/util/memorypolicy.h"
#include "python/bindings/engine.h"

PYBIND11_MODULE(sylva, m) {
    m.doc() = "Sylva: procedural trees and forests (species, growth, forests, export).";
    // Freed tree arrays are reused by the next tree, at most 64 MiB of them kept from the
    // host (docs/python.md); SYLVA_MALLOC=system leaves glibc's policy as the host set it.
    const char* policy = std::getenv("SYLVA_MALLOC");
    if (policy == nullptr || std::strcmp(policy, "system") != 0)
        sylva::keepFreedMemoryUpTo(std::size_t{64} << 20);
    sylva::python::bindEngine(m);
}
