#include "engine/growth/envelope.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

namespace sylva::growth {

namespace {

void requirePositive(const char* name, float v) {
    if (!std::isfinite(v) || !(v > 0.0f))
        throw InvalidInput(std::string("envelope ") + name +
                           " must be a positive finite number, got " + std::to_string(v));
}

void requireFinite(const char* name, const glm::vec3& v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw InvalidInput(std::string("envelope ") + name + " must be finite");
}

float horizontal2(const glm::vec3& d) {
    return d.x * d.x + d.z * d.z;
}

} // namespace

EnvelopeShape envelopeShapeFromName(const std::string& name) {
    static const std::pair<const char*, EnvelopeShape> kNames[] = {
        {"sphere", EnvelopeShape::Sphere},
        {"ellipsoid", EnvelopeShape::Ellipsoid},
        {"cone", EnvelopeShape::Cone},
        {"cylinder", EnvelopeShape::Cylinder},
        {"hemisphere", EnvelopeShape::Hemisphere},
        {"profile", EnvelopeShape::Profile},
        {"mesh", EnvelopeShape::Mesh}};
    for (const auto& [n, s] : kNames)
        if (name == n) return s;
    throw InvalidInput("envelope shape must be one of sphere, ellipsoid, cone, cylinder, "
                       "hemisphere, profile, mesh; got '" +
                       name + "'");
}

const char* envelopeShapeName(EnvelopeShape shape) {
    switch (shape) {
    case EnvelopeShape::Sphere:
        return "sphere";
    case EnvelopeShape::Ellipsoid:
        return "ellipsoid";
    case EnvelopeShape::Cone:
        return "cone";
    case EnvelopeShape::Cylinder:
        return "cylinder";
    case EnvelopeShape::Hemisphere:
        return "hemisphere";
    case EnvelopeShape::Profile:
        return "profile";
    case EnvelopeShape::Mesh:
        return "mesh";
    }
    return "?";
}

Envelope Envelope::sphere(const glm::vec3& center, float radius) {
    requireFinite("center", center);
    requirePositive("radius", radius);
    Envelope e;
    e.mShape = EnvelopeShape::Sphere;
    e.mCenter = center;
    e.mRadii = glm::vec3(radius);
    e.mLo = center - glm::vec3(radius);
    e.mHi = center + glm::vec3(radius);
    return e;
}

Envelope Envelope::ellipsoid(const glm::vec3& center, const glm::vec3& radii) {
    requireFinite("center", center);
    requirePositive("radii[0]", radii.x);
    requirePositive("radii[1]", radii.y);
    requirePositive("radii[2]", radii.z);
    Envelope e;
    e.mShape = EnvelopeShape::Ellipsoid;
    e.mCenter = center;
    e.mRadii = radii;
    e.mLo = center - radii;
    e.mHi = center + radii;
    return e;
}

Envelope Envelope::cone(const glm::vec3& base, float radius, float height, bool inverted) {
    requireFinite("center", base);
    requirePositive("radius", radius);
    requirePositive("height", height);
    Envelope e;
    e.mShape = EnvelopeShape::Cone;
    e.mCenter = base;
    e.mRadii = glm::vec3(radius);
    e.mHeight = height;
    e.mInverted = inverted;
    e.mLo = base - glm::vec3(radius, 0, radius);
    e.mHi = base + glm::vec3(radius, height, radius);
    return e;
}

Envelope Envelope::cylinder(const glm::vec3& base, float radius, float height) {
    Envelope e = cone(base, radius, height);
    e.mShape = EnvelopeShape::Cylinder;
    return e;
}

Envelope Envelope::hemisphere(const glm::vec3& base, float radius) {
    Envelope e = cone(base, radius, radius);
    e.mShape = EnvelopeShape::Hemisphere;
    return e;
}

Envelope Envelope::profile(const glm::vec3& base, float radius, float height,
                           std::vector<glm::vec2> points) {
    Envelope e = cone(base, radius, height);
    e.mShape = EnvelopeShape::Profile;
    if (points.size() < 2)
        throw InvalidInput("envelope profile needs at least 2 [t, radius] points");
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::vec2 p = points[i];
        if (!(p.x >= 0.0f && p.x <= 1.0f) || !(p.y >= 0.0f && p.y <= 1.0f))
            throw InvalidInput("envelope profile point " + std::to_string(i) +
                               " must have t and radius in [0, 1]");
        if (i > 0 && !(p.x > points[i - 1].x))
            throw InvalidInput("envelope profile points must have strictly increasing t");
    }
    if (points.front().x != 0.0f || points.back().x != 1.0f)
        throw InvalidInput("envelope profile must start at t = 0 and end at t = 1");
    e.mProfile = std::move(points);
    return e;
}

