#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::growth {

enum class EnvelopeShape { Sphere, Ellipsoid, Cone, Cylinder, Hemisphere, Profile, Mesh };

/// Parses "sphere", "ellipsoid", ...; throws InvalidInput listing the allowed names.
EnvelopeShape envelopeShapeFromName(const std::string& name);
const char* envelopeShapeName(EnvelopeShape shape);

class MeshVolume;

/// The volume the attraction points are scattered in. Y is up, metres. All shapes except the
/// sphere, ellipsoid and mesh are placed by the centre of their flat base (`base`) and grow up +Y.
/// Copies are cheap (a mesh is shared).
class Envelope {
public:
    /// \param radius metres, > 0
    static Envelope sphere(const glm::vec3& center, float radius);
    /// \param radii semi-axes along X, Y, Z in metres, each > 0
    static Envelope ellipsoid(const glm::vec3& center, const glm::vec3& radii);
    /// A cone with its base disc at \p base; apex at base + (0, height, 0). With \p inverted the
    /// apex is at the bottom (base + 0) and the disc at the top.
    static Envelope cone(const glm::vec3& base, float radius, float height, bool inverted = false);
    static Envelope cylinder(const glm::vec3& base, float radius, float height);
    /// Dome up, flat side at \p base.
    static Envelope hemisphere(const glm::vec3& base, float radius);
    /// A Weber–Penn style solid of revolution: at height fraction t in [0, 1] above \p base the
    /// radius is radius · profile(t), linear between the given (t, relative radius) points
    /// (t increasing, from 0 to 1, relative radius in [0, 1]).
    static Envelope profile(const glm::vec3& base, float radius, float height,
                            std::vector<glm::vec2> points);
    /// The profile of one of Weber & Penn's (1995) shape ratios: conical, spherical,
    /// hemispherical, cylindrical, tapered_cylindrical, flame, inverse_conical, tend_flame.
    /// Sampled at 33 points. Throws InvalidInput naming the allowed values.
    static std::vector<glm::vec2> weberPennProfile(const std::string& name);
    /// A closed triangle mesh (indices three per triangle). Inside = odd ray-crossing parity.
    /// \param name for messages (the file name).
    static Envelope mesh(std::vector<glm::vec3> positions, std::vector<std::uint32_t> indices,
                         const std::string& name);
    // A mesh file becomes an envelope in the space-colonization node (nodes::loadEnvelopeMesh),
    // which reads it as obstacles are read.

    EnvelopeShape shape() const { return mShape; }
    bool contains(const glm::vec3& p) const;
    /// Axis-aligned bounds of the volume.
    glm::vec3 boundsMin() const { return mLo; }
    glm::vec3 boundsMax() const { return mHi; }

    /// \p count points uniformly distributed inside the volume (rejection sampling in the bounds
    /// with sylva::Rng, so the same seed gives the same points everywhere).
    /// \throw InvalidInput when the volume is empty or far too thin to sample.
    std::vector<glm::vec3> sample(std::size_t count, std::uint64_t seed) const;

private:
    Envelope() = default;
    float profileAt(float t) const;
    /// contains() and sample() for one shape (sample() tests its tries without a switch).
    template <EnvelopeShape S> bool containsAs(const glm::vec3& p) const;
    template <EnvelopeShape S>
    std::vector<glm::vec3> sampleAs(std::size_t count, std::uint64_t seed) const;

    EnvelopeShape mShape = EnvelopeShape::Sphere;
    glm::vec3 mCenter{0.0f}; ///< centre, or base centre
    glm::vec3 mRadii{1.0f};
    float mHeight = 1.0f;
    bool mInverted = false;
    std::vector<glm::vec2> mProfile;
    std::shared_ptr<const MeshVolume> mMesh;
    std::string mName;
    glm::vec3 mLo{0.0f};
    glm::vec3 mHi{0.0f};
};

/// Inside test for a closed triangle mesh: counts crossings of the ray from the point along +X.
/// Triangles are binned by their projection on the YZ plane into a 2D grid, so one test costs
/// the triangles of one cell. Points on shared edges count once (a consistent tie rule on
/// counter-clockwise-ordered projections), so the parity is watertight for closed meshes.
class MeshVolume {
public:
    MeshVolume(std::vector<glm::vec3> positions, std::vector<std::uint32_t> indices);
    bool contains(const glm::vec3& p) const;
    glm::vec3 boundsMin() const { return mLo; }
    glm::vec3 boundsMax() const { return mHi; }
    std::size_t triangleCount() const { return mIndices.size() / 3; }

private:
    std::vector<glm::vec3> mPositions;
    std::vector<std::uint32_t> mIndices;
    glm::vec3 mLo{0.0f};
    glm::vec3 mHi{0.0f};
    int mGridY = 1;
    int mGridZ = 1;
    std::vector<std::uint32_t> mCellStart; ///< CSR over mCellTriangles
    std::vector<std::uint32_t> mCellTriangles;
};

} // namespace sylva::growth
