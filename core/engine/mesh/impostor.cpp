#include "engine/mesh/impostor.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <vector>

#include "engine/mesh/raster.h"
#include "engine/util/error.h"

namespace sylva::mesh {

namespace {

std::uint8_t toByte(float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

glm::vec4 texel(const Image& image, int x, int y) {
    const std::uint8_t* p = image.at(x, y);
    return {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, p[3] / 255.0f};
}

/// Nearest texel, wrapping (bark v runs past 1 along a branch).
glm::vec4 sampleWrapped(const Image& image, glm::vec2 uv) {
    const float u = uv.x - std::floor(uv.x), v = uv.y - std::floor(uv.y);
    const int x = std::min(image.width - 1, static_cast<int>(u * static_cast<float>(image.width)));
    const int y =
        std::min(image.height - 1, static_cast<int>(v * static_cast<float>(image.height)));
    return texel(image, x, y);
}

/// Which submesh each triangle belongs to (-1: none, drawn as bark).
std::vector<int> triangleSubmeshes(const Mesh& mesh) {
    std::vector<int> of(mesh.triangleCount(), -1);
    for (std::size_t s = 0; s < mesh.submeshes.size(); ++s) {
        const Submesh& sm = mesh.submeshes[s];
        for (std::uint32_t t = sm.firstIndex / 3;
             t < (sm.firstIndex + sm.indexCount) / 3 && t < of.size(); ++t)
            of[t] = static_cast<int>(s);
    }
    return of;
}

/// Fills the colour (and normal, depth) of empty texels of the cell at (x0, y0) from covered
/// neighbours, ring by ring, so that bilinear filtering and mipmaps do not pull in black.
void bleed(Image& color, Image* normal, Image* depth, int x0, int y0, int size, int passes) {
    std::vector<std::uint8_t> known(static_cast<std::size_t>(size) * size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            known[static_cast<std::size_t>(y) * size + x] = color.at(x0 + x, y0 + y)[3] > 0;
    std::vector<std::uint8_t> next = known;
    for (int pass = 0; pass < passes; ++pass) {
        bool any = false;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                if (known[static_cast<std::size_t>(y) * size + x]) continue;
                int n = 0;
                int c[3] = {0, 0, 0}, nn[3] = {0, 0, 0}, d = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int xx = x + dx, yy = y + dy;
                        if (xx < 0 || yy < 0 || xx >= size || yy >= size) continue;
                        if (!known[static_cast<std::size_t>(yy) * size + xx]) continue;
                        ++n;
                        const std::uint8_t* p = color.at(x0 + xx, y0 + yy);
                        for (int k = 0; k < 3; ++k)
                            c[k] += p[k];
                        if (normal) {
                            const std::uint8_t* q = normal->at(x0 + xx, y0 + yy);
                            for (int k = 0; k < 3; ++k)
                                nn[k] += q[k];
                        }
                        if (depth) d += depth->at(x0 + xx, y0 + yy)[0];
                    }
                if (n == 0) continue;
                any = true;
                next[static_cast<std::size_t>(y) * size + x] = 1;
                std::uint8_t* p = color.at(x0 + x, y0 + y);
                for (int k = 0; k < 3; ++k)
                    p[k] = static_cast<std::uint8_t>(c[k] / n);
                if (normal) {
                    std::uint8_t* q = normal->at(x0 + x, y0 + y);
                    for (int k = 0; k < 3; ++k)
                        q[k] = static_cast<std::uint8_t>(nn[k] / n);
                }
                if (depth) depth->at(x0 + x, y0 + y)[0] = static_cast<std::uint8_t>(d / n);
            }
        known = next;
        if (!any) break;
    }
    // What the passes did not reach takes the cell's mean colour (far mipmaps average it in).
    long long sum[3] = {0, 0, 0}, count = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            if (color.at(x0 + x, y0 + y)[3] > 0) {
                for (int k = 0; k < 3; ++k)
                    sum[k] += color.at(x0 + x, y0 + y)[k];
                ++count;
            }
    if (count == 0) return;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (known[static_cast<std::size_t>(y) * size + x]) continue;
            std::uint8_t* p = color.at(x0 + x, y0 + y);
            for (int k = 0; k < 3; ++k)
                p[k] = static_cast<std::uint8_t>(sum[k] / count);
        }
}

} // namespace