std::vector<glm::vec2> Envelope::weberPennProfile(const std::string& name) {
    static const char* const kNames[] = {"conical",         "spherical",           "hemispherical",
                                         "cylindrical",     "tapered_cylindrical", "flame",
                                         "inverse_conical", "tend_flame"};
    int shape = -1;
    for (int i = 0; i < 8; ++i)
        if (name == kNames[i]) shape = i;
    if (shape < 0)
        throw InvalidInput("envelope profile must be a list of [t, radius] points or one of "
                           "conical, spherical, hemispherical, cylindrical, tapered_cylindrical, "
                           "flame, inverse_conical, tend_flame; got '" +
                           name + "'");
    // Weber & Penn's ShapeRatio takes the distance from the top (1 at the base of the crown).
    auto ratio = [shape](double r) -> double {
        switch (shape) {
        case 0:
            return 0.2 + 0.8 * r;
        case 1:
            return 0.2 + 0.8 * std::sin(std::numbers::pi * r);
        case 2:
            return 0.2 + 0.8 * std::sin(0.5 * std::numbers::pi * r);
        case 3:
            return 1.0;
        case 4:
            return 0.5 + 0.5 * r;
        case 5:
            return r <= 0.7 ? r / 0.7 : (1.0 - r) / 0.3;
        case 6:
            return 1.0 - 0.8 * r;
        default:
            return r <= 0.7 ? 0.5 + 0.5 * r / 0.7 : 0.5 + 0.5 * (1.0 - r) / 0.3;
        }
    };
    std::vector<glm::vec2> points;
    for (int i = 0; i <= 32; ++i) {
        const double t = i / 32.0;
        points.emplace_back(static_cast<float>(t),
                            static_cast<float>(std::clamp(ratio(1.0 - t), 0.0, 1.0)));
    }
    return points;
}

Envelope Envelope::mesh(std::vector<glm::vec3> positions, std::vector<std::uint32_t> indices,
                        const std::string& name) {
    if (indices.empty() || indices.size() % 3 != 0)
        throw InvalidInput("envelope mesh '" + name + "' has no triangles");
    for (std::uint32_t i : indices)
        if (i >= positions.size())
            throw InvalidInput("envelope mesh '" + name + "' has an index out of range");
    for (const glm::vec3& p : positions)
        requireFinite("mesh vertex", p);
    Envelope e;
    e.mShape = EnvelopeShape::Mesh;
    e.mName = name;
    auto volume = std::make_shared<MeshVolume>(std::move(positions), std::move(indices));
    e.mLo = volume->boundsMin();
    e.mHi = volume->boundsMax();
    e.mMesh = std::move(volume);
    return e;
}

float Envelope::profileAt(float t) const {
    if (t <= mProfile.front().x) return mProfile.front().y;
    for (std::size_t i = 1; i < mProfile.size(); ++i)
        if (t <= mProfile[i].x) {
            const glm::vec2 a = mProfile[i - 1];
            const glm::vec2 b = mProfile[i];
            return a.y + (b.y - a.y) * (t - a.x) / (b.x - a.x);
        }
    return mProfile.back().y;
}

template <EnvelopeShape S> bool Envelope::containsAs(const glm::vec3& p) const {
    const glm::vec3 d = p - mCenter;
    if constexpr (S == EnvelopeShape::Sphere) {
        return glm::dot(d, d) <= mRadii.x * mRadii.x;
    } else if constexpr (S == EnvelopeShape::Ellipsoid) {
        const glm::vec3 q = d / mRadii;
        return glm::dot(q, q) <= 1.0f;
    } else if constexpr (S == EnvelopeShape::Cone) {
        if (d.y < 0.0f || d.y > mHeight) return false;
        const float t = d.y / mHeight;
        const float r = mRadii.x * (mInverted ? t : 1.0f - t);
        return horizontal2(d) <= r * r;
    } else if constexpr (S == EnvelopeShape::Cylinder) {
        return d.y >= 0.0f && d.y <= mHeight && horizontal2(d) <= mRadii.x * mRadii.x;
    } else if constexpr (S == EnvelopeShape::Hemisphere) {
        return d.y >= 0.0f && glm::dot(d, d) <= mRadii.x * mRadii.x;
    } else if constexpr (S == EnvelopeShape::Profile) {
        if (d.y < 0.0f || d.y > mHeight) return false;
        const float r = mRadii.x * profileAt(d.y / mHeight);
        return horizontal2(d) <= r * r;
    } else {
        return mMesh->contains(p);
    }
}

