#include "engine/util/alphamips.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/util/error.h"

namespace sylva {

namespace {

std::uint8_t threshold(double cutoff) {
    return static_cast<std::uint8_t>(std::clamp(std::ceil(cutoff * 255.0 - 1e-9), 1.0, 255.0));
}

// The 2 x 2 box filter of \p src (a last odd row or column folds into its neighbour's texel,
// as the 3 x 3 footprint of OpenGL's generated mipmaps does), colour weighted by alpha.
Image halve(const Image& src) {
    const int w = std::max(1, src.width / 2), h = std::max(1, src.height / 2);
    Image dst(w, h, 4);
    for (int y = 0; y < h; ++y) {
        const int y0 = std::min(2 * y, src.height - 1);
        const int y1 = y + 1 == h ? src.height - 1 : std::min(2 * y + 1, src.height - 1);
        for (int x = 0; x < w; ++x) {
            const int x0 = std::min(2 * x, src.width - 1);
            const int x1 = x + 1 == w ? src.width - 1 : std::min(2 * x + 1, src.width - 1);
            double rgb[3] = {0, 0, 0}, plain[3] = {0, 0, 0}, alpha = 0.0;
            int count = 0;
            for (int sy = y0; sy <= y1; ++sy)
                for (int sx = x0; sx <= x1; ++sx) {
                    const std::uint8_t* p = src.at(sx, sy);
                    for (int c = 0; c < 3; ++c) {
                        rgb[c] += static_cast<double>(p[c]) * p[3];
                        plain[c] += p[c];
                    }
                    alpha += p[3];
                    ++count;
                }
            std::uint8_t* q = dst.at(x, y);
            for (int c = 0; c < 3; ++c) {
                // Transparent texels keep their own (dilated) colour for the bilinear fringe.
                const double v = alpha > 0.0 ? rgb[c] / alpha : plain[c] / count;
                q[c] = static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 255.0)));
            }
            q[3] = static_cast<std::uint8_t>(std::lround(alpha / count));
        }
    }
    return dst;
}

} // namespace

double alphaCoverage(const Image& image, double cutoff) {
    if (image.channels != 4) throw InvalidInput("alpha coverage needs an RGBA image");
    const std::uint8_t t = threshold(cutoff);
    std::size_t covered = 0;
    for (std::size_t i = 3; i < image.pixels.size(); i += 4)
        covered += image.pixels[i] >= t;
    const std::size_t n = image.pixels.size() / 4;
    return n ? static_cast<double>(covered) / static_cast<double>(n) : 0.0;
}

std::vector<Image> alphaTestedMips(const Image& image, double cutoff) {
    if (image.channels != 4) throw InvalidInput("alpha-tested mipmaps need an RGBA image");
    requireRange("alpha cutoff", cutoff, 1e-3, 0.999);
    std::vector<Image> levels;
    if (image.empty()) return levels;
    const double target = alphaCoverage(image, cutoff);
    const Image* above = &image;
    while (above->width > 1 || above->height > 1) {
        Image level = halve(*above);
        // Scale alpha by cutoff / a, where a is the alpha of the texel that ranks at level 0's
        // coverage: then as many texels as at level 0, in share, pass the cut-off.
        std::array<std::size_t, 256> histogram{};
        const std::size_t n = level.pixels.size() / 4;
        for (std::size_t i = 3; i < level.pixels.size(); i += 4)
            ++histogram[level.pixels[i]];
        const auto want = static_cast<std::size_t>(std::lround(target * static_cast<double>(n)));
        if (want > 0) {
            std::size_t seen = 0;
            int a = 255;
            for (; a > 1; --a) {
                const std::size_t before = seen;
                seen += histogram[static_cast<std::size_t>(a)];
                if (seen >= want) {
                    // Texels of one alpha pass together: the nearer of the two shares.
                    if (seen - want > want - before && before > 0) ++a;
                    break;
                }
            }
            // Rounded, alpha a lands on the threshold and a - 1 just under it.
            const double s = (static_cast<double>(threshold(cutoff)) - 0.5 + 1e-6) / a;
            for (std::size_t i = 3; i < level.pixels.size(); i += 4) {
                const double v = std::round(level.pixels[i] * s);
                level.pixels[i] = static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0));
            }
        }
        levels.push_back(std::move(level));
        above = &levels.back();
    }
    return levels;
}

} // namespace sylva
