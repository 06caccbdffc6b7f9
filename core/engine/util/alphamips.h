#pragma once

#include <vector>

#include "engine/util/image.h"

namespace sylva {

/// The mipmap chain of an RGBA cut-out texture (leaf cards, needle sprays) whose alpha keeps
/// the coverage of level 0 (issue #33; Castaño, "Computing Alpha Mipmaps", 2010): a plain box
/// filter averages a needle two texels wide with the sky beside it, so that a few levels down
/// the alpha of a brush of needles falls below the cut-off and the brush thins away, or (with
/// the cut-off lowered by hand) swells into a solid wedge. Here each level is the 2 x 2 box
/// filter of the one above (colour weighted by alpha, so transparent texels lend it nothing),
/// then its alpha is scaled so that the share of texels at or above \p cutoff is level 0's.
/// Returns levels 1, 2, ... down to 1 x 1 (level 0 is \p image itself); odd sizes round down
/// as OpenGL's do. \p image must have 4 channels. Deterministic.
/// \throw InvalidInput for another channel count or a cutoff outside (0, 1).
std::vector<Image> alphaTestedMips(const Image& image, double cutoff = 0.5);

/// The share of \p image's texels whose alpha is at least \p cutoff (0..1).
double alphaCoverage(const Image& image, double cutoff = 0.5);

} // namespace sylva