bool Envelope::contains(const glm::vec3& p) const {
    switch (mShape) {
    case EnvelopeShape::Sphere:
        return containsAs<EnvelopeShape::Sphere>(p);
    case EnvelopeShape::Ellipsoid:
        return containsAs<EnvelopeShape::Ellipsoid>(p);
    case EnvelopeShape::Cone:
        return containsAs<EnvelopeShape::Cone>(p);
    case EnvelopeShape::Cylinder:
        return containsAs<EnvelopeShape::Cylinder>(p);
    case EnvelopeShape::Hemisphere:
        return containsAs<EnvelopeShape::Hemisphere>(p);
    case EnvelopeShape::Profile:
        return containsAs<EnvelopeShape::Profile>(p);
    case EnvelopeShape::Mesh:
        return containsAs<EnvelopeShape::Mesh>(p);
    }
    return false;
}

std::vector<glm::vec3> Envelope::sample(std::size_t count, std::uint64_t seed) const {
    switch (mShape) {
    case EnvelopeShape::Sphere:
        return sampleAs<EnvelopeShape::Sphere>(count, seed);
    case EnvelopeShape::Ellipsoid:
        return sampleAs<EnvelopeShape::Ellipsoid>(count, seed);
    case EnvelopeShape::Cone:
        return sampleAs<EnvelopeShape::Cone>(count, seed);
    case EnvelopeShape::Cylinder:
        return sampleAs<EnvelopeShape::Cylinder>(count, seed);
    case EnvelopeShape::Hemisphere:
        return sampleAs<EnvelopeShape::Hemisphere>(count, seed);
    case EnvelopeShape::Profile:
        return sampleAs<EnvelopeShape::Profile>(count, seed);
    case EnvelopeShape::Mesh:
        return sampleAs<EnvelopeShape::Mesh>(count, seed);
    }
    return {};
}

template <EnvelopeShape S>
std::vector<glm::vec3> Envelope::sampleAs(std::size_t count, std::uint64_t seed) const {
    // The shape's test inlined into the loop, and every try written at the end of the points
    // (kept by advancing the count when inside): about half the tries land outside a sphere,
    // a branch on that would be mispredicted every other try.
    std::vector<glm::vec3> points(count + 1);
    Rng rng(mixSeed(seed, salt::kEnvelope));
    // Generous: a sphere fills 52% of its box, a thin cone or mesh far less.
    const std::size_t maxTries = 1000 * count + 100000;
    const glm::dvec3 lo(mLo);
    const glm::dvec3 ext = glm::dvec3(mHi) - lo;
    std::size_t n = 0;
    for (std::size_t tries = 0; n < count; ++tries) {
        if (tries >= maxTries)
            throw InvalidInput(std::string("envelope ") + envelopeShapeName(mShape) +
                               (mName.empty() ? "" : " '" + mName + "'") +
                               " encloses too little volume to place attraction points"
                               " (is the mesh closed? is the profile all zeros?)");
        const double x = lo.x + ext.x * rng.uniform();
        const double y = lo.y + ext.y * rng.uniform();
        const double z = lo.z + ext.z * rng.uniform();
        const glm::vec3 p(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
        points[n] = p;
        n += containsAs<S>(p) ? 1 : 0;
    }
    points.resize(count);
    return points;
}

// ---------------------------------------------------------------------------------------------

namespace {

// Twice the signed area of (a, b, p) in the YZ plane.
double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// A point exactly on an edge belongs to one side only: the rule differs for d and -d, and a
// shared edge of a closed mesh appears in both directions once the triangles are CCW.
bool ownsEdge(const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 d = b - a;
    return d.y > 0.0 || (d.y == 0.0 && d.x > 0.0);
}

} // namespace

MeshVolume::MeshVolume(std::vector<glm::vec3> positions, std::vector<std::uint32_t> indices)
    : mPositions(std::move(positions)), mIndices(std::move(indices)) {
    mLo = mHi = mPositions[mIndices[0]];
    for (std::uint32_t i : mIndices) {
        mLo = glm::min(mLo, mPositions[i]);
        mHi = glm::max(mHi, mPositions[i]);
    }
    const std::size_t tris = mIndices.size() / 3;
    const int g = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(tris))), 1, 256);
    mGridY = mGridZ = g;
    const double sy = (mHi.y - mLo.y) > 0 ? g / static_cast<double>(mHi.y - mLo.y) : 0.0;
    const double sz = (mHi.z - mLo.z) > 0 ? g / static_cast<double>(mHi.z - mLo.z) : 0.0;
    auto cellRange = [&](std::size_t t, int& y0, int& y1, int& z0, int& z1) {
        double ylo = 1e300, yhi = -1e300, zlo = 1e300, zhi = -1e300;
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& p = mPositions[mIndices[3 * t + static_cast<std::size_t>(k)]];
            ylo = std::min(ylo, double(p.y));
            yhi = std::max(yhi, double(p.y));
            zlo = std::min(zlo, double(p.z));
            zhi = std::max(zhi, double(p.z));
        }
        y0 = std::clamp(static_cast<int>((ylo - mLo.y) * sy), 0, g - 1);
        y1 = std::clamp(static_cast<int>((yhi - mLo.y) * sy), 0, g - 1);
        z0 = std::clamp(static_cast<int>((zlo - mLo.z) * sz), 0, g - 1);
        z1 = std::clamp(static_cast<int>((zhi - mLo.z) * sz), 0, g - 1);
    };
    mCellStart.assign(static_cast<std::size_t>(g * g) + 1, 0);
    for (std::size_t t = 0; t < tris; ++t) {
        int y0, y1, z0, z1;
        cellRange(t, y0, y1, z0, z1);
        for (int z = z0; z <= z1; ++z)
            for (int y = y0; y <= y1; ++y)
                ++mCellStart[static_cast<std::size_t>(z * g + y) + 1];
    }
    for (std::size_t c = 0; c + 1 < mCellStart.size(); ++c)
        mCellStart[c + 1] += mCellStart[c];
    mCellTriangles.resize(mCellStart.back());
    std::vector<std::uint32_t> fill(mCellStart.begin(), mCellStart.end() - 1);
    for (std::size_t t = 0; t < tris; ++t) {
        int y0, y1, z0, z1;
        cellRange(t, y0, y1, z0, z1);
        for (int z = z0; z <= z1; ++z)
            for (int y = y0; y <= y1; ++y)
                mCellTriangles[fill[static_cast<std::size_t>(z * g + y)]++] =
                    static_cast<std::uint32_t>(t);
    }
}