ImpostorTextures::ImpostorTextures(std::filesystem::path shippedDir)
    : mState(std::make_shared<State>()) {
    mState->shipped = std::move(shippedDir);
}

ImpostorMaterial ImpostorTextures::operator()(const Submesh& submesh) const {
    const bool leaf = submesh.material == "leaf";
    ImpostorMaterial m;
    // The colours the exporters use without a texture (materials.cpp), as sRGB.
    m.colour = leaf ? glm::vec3(0.33f, 0.55f, 0.24f) : glm::vec3(0.45f, 0.36f, 0.27f);
    m.alphaTest = leaf;
    std::filesystem::path file = submesh.texture;
    if (file.empty() && !mState->shipped.empty())
        file = mState->shipped / (leaf ? "leaf.png" : "bark.png");
    if (file.empty()) return m;
    const std::lock_guard lock(mState->mutex);
    auto it = mState->images.find(file.string());
    if (it == mState->images.end()) {
        std::shared_ptr<const Image> image;
        try {
            image = std::make_shared<const Image>(readPng(file));
        } catch (const IoError&) {
            // A missing texture is drawn in the material's colour, as the exporters do.
        }
        it = mState->images.emplace(file.string(), image).first;
    }
    m.texture = it->second.get();
    return m;
}

void validateImpostor(const ImpostorSettings& s) {
    requireRange("impostor grid", s.grid, 2, 32);
    requireRange("impostor cell pixels", s.cellPixels, 8, 2048);
    requireRange("impostor supersample", s.supersample, 1, 4);
}

glm::vec3 impostorViewDirection(glm::vec2 uv, bool hemisphere) {
    const glm::vec2 p = glm::clamp(uv, 0.0f, 1.0f) * 2.0f - 1.0f;
    glm::vec3 d;
    if (hemisphere) {
        // The octahedron's upper half turned 45 degrees so that it fills the square.
        const float x = 0.5f * (p.x + p.y), z = 0.5f * (p.x - p.y);
        d = {x, 1.0f - std::abs(x) - std::abs(z), z};
    } else {
        float x = p.x, z = p.y;
        const float y = 1.0f - std::abs(x) - std::abs(z);
        if (y < 0.0f) {
            const float ox = x;
            x = (1.0f - std::abs(z)) * (ox < 0.0f ? -1.0f : 1.0f);
            z = (1.0f - std::abs(ox)) * (z < 0.0f ? -1.0f : 1.0f);
        }
        d = {x, y, z};
    }
    return glm::normalize(d);
}

glm::vec2 impostorAtlasCoord(glm::vec3 d, bool hemisphere) {
    if (hemisphere) d.y = std::max(d.y, 0.0f);
    const float s = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
    if (!(s > 0.0f)) return {0.5f, 0.5f};
    d /= s;
    glm::vec2 p;
    if (hemisphere) {
        p = {d.x + d.z, d.x - d.z};
    } else {
        p = {d.x, d.z};
        if (d.y < 0.0f)
            p = {(1.0f - std::abs(d.z)) * (d.x < 0.0f ? -1.0f : 1.0f),
                 (1.0f - std::abs(d.x)) * (d.z < 0.0f ? -1.0f : 1.0f)};
    }
    return glm::clamp(p * 0.5f + 0.5f, 0.0f, 1.0f);
}

void impostorViewBasis(const glm::vec3& direction, glm::vec3& right, glm::vec3& up) {
    const glm::vec3 hint =
        std::abs(direction.y) > 0.9999f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    right = glm::normalize(glm::cross(hint, direction));
    up = glm::cross(direction, right);
}

