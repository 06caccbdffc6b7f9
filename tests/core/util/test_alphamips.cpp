// Issue #33: mipmaps of cut-out textures that keep the share of texels passing the alpha test.
#include <gtest/gtest.h>

#include "engine/util/alphamips.h"
#include "engine/util/error.h"

using namespace sylva;

namespace {

// Needles seen from afar: a quarter of the texels opaque, scattered (a fixed LCG), on a
// transparent ground of the needles' colour.
Image needles(int size) {
    Image img(size, size, 4);
    std::uint32_t state = 12345;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            state = state * 1664525u + 1013904223u;
            std::uint8_t* p = img.at(x, y);
            p[0] = 40;
            p[1] = 90;
            p[2] = 70;
            p[3] = (state >> 24) < 64 ? 255 : 0;
        }
    return img;
}

} // namespace

TEST(AlphaMips, KeepLevelZerosCoverage) {
    const Image img = needles(64);
    const double c0 = alphaCoverage(img);
    EXPECT_NEAR(c0, 0.25, 0.02);
    const std::vector<Image> mips = alphaTestedMips(img);
    ASSERT_EQ(mips.size(), 6u); // 32, 16, 8, 4, 2, 1
    EXPECT_EQ(mips[0].width, 32);
    EXPECT_EQ(mips.back().width, 1);
    EXPECT_EQ(mips.back().height, 1);
    // Down to 8 x 8 the share passing the cut-off stays near level 0's (texels of one alpha
    // pass together, so not exactly; a plain box filter's alpha
    // is about 0.25 everywhere from 16 x 16 on: nothing would pass).
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(alphaCoverage(mips[k]), c0, 0.07) << "level " << k + 1;
    // The colour is the needles' (transparent texels lend none).
    for (const Image& m : mips) {
        EXPECT_EQ(m.at(0, 0)[0], 40);
        EXPECT_EQ(m.at(0, 0)[1], 90);
    }
}

TEST(AlphaMips, OpaqueAndEmptyStaySoAndOddSizesRoundDown) {
    Image opaque(5, 3, 4);
    for (std::size_t i = 3; i < opaque.pixels.size(); i += 4)
        opaque.pixels[i] = 255;
    const std::vector<Image> mips = alphaTestedMips(opaque);
    ASSERT_EQ(mips.size(), 2u); // 2 x 1, 1 x 1
    EXPECT_EQ(mips[0].width, 2);
    EXPECT_EQ(mips[0].height, 1);
    for (const Image& m : mips)
        EXPECT_DOUBLE_EQ(alphaCoverage(m), 1.0);
    const Image empty(8, 8, 4);
    for (const Image& m : alphaTestedMips(empty))
        EXPECT_DOUBLE_EQ(alphaCoverage(m), 0.0);
    EXPECT_THROW(alphaTestedMips(Image(4, 4, 3)), InvalidInput);
    EXPECT_THROW(alphaTestedMips(empty, 1.5), InvalidInput);
}