bool MeshVolume::contains(const glm::vec3& p) const {
    if (p.x < mLo.x || p.x > mHi.x || p.y < mLo.y || p.y > mHi.y || p.z < mLo.z || p.z > mHi.z)
        return false;
    const int g = mGridY;
    const double sy = (mHi.y - mLo.y) > 0 ? g / static_cast<double>(mHi.y - mLo.y) : 0.0;
    const double sz = (mHi.z - mLo.z) > 0 ? g / static_cast<double>(mHi.z - mLo.z) : 0.0;
    const int cy = std::clamp(static_cast<int>((double(p.y) - mLo.y) * sy), 0, g - 1);
    const int cz = std::clamp(static_cast<int>((double(p.z) - mLo.z) * sz), 0, mGridZ - 1);
    const std::size_t cell = static_cast<std::size_t>(cz * g + cy);
    const glm::dvec2 q(p.y, p.z);
    int crossings = 0;
    for (std::uint32_t k = mCellStart[cell]; k < mCellStart[cell + 1]; ++k) {
        const std::size_t t = mCellTriangles[k];
        glm::dvec3 v[3];
        for (int j = 0; j < 3; ++j)
            v[j] = glm::dvec3(mPositions[mIndices[3 * t + std::size_t(j)]]);
        glm::dvec2 a(v[0].y, v[0].z), b(v[1].y, v[1].z), c(v[2].y, v[2].z);
        double area = edge(a, b, c);
        if (area == 0.0) continue; // parallel to the ray: its neighbours decide
        if (area < 0.0) {
            std::swap(b, c);
            std::swap(v[1], v[2]);
            area = -area;
        }
        const double wa = edge(b, c, q);
        const double wb = edge(c, a, q);
        const double wc = edge(a, b, q);
        if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
        if ((wa == 0.0 && !ownsEdge(b, c)) || (wb == 0.0 && !ownsEdge(c, a)) ||
            (wc == 0.0 && !ownsEdge(a, b)))
            continue;
        const double x = (wa * v[0].x + wb * v[1].x + wc * v[2].x) / area;
        if (x > p.x) ++crossings;
    }
    return (crossings & 1) != 0;
}

} // namespace sylva::growth
