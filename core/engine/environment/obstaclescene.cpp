#include "engine/environment/obstaclescene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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
