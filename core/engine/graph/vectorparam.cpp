#include "engine/graph/vectorparam.h"

#include <cmath>

#include "engine/util/error.h"

namespace sylva::graph {

glm::vec3 vec3Of(const Value& v, const std::string& what) {
    const Value::Array& a = v.toArray(what);
    if (a.size() != 3) throw InvalidInput(what + " must be [x, y, z]");
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) {
        const double d = a[static_cast<std::size_t>(i)].toNumber(what);
        if (!std::isfinite(d)) throw InvalidInput(what + " must be finite");
        out[i] = static_cast<float>(d);
    }
    return out;
}

} // namespace sylva::graph
