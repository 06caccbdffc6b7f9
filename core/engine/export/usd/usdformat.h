#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace sylva::exporter::usd {

/// \p name as a USD prim name: letters, digits and '_' kept, anything else '_', a leading digit
/// prefixed with '_' ("_" when empty). USD identifiers are [A-Za-z_][A-Za-z0-9_]*.
std::string primName(std::string_view name);

/// \p text as a USD string literal, quotes included ("..." with \" \\ \n escaped).
std::string usdString(std::string_view text);

/// Appends the shortest text that reads back as the same float (std::to_chars): the form of
/// transforms, which tiles and the single run must agree on exactly.
void appendFloat(std::string& out, float value);

/// Appends \p value with \p decimals fixed decimals, trailing zeros trimmed ("0.25", "-3", "0").
void appendFixed(std::string& out, double value, int decimals);

/// The value a `half` stores for \p value (round to nearest even), as a float.
float toHalf(float value);

/// Appends the shortest text that reads back (through float, then half) as the same half as
/// \p value: what a `quath` component needs, 1 to 5 significant digits.
void appendHalf(std::string& out, float value);

/// Appends a quaternion in USD's text order (real, i, j, k), each component as a half.
void appendQuath(std::string& out, const glm::quat& q);

} // namespace sylva::exporter::usd