Mesh impostorCard(const Impostor& imp) {
    const int n = imp.settings.grid;
    const glm::vec2 cell = glm::round(impostorAtlasCoord({0, 0, 1}, imp.settings.hemisphere) *
                                      static_cast<float>(n - 1));
    const float du = 1.0f / static_cast<float>(n);
    const float u0 = cell.x * du, u1 = u0 + du;
    // Row j spans [j, j + 1] / n from the image's top: bottom-left origin flips it.
    const float v1 = 1.0f - cell.y * du, v0 = v1 - du;
    const float r = imp.radius;
    Mesh m;
    m.positions = {imp.centre + glm::vec3(-r, -r, 0), imp.centre + glm::vec3(r, -r, 0),
                   imp.centre + glm::vec3(r, r, 0), imp.centre + glm::vec3(-r, r, 0)};
    m.normals.assign(4, glm::vec3(0, 0, 1));
    m.uvs = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
    m.indices = {0, 1, 2, 0, 2, 3};
    m.submeshes.push_back({"impostor", 0, 6});
    return m;
}

float verticalExtent(const Mesh& mesh) {
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    for (const glm::vec3& p : mesh.positions) {
        lo = std::min(lo, p.y);
        hi = std::max(hi, p.y);
    }
    return hi > lo ? hi - lo : 0.0f;
}

void boundingSphere(const Mesh& mesh, glm::vec3& centre, float& radius) {
    if (mesh.positions.empty()) {
        centre = glm::vec3(0.0f);
        radius = 1.0f;
        return;
    }
    glm::vec3 lo(mesh.positions[0]), hi(mesh.positions[0]);
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    centre = 0.5f * (lo + hi);
    float r2 = 0.0f;
    for (const glm::vec3& p : mesh.positions) {
        const glm::vec3 d = p - centre;
        r2 = std::max(r2, glm::dot(d, d));
    }
    radius = std::max(std::sqrt(r2), 1e-4f);
}

