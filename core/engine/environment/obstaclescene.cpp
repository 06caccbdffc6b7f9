#include "engine/environment/obstaclescene.h"

#include "engine/util/closestpoint.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>

#include <embree3/rtcore.h>
#include <omp.h>

namespace sylva::env {

bool mollerTrumbore(const glm::dvec3& orig, const glm::dvec3& dir, const glm::dvec3& v0,
                    const glm::dvec3& v1, const glm::dvec3& v2, double& t, double& u, double& v) {
    const glm::dvec3 e1 = v1 - v0;
    const glm::dvec3 e2 = v2 - v0;
    const glm::dvec3 p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    // Parallel to the plane (or degenerate): a segment lying in the plane counts as a miss, as
    // it does for Embree.
    if (std::abs(det) < 1e-300) return false;
    const double inv = 1.0 / det;
    const glm::dvec3 s = orig - v0;
    u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return false;
    const glm::dvec3 q = glm::cross(s, e1);
    v = glm::dot(dir, q) * inv;
    if (v < 0.0 || u + v > 1.0) return false;
    t = glm::dot(e2, q) * inv;
    return true;
}

namespace {

/// Ericson 5.1.9: closest points of the segments p1q1 (parameter s) and p2q2 (parameter t).
double segmentSegmentDistance2(const glm::dvec3& p1, const glm::dvec3& q1, const glm::dvec3& p2,
                               const glm::dvec3& q2, double& s, double& t, glm::dvec3& c2) {
    const glm::dvec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    constexpr double eps = 1e-300;
    if (a <= eps && e <= eps) {
        s = t = 0.0;
    } else if (a <= eps) {
        s = 0.0;
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = glm::dot(d1, r);
        if (e <= eps) {
            t = 0.0;
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = glm::dot(d1, d2), denom = a * e - b * b;
            s = denom > eps ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    const glm::dvec3 c1 = p1 + d1 * s;
    c2 = p2 + d2 * t;
    const glm::dvec3 d = c1 - c2;
    return glm::dot(d, d);
}

} // namespace

double segmentTriangleDistance2(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& v0,
                                const glm::dvec3& v1, const glm::dvec3& v2, glm::dvec3& onTriangle,
                                double& t) {
    double ct, u, v;
    if (p0 != p1 && mollerTrumbore(p0, p1 - p0, v0, v1, v2, ct, u, v) && ct >= 0.0 && ct <= 1.0) {
        t = ct;
        onTriangle = (1.0 - u - v) * v0 + u * v1 + v * v2;
        return 0.0;
    }
    // Not crossing: the closest pair has an endpoint of the segment or a point of an edge.
    double best = std::numeric_limits<double>::infinity();
    const auto consider = [&](double d2, const glm::dvec3& q, double at) {
        if (d2 < best) {
            best = d2;
            onTriangle = q;
            t = at;
        }
    };
    const glm::dvec3 q0 = closestPointOnTriangle(p0, v0, v1, v2);
    consider(glm::dot(p0 - q0, p0 - q0), q0, 0.0);
    const glm::dvec3 q1 = closestPointOnTriangle(p1, v0, v1, v2);
    consider(glm::dot(p1 - q1, p1 - q1), q1, 1.0);
    const glm::dvec3* corners[3] = {&v0, &v1, &v2};
    for (int k = 0; k < 3; ++k) {
        double s, e;
        glm::dvec3 q;
        const double d2 =
            segmentSegmentDistance2(p0, p1, *corners[k], *corners[(k + 1) % 3], s, e, q);
        consider(d2, q, s);
    }
    return best;
}

namespace {

struct DeviceDeleter {
    void operator()(RTCDevice d) const { rtcReleaseDevice(d); }
};
struct SceneDeleter {
    void operator()(RTCScene s) const { rtcReleaseScene(s); }
};

bool segmentHitsBox(const glm::vec3& a, const glm::vec3& d, const glm::vec3& lo,
                    const glm::vec3& hi) {
    double t0 = 0.0, t1 = 1.0;
    for (int k = 0; k < 3; ++k) {
        const double pad = 1e-5 * (1.0 + std::abs(static_cast<double>(hi[k] - lo[k])));
        const double l = lo[k] - pad, h = hi[k] + pad;
        if (std::abs(d[k]) < 1e-30) {
            if (a[k] < l || a[k] > h) return false;
            continue;
        }
        double ta = (l - a[k]) / d[k], tb = (h - a[k]) / d[k];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

} // namespace

struct ObstacleScene::Impl {
    CollisionBackend backend = CollisionBackend::Embree;
    std::vector<ObstacleMesh> meshes;
    std::vector<std::uint32_t> geomToMesh; // Embree geometry id -> mesh index
    std::size_t triangles = 0;
    std::size_t degenerates = 0;
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{-std::numeric_limits<float>::max()};
    std::unique_ptr<RTCDeviceTy, DeviceDeleter> device;
    std::unique_ptr<RTCSceneTy, SceneDeleter> scene;

    SegmentHit bruteIntersect(const Segment& s, bool anyHit) const {
        SegmentHit best;
        const glm::vec3 d = s.b - s.a;
        if (d == glm::vec3(0.0f)) return best;
        double bestT = std::numeric_limits<double>::infinity();
        for (std::size_t m = 0; m < meshes.size(); ++m) {
            const ObstacleMesh& mesh = meshes[m];
            if (mesh.empty() || !segmentHitsBox(s.a, d, mesh.lo, mesh.hi)) continue;
            for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
                const glm::uvec3& tri = mesh.triangles[i];
                double t, u, v;
                if (!mollerTrumbore(glm::dvec3(s.a), glm::dvec3(d),
                                    glm::dvec3(mesh.vertices[tri.x]),
                                    glm::dvec3(mesh.vertices[tri.y]),
                                    glm::dvec3(mesh.vertices[tri.z]), t, u, v))
                    continue;
                if (t < 0.0 || t > 1.0 || t >= bestT) continue;
                bestT = t;
                best.hit = true;
                best.mesh = static_cast<std::uint32_t>(m);
                best.triangle = static_cast<std::uint32_t>(i);
                if (anyHit) return best;
            }
        }
        if (best.hit) {
            best.t = static_cast<float>(bestT);
            const ObstacleMesh& mesh = meshes[best.mesh];
            const glm::uvec3& tri = mesh.triangles[best.triangle];
            best.normal = glm::normalize(glm::cross(mesh.vertices[tri.y] - mesh.vertices[tri.x],
                                                    mesh.vertices[tri.z] - mesh.vertices[tri.x]));
        }
        return best;
    }

    /// The candidate triangle (mesh m, triangle i) for nearest(): keeps the closest within r.
    void considerNearest(const Segment& s, double r2, std::uint32_t m, std::uint32_t i,
                         SegmentHit& best, double& bestD2) const {
        const ObstacleMesh& mesh = meshes[m];
        const glm::uvec3& tri = mesh.triangles[i];
        glm::dvec3 q;
        double t;
        const double d2 = segmentTriangleDistance2(
            glm::dvec3(s.a), glm::dvec3(s.b), glm::dvec3(mesh.vertices[tri.x]),
            glm::dvec3(mesh.vertices[tri.y]), glm::dvec3(mesh.vertices[tri.z]), q, t);
        // Ties go to the lower (mesh, triangle): the answer does not depend on visiting order.
        if (d2 > r2 || d2 > bestD2 ||
            (d2 == bestD2 && best.hit && std::tie(m, i) > std::tie(best.mesh, best.triangle)))
            return;
        bestD2 = d2;
        best.hit = true;
        best.t = static_cast<float>(t);
        best.point = glm::vec3(q);
        best.mesh = m;
        best.triangle = i;
    }

    SegmentHit nearest(const Segment& s, float radius) const {
        SegmentHit best;
        double bestD2 = std::numeric_limits<double>::infinity();
        const double r = std::max(0.0, static_cast<double>(radius));
        const double r2 = r * r;
        const glm::vec3 pad(static_cast<float>(r) * 1.0001f + 1e-6f);
        const glm::vec3 lo = glm::min(s.a, s.b) - pad, hi = glm::max(s.a, s.b) + pad;
        if (backend == CollisionBackend::Embree && scene) {
            struct Query {
                const Impl* self;
                const Segment* s;
                double r2;
                SegmentHit* best;
                double* bestD2;
            } q{this, &s, r2, &best, &bestD2};
            const glm::vec3 mid = 0.5f * (s.a + s.b);
            RTCPointQuery pq;
            pq.x = mid.x;
            pq.y = mid.y;
            pq.z = mid.z;
            pq.time = 0.0f;
            pq.radius = 0.5f * glm::length(s.b - s.a) + pad.x;
            RTCPointQueryContext ctx;
            rtcInitPointQueryContext(&ctx);
            rtcPointQuery(
                scene.get(), &pq, &ctx,
                [](RTCPointQueryFunctionArguments* args) -> bool {
                    auto* q = static_cast<Query*>(args->userPtr);
                    q->self->considerNearest(*q->s, q->r2, q->self->geomToMesh[args->geomID],
                                             args->primID, *q->best, *q->bestD2);
                    return false;
                },
                &q);
        } else {
            for (std::size_t m = 0; m < meshes.size(); ++m) {
                const ObstacleMesh& mesh = meshes[m];
                if (mesh.empty() || !glm::all(glm::lessThanEqual(lo, mesh.hi)) ||
                    !glm::all(glm::lessThanEqual(mesh.lo, hi)))
                    continue;
                for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
                    considerNearest(s, r2, static_cast<std::uint32_t>(m),
                                    static_cast<std::uint32_t>(i), best, bestD2);
            }
        }
        if (best.hit) {
            const ObstacleMesh& mesh = meshes[best.mesh];
            const glm::uvec3& tri = mesh.triangles[best.triangle];
            const glm::vec3 n = glm::cross(mesh.vertices[tri.y] - mesh.vertices[tri.x],
                                           mesh.vertices[tri.z] - mesh.vertices[tri.x]);
            best.normal = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f);
        }
        return best;
    }

    static void initRay(RTCRay& ray, const Segment& s) {
        ray.org_x = s.a.x;
        ray.org_y = s.a.y;
        ray.org_z = s.a.z;
        ray.dir_x = s.b.x - s.a.x;
        ray.dir_y = s.b.y - s.a.y;
        ray.dir_z = s.b.z - s.a.z;
        ray.tnear = 0.0f;
        ray.tfar = 1.0f; // the direction is b - a, so t = 1 is the segment's end
        ray.time = 0.0f;
        ray.mask = 0xFFFFFFFFu;
        ray.id = 0;
        ray.flags = 0;
    }

    SegmentHit embreeIntersect(const Segment& s) const {
        SegmentHit out;
        if (s.a == s.b || !scene) return out;
        RTCRayHit rh;
        initRay(rh.ray, s);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        rtcIntersect1(scene.get(), &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return out;
        out.hit = true;
        out.t = rh.ray.tfar;
        out.mesh = geomToMesh[rh.hit.geomID];
        out.triangle = rh.hit.primID;
        out.normal = glm::normalize(glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
        return out;
    }

    bool embreeOccluded(const Segment& s) const {
        if (s.a == s.b || !scene) return false;
        RTCRay ray;
        initRay(ray, s);
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        rtcOccluded1(scene.get(), &ctx, &ray);
        return ray.tfar < 0.0f; // Embree sets tfar to -inf on a hit
    }
};

ObstacleScene::ObstacleScene() : mImpl(std::make_unique<Impl>()) {}

ObstacleScene::ObstacleScene(std::vector<ObstacleMesh> meshes, CollisionBackend backend)
    : mImpl(std::make_unique<Impl>()) {
    Impl& d = *mImpl;
    d.backend = backend;
    d.meshes = std::move(meshes);
    for (const ObstacleMesh& m : d.meshes) {
        d.triangles += m.triangleCount();
        d.degenerates += m.degenerateCount;
        if (!m.empty()) {
            d.lo = glm::min(d.lo, m.lo);
            d.hi = glm::max(d.hi, m.hi);
        }
    }
    if (backend != CollisionBackend::Embree || d.triangles == 0) return;

    d.device.reset(rtcNewDevice(nullptr));
    if (!d.device) throw std::runtime_error("cannot create the Embree device");
    d.scene.reset(rtcNewScene(d.device.get()));
    // Robust mode makes edge and vertex hits watertight, so a branch crossing a shared edge of a
    // closed mesh is never missed.
    rtcSetSceneFlags(d.scene.get(), RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(d.scene.get(), RTC_BUILD_QUALITY_HIGH);
    for (std::size_t m = 0; m < d.meshes.size(); ++m) {
        const ObstacleMesh& mesh = d.meshes[m];
        if (mesh.empty()) continue;
        RTCGeometry geom = rtcNewGeometry(d.device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
        // New (Embree-owned) buffers rather than shared ones: Embree may read 16 bytes past the
        // last vertex, which our std::vector does not guarantee to be addressable.
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                              mesh.vertices.size()));
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
            v[3 * i + 0] = mesh.vertices[i].x;
            v[3 * i + 1] = mesh.vertices[i].y;
            v[3 * i + 2] = mesh.vertices[i].z;
        }
        auto* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), mesh.triangles.size()));
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
            idx[3 * i + 0] = mesh.triangles[i].x;
            idx[3 * i + 1] = mesh.triangles[i].y;
            idx[3 * i + 2] = mesh.triangles[i].z;
        }
        rtcCommitGeometry(geom);
        const unsigned id = rtcAttachGeometry(d.scene.get(), geom);
        rtcReleaseGeometry(geom);
        if (d.geomToMesh.size() <= id) d.geomToMesh.resize(id + 1, 0);
        d.geomToMesh[id] = static_cast<std::uint32_t>(m);
    }
    rtcCommitScene(d.scene.get());
    if (rtcGetDeviceError(d.device.get()) != RTC_ERROR_NONE)
        throw std::runtime_error("Embree could not build the obstacle scene");
}

