#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::mesh {

/// The shape of a species' bark as geometry (issue #44): the tube mesher displaces the rings of
/// thick axes outward by this pattern at the nearest level of detail.
enum class BarkPattern : std::uint8_t {
    Ridges, ///< long ridges split by V furrows, meandering and broken across (oak, maple)
    Plates, ///< flat plates of varying height between cracks around and along (pine)
};

/// "ridges" or "plates"; throws InvalidInput naming the allowed values otherwise.
BarkPattern parseBarkPattern(const std::string& name);

/// Ring vertices a column (a ridge or a plate) of the pattern gets around the axis.
inline constexpr int kBarkSidesPerColumn = 4;

/// Ring spacing along the axis, in column widths, where the pattern is drawn: ridges run along
/// the axis and need fewer rings than plates, whose cracks also run around it.
double barkRingSpacing(BarkPattern pattern);

/// How far the bark stands out at a point, in [0, 1] (0: the bottom of a furrow or crack, on the
/// skeleton's radius). \p x is the position around the axis in columns, periodic with period
/// \p columns (so the ring closes), \p y the arc length along the axis in column widths; \p seed
/// varies the pattern from axis to axis. Deterministic: integer hashing and float arithmetic
/// only, the same on every platform.
float barkReliefShape(BarkPattern pattern, float x, float y, int columns, std::uint32_t seed);

/// The rings of one axis (their pattern, columns and sides): what the ridges need of each
/// vertex's place around the axis (x_j, its warp noise's lattice columns and blend), the same on
/// every ring, made once for all of them; and the room a ring's lattice rows take.
struct BarkRing {
    BarkRing(BarkPattern pattern, int columns, int sides);
    BarkPattern pattern;
    int columns;
    int sides;
    std::vector<float> x, blend;     ///< the ridges' x_j and the warp noise's smoothed fraction
    std::vector<std::int32_t> lower; ///< the warp lattice's column below x_j (the next: wraps)
    std::vector<float> scratch;      ///< a ring's lattice rows, heights and breaks
};

/// One ring of the pattern: row[j] = amplitude * barkReliefShape(pattern, x_j, y, columns, seed)
/// for j in [0, sides), x_j = float(j * columns) / float(sides), bit for bit. The ridges' lattice
/// hashes, constant along a ring, and each column's break and height are made once a ring
/// instead of once a vertex (the English oak's bark: about a quarter of its tube meshing); what
/// depends on j alone (x_j, its lattice columns and blend: a division, a floor, a smoothstep and
/// an integer division a vertex) once for all the rings of \p ring.
void barkReliefRow(BarkRing& ring, float y, std::uint32_t seed, float amplitude, float* row);

/// The same for one ring (a BarkRing made for it).
void barkReliefRow(BarkPattern pattern, int columns, int sides, float y, std::uint32_t seed,
                   float amplitude, float* row);

/// A relief ring's slopes for its vertices' normals (the tube mesher's relief rings), j from 0 to
/// \p res: dTh[j] = (row[jNext] - row[jPrev]) / twoDTheta, the seam's neighbours across it (jPrev
/// of 0 is res - 1, jNext of res is 1), and dS[j] = (b[j] - a[j]) / ds, 0 where ds is not above
/// 1e-12: bit for bit those quotients one by one, made four to a division (they were a relief
/// vertex's two divisions besides its normal's). \p dTh and \p dS have room for res + 4 floats.
void barkSlopeRow(const float* row, const float* a, const float* b, int res, float twoDTheta,
                  float ds, float* dTh, float* dS);

/// A relief ring's vertices, j from 0 to \p count - 1: with a = (ax[j], ay[j]) its direction
/// round the ring (cos, sin), radial = a.x n + a.y b and around = -a.y n + a.x b, the position
/// p + rho[j] radial and the normal safeNormalize(rho[j] radial - dTheta[j] around - rho[j] dS[j]
/// t, radial, minLength), as glm makes them vertex by vertex, bit for bit; written to \p out as six
/// rows of \p stride floats (position x, y, z, normal x, y, z). On SSE2 four vertices to an
/// instruction (their square roots and divisions: the relief vertices waited on the divider):
/// \p ax, \p ay, \p rho, \p dTheta, \p dS are read up to \p count rounded up to four, and
/// \p stride is at least that.
void barkReliefVertices(const float* ax, const float* ay, std::size_t count, const glm::vec3& p,
                        const glm::vec3& n, const glm::vec3& b, const glm::vec3& t,
                        const float* rho, const float* dTheta, const float* dS, float minLength,
                        float* out, std::size_t stride);

/// barkReliefVertices' lanes (\p lanes: x, y, z of the positions, then of the normals, each row
/// \p stride apart) as \p count vertices: pos[j] = (x, y, z), nrm[j] likewise and
/// uv[j] = (uTiles · u[j], v), the same bits as a vertex at a time. Four vertices to three
/// 16-byte stores of each array on SSE2 (a vertex's two 8-byte and 4-byte stores of each
/// were most of the relief rings' samples), the last up to three a vertex at a time.
void barkReliefInterleave(const float* lanes, std::size_t stride, std::size_t count, const float* u,
                          float uTiles, float v, glm::vec3* pos, glm::vec3* nrm, glm::vec2* uv);

} // namespace sylva::mesh
