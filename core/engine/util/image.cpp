#include "engine/util/image.h"

#include <png.h>

#include <cstring>

#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

namespace sylva {

Image readPng(const std::filesystem::path& file) {
    // libpng's simplified API: any PNG in, 8-bit RGBA out.
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, file.string().c_str()))
        throw IoError("cannot read PNG " + file.string() + ": " + png.message);
    png.format = PNG_FORMAT_RGBA;
    Image image(static_cast<int>(png.width), static_cast<int>(png.height), 4);
    if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr)) {
        const std::string message = png.message;
        png_image_free(&png);
        throw IoError("cannot read PNG " + file.string() + ": " + message);
    }
    return image;
}

std::string encodePng(const Image& image) {
    if (image.empty()) throw InvalidInput("cannot write an empty image as PNG");
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.width);
    png.height = static_cast<png_uint_32>(image.height);
    switch (image.channels) {
    case 1:
        png.format = PNG_FORMAT_GRAY;
        break;
    case 3:
        png.format = PNG_FORMAT_RGB;
        break;
    case 4:
        png.format = PNG_FORMAT_RGBA;
        break;
    default:
        throw InvalidInput("PNG images have 1, 3 or 4 channels, not " +
                           std::to_string(image.channels));
    }
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&png, nullptr, &size, 0, image.pixels.data(), 0, nullptr))
        throw IoError(std::string("cannot encode PNG: ") + png.message);
    std::string bytes(size, '\0');
    if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, image.pixels.data(), 0, nullptr))
        throw IoError(std::string("cannot encode PNG: ") + png.message);
    bytes.resize(size);
    return bytes;
}

void writePng(const std::filesystem::path& file, const Image& image) {
    writeFileAtomically(file, encodePng(image));
}

} // namespace sylva