ObstacleScene::~ObstacleScene() = default;
ObstacleScene::ObstacleScene(ObstacleScene&&) noexcept = default;
ObstacleScene& ObstacleScene::operator=(ObstacleScene&&) noexcept = default;

CollisionBackend ObstacleScene::backend() const {
    return mImpl->backend;
}
const std::vector<ObstacleMesh>& ObstacleScene::meshes() const {
    return mImpl->meshes;
}
std::size_t ObstacleScene::triangleCount() const {
    return mImpl->triangles;
}
std::size_t ObstacleScene::degenerateCount() const {
    return mImpl->degenerates;
}
glm::vec3 ObstacleScene::lo() const {
    return mImpl->lo;
}
glm::vec3 ObstacleScene::hi() const {
    return mImpl->hi;
}

bool ObstacleScene::overlapsBounds(const glm::vec3& lo, const glm::vec3& hi) const {
    for (const ObstacleMesh& m : mImpl->meshes)
        if (!m.empty() && glm::all(glm::lessThanEqual(lo, m.hi)) &&
            glm::all(glm::lessThanEqual(m.lo, hi)))
            return true;
    return false;
}

SegmentHit ObstacleScene::intersect(const Segment& s) const {
    SegmentHit h = mImpl->backend == CollisionBackend::Embree ? mImpl->embreeIntersect(s)
                                                              : mImpl->bruteIntersect(s, false);
    if (h.hit) h.point = s.a + h.t * (s.b - s.a);
    return h;
}