Image renderOrthographicView(const Mesh& mesh, const ImpostorMaterials& materials,
                             const glm::vec3& direction, const glm::vec3& centre, float radius,
                             int pixels, int supersample, Image* normal, Image* depth) {
    const glm::vec3 view = glm::normalize(direction);
    glm::vec3 right, up;
    impostorViewBasis(view, right, up);
    const int n = pixels * supersample;
    const float scale = 0.5f * static_cast<float>(n) / radius;
    // Samples: nearest surface (largest dot with the view), its albedo, normal and depth.
    std::vector<float> z(static_cast<std::size_t>(n) * n, -1e30f);
    std::vector<glm::vec4> albedo(static_cast<std::size_t>(n) * n, glm::vec4(0.0f));
    std::vector<glm::vec3> nrm(normal ? static_cast<std::size_t>(n) * n : 0, glm::vec3(0.0f));
    std::vector<glm::vec3> screen(mesh.positions.size());
    for (std::size_t i = 0; i < screen.size(); ++i) {
        const glm::vec3 d = mesh.positions[i] - centre;
        screen[i] = {(glm::dot(d, right) + radius) * scale, (radius - glm::dot(d, up)) * scale,
                     glm::dot(d, view)};
    }
    const std::vector<int> submeshOf = triangleSubmeshes(mesh);
    std::vector<ImpostorMaterial> mats(mesh.submeshes.size() + 1);
    Submesh bark;
    bark.material = "bark";
    mats.back() = materials ? materials(bark) : ImpostorMaterial{};
    for (std::size_t s = 0; s < mesh.submeshes.size(); ++s)
        mats[s] = materials ? materials(mesh.submeshes[s]) : ImpostorMaterial{};
    const bool hasUv = mesh.uvs.size() == mesh.positions.size();
    const bool hasNormals = mesh.normals.size() == mesh.positions.size();
    // The leaf tints (Mesh::colors, linear multipliers) applied to the texture's sRGB values:
    // a linear factor f is f^(1/2.2) there, so the impostor shows the cards' variation.
    const bool hasColors = mesh.colors.size() == mesh.positions.size();
    std::vector<glm::vec3> tint(hasColors ? mesh.positions.size() : 0);
    if (hasColors) {
        float factor[256];
        for (int i = 0; i < 256; ++i)
            factor[i] = std::pow(static_cast<float>(i) / 255.0f, 1.0f / 2.2f);
        for (std::size_t i = 0; i < tint.size(); ++i)
            tint[i] = {factor[mesh.colors[i].x], factor[mesh.colors[i].y],
                       factor[mesh.colors[i].z]};
    }
    for (std::size_t t = 0; t < submeshOf.size(); ++t) {
        const std::uint32_t ia = mesh.indices[3 * t], ib = mesh.indices[3 * t + 1],
                            ic = mesh.indices[3 * t + 2];
        const ImpostorMaterial& m =
            mats[submeshOf[t] < 0 ? mats.size() - 1 : static_cast<std::size_t>(submeshOf[t])];
        const glm::vec3 faceNormal = glm::cross(mesh.positions[ib] - mesh.positions[ia],
                                                mesh.positions[ic] - mesh.positions[ia]);
        rasterizeTriangle(
            screen[ia], screen[ib], screen[ic], n, n,
            [&](int x, int y, float w0, float w1, float w2) {
                const std::size_t k = static_cast<std::size_t>(y) * n + x;
                const float d = w0 * screen[ia].z + w1 * screen[ib].z + w2 * screen[ic].z;
                if (d <= z[k]) return;
                glm::vec4 c(m.colour, 1.0f);
                if (m.texture && hasUv) {
                    const glm::vec2 uv = w0 * mesh.uvs[ia] + w1 * mesh.uvs[ib] + w2 * mesh.uvs[ic];
                    c = sampleWrapped(*m.texture, uv);
                    if (m.alphaTest && c.w < 0.5f) return;
                }
                if (hasColors) {
                    const glm::vec3 f = w0 * tint[ia] + w1 * tint[ib] + w2 * tint[ic];
                    c = glm::vec4(glm::vec3(c) * f, c.w);
                }
                z[k] = d;
                albedo[k] = glm::vec4(glm::vec3(c), 1.0f);
                if (normal) {
                    glm::vec3 nv = hasNormals ? w0 * mesh.normals[ia] + w1 * mesh.normals[ib] +
                                                    w2 * mesh.normals[ic]
                                              : faceNormal;
                    // Cards are seen from both sides: the normal faces the viewer.
                    if (glm::dot(nv, view) < 0.0f) nv = -nv;
                    nrm[k] = nv;
                }
            });
    }
    Image color(pixels, pixels, 4);
    if (normal) *normal = Image(pixels, pixels, 3);
    if (depth) *depth = Image(pixels, pixels, 1);
    const float inv = 1.0f / static_cast<float>(supersample * supersample);
    for (int y = 0; y < pixels; ++y)
        for (int x = 0; x < pixels; ++x) {
            glm::vec3 c(0.0f), nv(0.0f);
            float covered = 0.0f, dz = 0.0f;
            for (int sy = 0; sy < supersample; ++sy)
                for (int sx = 0; sx < supersample; ++sx) {
                    const std::size_t k =
                        static_cast<std::size_t>(y * supersample + sy) * n + x * supersample + sx;
                    if (albedo[k].w == 0.0f) continue;
                    covered += 1.0f;
                    c += glm::vec3(albedo[k]);
                    dz += z[k];
                    if (normal) nv += glm::normalize(nrm[k]);
                }
            std::uint8_t* p = color.at(x, y);
            if (covered > 0.0f) {
                c /= covered;
                for (int k = 0; k < 3; ++k)
                    p[k] = toByte(c[k]);
            }
            p[3] = toByte(covered * inv);
            if (normal) {
                const glm::vec3 u =
                    covered > 0.0f && glm::dot(nv, nv) > 0.0f ? glm::normalize(nv) : view;
                std::uint8_t* q = normal->at(x, y);
                for (int k = 0; k < 3; ++k)
                    q[k] = toByte(u[k] * 0.5f + 0.5f);
            }
            if (depth)
                depth->at(x, y)[0] =
                    toByte(covered > 0.0f ? 0.5f + 0.5f * dz / covered / radius : 0.5f);
        }
    return color;
}

