#pragma once

#include <cstddef>
#include <span>

namespace sylva::mesh {

/// The value of rank \p rank (0-based, below values.size()) among \p values, as a sort would
/// place it: by the floats' bits, ten or eleven at a time from the top (a histogram of the top
/// digit, then of the next among the values that share the digits found). Only for values that
/// are all +0 or above, +infinity included, never -0 or NaN: their bits order as the values, and
/// equal values have equal bits, so the value is the one std::nth_element leaves at that rank.
/// \return false, with \p out untouched, when a value is -0, negative or NaN.
bool valueAtRank(std::span<const float> values, std::size_t rank, float& out);

/// The same with std::nth_element on a copy (for tests, and the values valueAtRank refuses).
float valueAtRankPlain(std::span<const float> values, std::size_t rank);

} // namespace sylva::mesh
