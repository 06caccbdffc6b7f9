#include "engine/export/pivotpainter.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/util/atomicfile.h"
#include "engine/util/error.h"
#include "engine/util/image.h"

namespace sylva::exporter {

namespace {

constexpr std::int32_t kMaxElements = 30719; // + 1024 stays below the half's infinity (0x7c00)

// OpenEXR writes through a stream; ours keeps the bytes for one atomic write.
class StringStream : public Imf::OStream {
public:
    StringStream() : Imf::OStream("pivot painter texture") {}
    void write(const char c[], int n) override {
        if (mAt + static_cast<std::size_t>(n) > mBytes.size())
            mBytes.resize(mAt + static_cast<std::size_t>(n));
        std::copy_n(c, n, mBytes.begin() + static_cast<std::ptrdiff_t>(mAt));
        mAt += static_cast<std::size_t>(n);
    }
    std::uint64_t tellp() override { return mAt; }
    void seekp(std::uint64_t pos) override { mAt = static_cast<std::size_t>(pos); }
    const std::string& bytes() const { return mBytes; }

private:
    std::string mBytes;
    std::size_t mAt = 0;
};

std::uint8_t unorm8(float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

} // namespace

glm::vec3 toUnreal(const glm::vec3& s) {
    return glm::vec3(s.x, s.z, s.y) * 100.0f;
}

std::uint16_t pivotPainterIntBits(std::int32_t n) {
    if (n < 0 || n > kMaxElements)
        throw InvalidInput("Pivot Painter index " + std::to_string(n) + " outside 0.." +
                           std::to_string(kMaxElements));
    return static_cast<std::uint16_t>(n + 1024);
}

float halfToFloat(std::uint16_t bits) {
    Imath::half h;
    h.setBits(bits);
    return static_cast<float>(h);
}

std::uint16_t floatToHalf(float value) {
    return Imath::half(value).bits();
}

PivotPainterData buildPivotPainter(const wind::WindElements& elements,
                                   const skel::Skeleton& skeleton, const mesh::Mesh& m) {
    const std::size_t n = elements.elements.size();
    if (n > static_cast<std::size_t>(kMaxElements) + 1)
        throw LimitExceeded("Pivot Painter textures hold at most " +
                            std::to_string(kMaxElements + 1) + " elements, the tree has " +
                            std::to_string(n));
    if (m.node.size() != m.positions.size())
        throw InvalidInput("Pivot Painter data needs the mesh's node ids");
    PivotPainterData d;
    const std::size_t count = std::max<std::size_t>(n, 1);
    d.width = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    d.height = static_cast<int>((count + static_cast<std::size_t>(d.width) - 1) /
                                static_cast<std::size_t>(d.width));
    const std::size_t pixels =
        static_cast<std::size_t>(d.width) * static_cast<std::size_t>(d.height);
    d.pivotIndex.assign(pixels, glm::vec4(0.0f));
    d.halfBits.assign(pixels * 4, 0);
    d.axisExtent.assign(pixels, glm::u8vec4(0));
    for (std::size_t e = 0; e < n; ++e) {
        const wind::WindElement& el = elements.elements[e];
        const std::int32_t parent = el.parent >= 0 ? el.parent : static_cast<std::int32_t>(e);
        const glm::vec3 pivot = toUnreal(el.pivot);
        for (int c = 0; c < 3; ++c)
            d.halfBits[4 * e + static_cast<std::size_t>(c)] = floatToHalf(pivot[c]);
        d.halfBits[4 * e + 3] = pivotPainterIntBits(parent);
        for (int c = 0; c < 4; ++c)
            d.pivotIndex[e][c] = halfToFloat(d.halfBits[4 * e + static_cast<std::size_t>(c)]);
        // Unreal's frame is a permutation of ours (and a scale): the axis stays a unit vector.
        const glm::vec3 axis = toUnreal(el.direction) / 100.0f;
        const glm::vec3 tip =
            el.tipNode >= 0 && static_cast<std::size_t>(el.tipNode) < skeleton.size()
                ? skeleton.position[static_cast<std::size_t>(el.tipNode)]
                : el.pivot;
        const float extentCm = 100.0f * std::max(0.0f, glm::dot(tip - el.pivot, el.direction));
        d.axisExtent[e] =
            glm::u8vec4(unorm8((axis.x + 1.0f) * 0.5f), unorm8((axis.y + 1.0f) * 0.5f),
                        unorm8((axis.z + 1.0f) * 0.5f),
                        unorm8(std::clamp(extentCm / 8.0f, 1.0f, 256.0f) / 256.0f));
    }
    const std::size_t nv = m.positions.size();
    d.vertexElement.resize(nv);
    d.vertexUv.resize(nv);
    for (std::size_t i = 0; i < nv; ++i) {
        const std::int32_t node = m.node[i];
        std::int32_t e = node >= 0 && static_cast<std::size_t>(node) < elements.nodeElement.size()
                             ? elements.nodeElement[static_cast<std::size_t>(node)]
                             : -1;
        if (e < 0) e = 0; // no node, or a hidden one: the first trunk
        d.vertexElement[i] = e;
        const int col = e % d.width, row = e / d.width;
        d.vertexUv[i] = glm::vec2((static_cast<float>(col) + 0.5f) / static_cast<float>(d.width),
                                  (static_cast<float>(row) + 0.5f) / static_cast<float>(d.height));
    }
    return d;
}

std::vector<std::filesystem::path> writePivotPainter(const std::filesystem::path& stem,
                                                     const PivotPainterData& d) {
    const std::filesystem::path exr = stem.string() + "_pivot_index.exr";
    const std::filesystem::path png = stem.string() + "_xaxis_extent.png";
    {
        Imf::Header header(d.width, d.height);
        header.compression() = Imf::NO_COMPRESSION;
        for (const char* c : {"R", "G", "B", "A"})
            header.channels().insert(c, Imf::Channel(Imf::HALF));
        StringStream out;
        {
            // The file is complete when OutputFile is gone: it writes the line offsets last.
            Imf::OutputFile file(out, header, 1);
            Imf::FrameBuffer frame;
            auto* base = const_cast<char*>(reinterpret_cast<const char*>(d.halfBits.data()));
            const std::size_t xStride = 4 * sizeof(std::uint16_t);
            const std::size_t yStride = xStride * static_cast<std::size_t>(d.width);
            const char* names[4] = {"R", "G", "B", "A"};
            for (int c = 0; c < 4; ++c)
                frame.insert(names[c], Imf::Slice(Imf::HALF, base + 2 * c, xStride, yStride));
            file.setFrameBuffer(frame);
            file.writePixels(d.height);
        }
        writeFileAtomically(exr, out.bytes());
    }
    Image image(d.width, d.height, 4);
    for (std::size_t i = 0; i < d.axisExtent.size(); ++i)
        for (int c = 0; c < 4; ++c)
            image.pixels[4 * i + static_cast<std::size_t>(c)] = d.axisExtent[i][c];
    writePng(png, image);
    return {exr, png};
}

} // namespace sylva::exporter
