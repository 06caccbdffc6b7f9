#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "engine/util/value.h"

namespace sylva::graph {

/// \p v as a point or vector `[x, y, z]` of finite numbers. Throws InvalidInput naming \p what:
/// "<what> must be [x, y, z]" for another shape, "<what> must be finite" for inf or NaN.
glm::vec3 vec3Of(const Value& v, const std::string& what);

} // namespace sylva::graph