Impostor bakeImpostor(const Mesh& mesh, const ImpostorMaterials& materials,
                      const ImpostorSettings& settings, Progress& progress) {
    validateImpostor(settings);
    if (mesh.triangleCount() == 0) throw InvalidInput("cannot bake an impostor of an empty mesh");
    Impostor imp;
    imp.settings = settings;
    boundingSphere(mesh, imp.centre, imp.radius);
    const int n = settings.grid, cell = settings.cellPixels, size = n * cell;
    imp.color = Image(size, size, 4);
    imp.normal = Image(size, size, 3);
    imp.depth = Image(size, size, 1);
    std::atomic<bool> cancelled{false};
    std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, 1)
    for (int v = 0; v < n * n; ++v) {
        if (cancelled.load()) continue;
        try {
            const int i = v % n, j = v / n;
            const glm::vec2 uv(static_cast<float>(i) / static_cast<float>(n - 1),
                               static_cast<float>(j) / static_cast<float>(n - 1));
            Image nm, dm;
            const Image cm = renderOrthographicView(
                mesh, materials, impostorViewDirection(uv, settings.hemisphere), imp.centre,
                imp.radius, cell, settings.supersample, &nm, &dm);
            for (int y = 0; y < cell; ++y) {
                std::copy_n(cm.at(0, y), cell * 4, imp.color.at(i * cell, j * cell + y));
                std::copy_n(nm.at(0, y), cell * 3, imp.normal.at(i * cell, j * cell + y));
                std::copy_n(dm.at(0, y), cell, imp.depth.at(i * cell, j * cell + y));
            }
            bleed(imp.color, &imp.normal, &imp.depth, i * cell, j * cell, cell, 8);
            if (progress.isCancelled()) cancelled = true;
        } catch (...) {
#pragma omp critical(sylva_impostor_error)
            if (!error) error = std::current_exception();
            cancelled = true;
        }
    }
    if (error) std::rethrow_exception(error);
    progress.checkCancelled();
    return imp;
}

