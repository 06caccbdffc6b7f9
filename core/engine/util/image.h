#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sylva {

/// An 8-bit image, rows top to bottom, channels interleaved (1 grey, 3 RGB, 4 RGBA; colour in
/// sRGB as PNG stores it).
struct Image {
    int width = 0;
    int height = 0;
    int channels = 4;
    std::vector<std::uint8_t> pixels;

    Image() = default;
    Image(int w, int h, int c)
        : width(w), height(h), channels(c),
          pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) *
                     static_cast<std::size_t>(c),
                 0) {}
    bool empty() const { return width == 0 || height == 0; }
    std::uint8_t* at(int x, int y) {
        return pixels.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                static_cast<std::size_t>(x)) *
                                   static_cast<std::size_t>(channels);
    }
    const std::uint8_t* at(int x, int y) const { return const_cast<Image*>(this)->at(x, y); }
};

/// Reads a PNG (any bit depth, palette or grey) as 8-bit RGBA through libpng.
/// \throw IoError when the file cannot be read or is no PNG.
Image readPng(const std::filesystem::path& file);

/// The PNG bytes of \p image (1, 3 or 4 channels), deterministic for the same pixels.
/// \throw InvalidInput for another channel count or an empty image.
std::string encodePng(const Image& image);

/// encodePng() written atomically. \throw IoError
void writePng(const std::filesystem::path& file, const Image& image);

} // namespace sylva