bool ObstacleScene::occluded(const Segment& s) const {
    return mImpl->backend == CollisionBackend::Embree ? mImpl->embreeOccluded(s)
                                                      : mImpl->bruteIntersect(s, true).hit;
}

SegmentHit ObstacleScene::nearest(const Segment& s, float radius) const {
    return mImpl->nearest(s, radius);
}

bool ObstacleScene::touches(const Segment& s, float radius) const {
    if (occluded(s)) return true;
    return radius > 0.0f && nearest(s, radius).hit;
}

void ObstacleScene::touches(std::span<const Segment> segments, std::span<const float> radii,
                            std::span<std::uint8_t> out) const {
    if (out.size() != segments.size() || radii.size() != segments.size())
        throw std::invalid_argument("ObstacleScene::touches: sizes differ");
    const auto n = static_cast<std::ptrdiff_t>(segments.size());
#pragma omp parallel for schedule(static) if (n > 1024 && !omp_in_parallel())
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        out[k] = touches(segments[k], radii[k]) ? 1 : 0;
    }
}

void ObstacleScene::intersect(std::span<const Segment> segments, std::span<SegmentHit> out) const {
    if (out.size() != segments.size())
        throw std::invalid_argument("ObstacleScene::intersect: output size differs");
    const auto n = static_cast<std::ptrdiff_t>(segments.size());
#pragma omp parallel for schedule(static) if (n > 1024 && !omp_in_parallel())
    for (std::ptrdiff_t i = 0; i < n; ++i)
        out[static_cast<std::size_t>(i)] = intersect(segments[static_cast<std::size_t>(i)]);
}

void ObstacleScene::occluded(std::span<const Segment> segments, std::span<std::uint8_t> out) const {
    if (out.size() != segments.size())
        throw std::invalid_argument("ObstacleScene::occluded: output size differs");
    const auto n = static_cast<std::ptrdiff_t>(segments.size());
#pragma omp parallel for schedule(static) if (n > 1024 && !omp_in_parallel())
    for (std::ptrdiff_t i = 0; i < n; ++i)
        out[static_cast<std::size_t>(i)] = occluded(segments[static_cast<std::size_t>(i)]) ? 1 : 0;
}

void ObstacleScene::triangle(std::uint32_t mesh, std::uint32_t tri, glm::vec3& v0, glm::vec3& v1,
                             glm::vec3& v2) const {
    const ObstacleMesh& m = mImpl->meshes.at(mesh);
    const glm::uvec3& t = m.triangles.at(tri);
    v0 = m.vertices[t.x];
    v1 = m.vertices[t.y];
    v2 = m.vertices[t.z];
}

} // namespace sylva::env