Image renderImpostor(const Impostor& imp, const glm::vec3& direction, int pixels) {
    // How far behind the surface a view stored a ray still counts as meeting it (radii): the
    // depth map holds only the nearest surface, so a ray that passes behind it is taken to hit
    // it this deep and no deeper, and at least as deep as the ray sinks in one march step (else
    // it would step over a surface: near an atlas view's own direction the ray sinks the whole
    // sphere in one step, and the old fixed 0.2 lost every hit there). Measured over the library
    // (test_lodchain, 8 x 8 views): 0.05 gives the best worst views (0.2: oak 0.948, pine 0.906,
    // beech 0.935, palm 0.807; 0.05: 0.955, 0.923, 0.958, 0.813); a thicker shell lets a view
    // add leaves the viewer's ray passes beside.
    constexpr float kShellThickness = 0.05f;
    // A view's hit that a heavier view contradicts: the heavier view has no coverage within
    // kFreeTexels texels of where the hit's surface point falls in its cell, so it sees empty
    // space there. Where one view reprojects a frond beside where it is (the date palm seen 1
    // degree above the horizon: its third view, 27 degrees away at weight 0.04, put a frond
    // tip in the gap between two fronds; IoU 0.895 there), the nearer views see through it.
    // The veto grows with how much heavier the contradicting view is (full at kVetoRamp more
    // weight), so the picture still changes continuously while the view turns. A texel of
    // slack keeps the thin leaflets two views place a texel apart (the palm's worst view,
    // vetoed by the heaviest view alone: 0 texels 0.886; 1: 0.909; 2: 0.908; 4: 0.895; as
    // here: 0.909; the ramp was not tuned).
    constexpr int kFreeTexels = 1;
    constexpr float kVetoRamp = 0.25f;
    // Bisection steps refining a hit between the last two march steps.
    constexpr int kRefineSteps = 5;
    // A view whose ray passes behind its own stored surface (where it covers at least half a
    // texel) and meets nothing cannot tell what lies there: it abstains, and the others'
    // coverage is taken at its full weight (rather than diluted by a view that does not know).
    constexpr float kHiddenCover = 0.5f;
    const glm::vec3 view = glm::normalize(direction);
    glm::vec3 right, up;
    impostorViewBasis(view, right, up);
    const int n = imp.settings.grid;
    const int cell = imp.settings.cellPixels;
    const Image* colorMap = &imp.color;
    const Image* depthMap = &imp.depth;
    // The grid triangle around the direction and its barycentric weights.
    const glm::vec2 g =
        impostorAtlasCoord(view, imp.settings.hemisphere) * static_cast<float>(n - 1);
    const glm::ivec2 base = glm::clamp(glm::ivec2(glm::floor(g)), glm::ivec2(0), glm::ivec2(n - 2));
    const glm::vec2 f = g - glm::vec2(base);
    glm::ivec2 corner[3];
    float weight[3];
    if (f.x + f.y <= 1.0f) {
        corner[0] = base;
        corner[1] = base + glm::ivec2(1, 0);
        corner[2] = base + glm::ivec2(0, 1);
        weight[0] = 1.0f - f.x - f.y;
        weight[1] = f.x;
        weight[2] = f.y;
    } else {
        corner[0] = base + glm::ivec2(1, 1);
        corner[1] = base + glm::ivec2(0, 1);
        corner[2] = base + glm::ivec2(1, 0);
        weight[0] = f.x + f.y - 1.0f;
        weight[1] = 1.0f - f.x;
        weight[2] = 1.0f - f.y;
    }
    glm::vec3 r[3], u[3], v[3];
    for (int k = 0; k < 3; ++k) {
        v[k] = impostorViewDirection(glm::vec2(corner[k]) / static_cast<float>(n - 1),
                                     imp.settings.hemisphere);
        impostorViewBasis(v[k], r[k], u[k]);
    }
    const auto bilinear = [&](const Image& image, int k, glm::vec2 t, int channels) {
        // t in texels of view k's cell; clamped to the cell so no neighbour bleeds in.
        const float cx = std::clamp(t.x, 0.0f, static_cast<float>(cell - 1));
        const float cy = std::clamp(t.y, 0.0f, static_cast<float>(cell - 1));
        const int x0 = static_cast<int>(cx), y0 = static_cast<int>(cy);
        const int x1 = std::min(x0 + 1, cell - 1), y1 = std::min(y0 + 1, cell - 1);
        const float fx = cx - static_cast<float>(x0), fy = cy - static_cast<float>(y0);
        const int ox = corner[k].x * cell, oy = corner[k].y * cell;
        glm::vec4 s(0.0f);
        const int xs[2] = {x0, x1}, ys[2] = {y0, y1};
        const float wx[2] = {1 - fx, fx}, wy[2] = {1 - fy, fy};
        for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a) {
                const std::uint8_t* q = image.at(ox + xs[a], oy + ys[b]);
                for (int c = 0; c < channels; ++c)
                    s[c] += wx[a] * wy[b] * static_cast<float>(q[c]) / 255.0f;
            }
        return s;
    };
    // Whether view j has coverage within kFreeTexels texels of where the point q (relative to
    // the centre, in radii) falls in its cell.
    const auto seenBy = [&](int j, const glm::vec3& q) {
        const int tx = static_cast<int>(
            std::floor((glm::dot(q, r[j]) * 0.5f + 0.5f) * static_cast<float>(cell)));
        const int ty = static_cast<int>(
            std::floor((0.5f - glm::dot(q, u[j]) * 0.5f) * static_cast<float>(cell)));
        for (int yy = std::max(0, ty - kFreeTexels); yy <= std::min(cell - 1, ty + kFreeTexels);
             ++yy)
            for (int xx = std::max(0, tx - kFreeTexels); xx <= std::min(cell - 1, tx + kFreeTexels);
                 ++xx)
                if (colorMap->at(corner[j].x * cell + xx, corner[j].y * cell + yy)[3] > 0)
                    return true;
        return false;
    };
    Image out(pixels, pixels, 4);
    for (int y = 0; y < pixels; ++y)
        for (int x = 0; x < pixels; ++x) {
            // The point of the camera-facing square, relative to the centre, in radii.
            const float bx =
                (static_cast<float>(x) + 0.5f) / static_cast<float>(pixels) * 2.0f - 1.0f;
            const float by =
                1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(pixels) * 2.0f;
            const glm::vec3 p = bx * right + by * up;
            // The tree lies inside its bounding sphere: the ray's stretch within it.
            const float pp = glm::dot(p, p);
            if (pp >= 1.0f) continue;
            const float half = std::sqrt(1.0f - pp);
            glm::vec3 rgb(0.0f);
            float alpha = 0.0f, abstained = 0.0f;
            for (int k = 0; k < 3; ++k) {
                if (weight[k] <= 0.0f) continue;
                // Relief mapping against view k's depth: the viewer's ray through p, x(s) =
                // p + view · s, is marched from the front of the bounding sphere backwards in
                // steps of about a texel of view k's cell, until it first passes behind the
                // surface view k stored there (height above view k's plane through the centre
                // <= the stored depth, by no more than kShellThickness) where that view has
                // coverage; then refined by bisection. A ray that meets nothing of view k takes
                // nothing from it, so a twig view k shows elsewhere does not ghost into the
                // picture (the reprojection of the three views agrees where the tree is).
                const float facing = glm::dot(view, v[k]);
                const float across = std::sqrt(std::max(0.0f, 1.0f - facing * facing));
                const int steps = std::clamp(
                    static_cast<int>(std::ceil(half * across * static_cast<float>(cell))), 1, 1024);
                const float h0 = glm::dot(p, v[k]);
                const auto texelAt = [&](float along) {
                    const glm::vec3 q = p + view * along;
                    return glm::vec2((glm::dot(q, r[k]) * 0.5f + 0.5f) * static_cast<float>(cell),
                                     (0.5f - glm::dot(q, u[k]) * 0.5f) * static_cast<float>(cell)) -
                           0.5f;
                };
                const auto surface = [&](glm::vec2 texel) {
                    return bilinear(*depthMap, k, texel, 1).x * 2.0f - 1.0f;
                };
                const float shell =
                    std::max(kShellThickness,
                             1.5f * 2.0f * half * std::abs(facing) / static_cast<float>(steps));
                bool hit = false, hidden = false;
                float hitAlong = 0.0f;
                glm::vec2 t(0.0f);
                float before = half;
                for (int i = 0; i <= steps && !hit; ++i) {
                    const float along =
                        half - 2.0f * half * static_cast<float>(i) / static_cast<float>(steps);
                    const glm::vec2 at = texelAt(along);
                    const float height = h0 + along * facing, depth = surface(at);
                    const float cover = bilinear(*colorMap, k, at, 4).w;
                    if (height < depth - shell && cover >= kHiddenCover) hidden = true;
                    if (height <= depth && height >= depth - shell && cover > 0.0f) {
                        float lo = along, hi = before; // behind and in front of the surface
                        for (int b = 0; b < kRefineSteps && i > 0; ++b) {
                            const float mid = 0.5f * (lo + hi);
                            if (h0 + mid * facing <= surface(texelAt(mid)))
                                lo = mid;
                            else
                                hi = mid;
                        }
                        t = texelAt(lo);
                        hitAlong = lo;
                        hit = true;
                    }
                    before = along;
                }
                if (!hit) {
                    if (hidden) abstained += weight[k];
                    continue;
                }
                float veto = 0.0f;
                const glm::vec3 q = p + view * hitAlong; // the surface point view k met
                for (int j = 0; j < 3; ++j)
                    if (weight[j] > weight[k] && !seenBy(j, q))
                        veto += std::min(1.0f, (weight[j] - weight[k]) / kVetoRamp);
                if (veto >= 1.0f) continue; // as if the ray met nothing of view k
                const glm::vec4 s = bilinear(*colorMap, k, t, 4);
                const float w = weight[k] * (1.0f - veto);
                rgb += w * glm::vec3(s) * s.w;
                alpha += w * s.w;
            }
            std::uint8_t* o = out.at(x, y);
            if (alpha > 0.0f)
                for (int k = 0; k < 3; ++k)
                    o[k] = toByte(rgb[k] / alpha);
            if (abstained < 1.0f) alpha /= 1.0f - abstained;
            o[3] = toByte(alpha);
        }
    return out;
}

} // namespace sylva::mesh
