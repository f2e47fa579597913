// An RGBA8 image in host memory, and what `quadtri render` does with one: PNG in and out
// (through stb), panels placed side by side, text labels.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace quadtri::render {

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;  // 4 bytes per pixel, row 0 at the top

    uint8_t* pixel(int x, int y) { return rgba.data() + 4 * (std::size_t(y) * std::size_t(width) + std::size_t(x)); }
    const uint8_t* pixel(int x, int y) const {
        return rgba.data() + 4 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
    }
};

// Reads a PNG or JPEG (anything stb_image reads) as RGBA8; std::runtime_error "path: reason".
Image readImage(const std::string& path);
// Encodes as PNG (RGBA).
std::vector<uint8_t> encodePng(const Image& image);

// Each k x k block of pixels averaged into one (the image's size divided by k, rounded down):
// supersampled anti-aliasing.
Image downsample(const Image& image, int k);
// `panels` (of one height) left to right.
Image sideBySide(const std::vector<Image>& panels);
// Blends `color` at `alpha` (0..1) over [x0, x1) x [y0, y1), clipped to the image.
void fillRect(Image& image, int x0, int y0, int x1, int y1, const std::array<uint8_t, 3>& color, float alpha = 1.0f);
// The size drawLabel gives `text` at `scale`, its backing box included.
std::array<int, 2> labelSize(const std::string& text, int scale);
// Draws `text` (printable ASCII; other bytes show as '?') with its top-left corner at (x, y), `scale` pixels per font unit, over a
// translucent backing box so that it reads on any shading.
void drawLabel(Image& image, int x, int y, const std::string& text, int scale, const std::array<uint8_t, 3>& color);

}  // namespace quadtri::render
