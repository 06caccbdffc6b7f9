#include "engine/mesh/impostorfit.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "engine/mesh/silhouette.h"
#include "engine/util/error.h"

namespace sylva::mesh {

double impostorSilhouetteIoU(const Mesh& reference, const Impostor& impostor, int pixels,
                             int views) {
    requireRange("impostor check pixels", pixels, 1, 4096);
    const double scale = pixels / (2.0 * static_cast<double>(std::max(impostor.radius, 1e-6f)));
    std::vector<std::uint8_t> tree, card(static_cast<std::size_t>(pixels) * pixels);
    double sum = 0.0;
    for (int k = 0; k < views; ++k) {
        const glm::vec3 dir = silhouetteView(k, views);
        glm::vec3 right, up;
        impostorViewBasis(dir, right, up);
        coverageMask(reference, impostor.centre, right, up, scale, pixels, tree);
        const Image drawn = renderImpostor(impostor, dir, pixels);
        for (int y = 0; y < pixels; ++y)
            for (int x = 0; x < pixels; ++x)
                card[static_cast<std::size_t>(y) * pixels + x] = drawn.at(x, y)[3] > 0 ? 1 : 0;
        sum += maskIoU(closeMask(tree, pixels, pixels), closeMask(card, pixels, pixels));
    }
    return views > 0 ? sum / views : 1.0;
}

ImpostorSwitch impostorSwitchHeight(const Mesh& reference, const Impostor& impostor,
                                    double treeHeight, double startHeightPx, double minIoU,
                                    double floorHeightPx, int views) {
    if (!(treeHeight > 0.0)) throw InvalidInput("the tree's height must be positive");
    requireRange("impostor switch height", startHeightPx, 1.0, 4096.0);
    requireRange("impostor floor height", floorHeightPx, 1.0, startHeightPx);
    // The square around the bounding sphere spans this many times the tree's height on screen.
    const double across = 2.0 * static_cast<double>(impostor.radius) / treeHeight;
    ImpostorSwitch out;
    for (double h = startHeightPx;; h *= 0.8) {
        const double height = std::max(h, floorHeightPx);
        const int pixels = std::clamp(static_cast<int>(std::lround(height * across)), 1, 4096);
        const double iou = impostorSilhouetteIoU(reference, impostor, pixels, views);
        out.tried.emplace_back(height, iou);
        out.heightPx = height;
        out.iou = iou;
        out.met = iou >= minIoU;
        if (out.met || height <= floorHeightPx) break;
    }
    if (!out.met) {
        // Never as good as asked: where it is best (the largest such height), since switching
        // later than that only costs meshes without bringing the silhouettes closer.
        const auto best =
            std::max_element(out.tried.begin(), out.tried.end(),
                             [](const auto& a, const auto& b) { return a.second < b.second; });
        out.heightPx = best->first;
        out.iou = best->second;
    }
    return out;
}

} // namespace sylva::mesh
