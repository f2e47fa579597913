#include "tools/render/image.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <stb_easy_font.h>
#include <stb_image.h>
#include <stb_image_write.h>

namespace quadtri::render {

Image readImage(const std::string& path) {
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (!data) {
        const char* reason = stbi_failure_reason();
        throw std::runtime_error(path + ": cannot read the image (" + (reason ? reason : "unknown reason") +
                                 "; PNG and JPEG are read)");
    }
    Image image{w, h, std::vector<uint8_t>(data, data + std::size_t(w) * std::size_t(h) * 4)};
    stbi_image_free(data);
    return image;
}

std::vector<uint8_t> encodePng(const Image& image) {
    std::vector<uint8_t> bytes;
    auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<uint8_t>*>(context);
        out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
    };
    if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4))
        throw std::runtime_error("PNG encoding failed");
    return bytes;
}

Image downsample(const Image& image, int k) {
    if (k <= 1) return image;
    Image out{image.width / k, image.height / k, {}};
    out.rgba.resize(std::size_t(out.width) * std::size_t(out.height) * 4);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int c = 0; c < 4; ++c) {
                int sum = 0;
                for (int dy = 0; dy < k; ++dy)
                    for (int dx = 0; dx < k; ++dx) sum += image.pixel(k * x + dx, k * y + dy)[c];
                out.pixel(x, y)[c] = uint8_t((sum + k * k / 2) / (k * k));
            }
    return out;
}

Image sideBySide(const std::vector<Image>& panels) {
    Image out;
    for (const Image& p : panels) out.width += p.width, out.height = std::max(out.height, p.height);
    out.rgba.assign(std::size_t(out.width) * std::size_t(out.height) * 4, 0);
    int x0 = 0;
    for (const Image& p : panels) {
        for (int y = 0; y < p.height; ++y) std::copy(p.pixel(0, y), p.pixel(0, y) + 4 * p.width, out.pixel(x0, y));
        x0 += p.width;
    }
    return out;
}

void fillRect(Image& image, int x0, int y0, int x1, int y1, const std::array<uint8_t, 3>& color, float alpha) {
    x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            uint8_t* p = image.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = uint8_t(std::lround(p[c] * (1.0f - alpha) + color[std::size_t(c)] * alpha));
            p[3] = 255;
        }
}

namespace {

// The font has printable ASCII only (it indexes its table by the character): anything else,
// tabs and newlines included, becomes '?'.
std::vector<char> cString(const std::string& text) {
    std::vector<char> chars;
    for (char c : text) chars.push_back(c >= 32 && c <= 126 ? c : '?');
    chars.push_back('\0');
    return chars;
}

}  // namespace

std::array<int, 2> labelSize(const std::string& text, int scale) {
    std::vector<char> chars = cString(text);
    return {stb_easy_font_width(chars.data()) * scale + 4 * scale,
            stb_easy_font_height(chars.data()) * scale + 4 * scale};
}

void drawLabel(Image& image, int x, int y, const std::string& text, int scale, const std::array<uint8_t, 3>& color) {
    std::vector<char> chars = cString(text);
    // stb_easy_font emits axis-aligned quads (4 vertices of 16 bytes: x, y, z, colour) in font
    // units; a line is about 12 units high.
    std::vector<char> quads(std::size_t(text.size()) * 270 + 1024);
    unsigned char rgba[4] = {255, 255, 255, 255};
    const int numQuads = stb_easy_font_print(0, 0, chars.data(), rgba, quads.data(), int(quads.size()));
    const int pad = 2 * scale;
    const std::array<uint8_t, 3> backing =
        color[0] + color[1] + color[2] > 384 ? std::array<uint8_t, 3>{0, 0, 0} : std::array<uint8_t, 3>{255, 255, 255};
    const std::array<int, 2> size = labelSize(text, scale);
    fillRect(image, x, y, x + size[0], y + size[1], backing, 0.55f);
    for (int q = 0; q < numQuads; ++q) {
        float v[16];
        std::memcpy(v, quads.data() + std::size_t(q) * 64, sizeof v);
        const float qx0 = std::min(v[0], v[8]), qx1 = std::max(v[0], v[8]);
        const float qy0 = std::min(v[1], v[9]), qy1 = std::max(v[1], v[9]);
        fillRect(image, x + pad + int(std::lround(qx0 * scale)), y + pad + int(std::lround(qy0 * scale)),
                 x + pad + int(std::lround(qx1 * scale)), y + pad + int(std::lround(qy1 * scale)), color, 1.0f);
    }
}

}  // namespace quadtri::render
