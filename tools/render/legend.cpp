#include "tools/render/legend.h"

#include <cmath>
#include <string>
#include <utility>

#include <quadtri/far/options.h>

#include "tools/render/surface_data.h"

namespace quadtri::render {

namespace {

const std::pair<float, const char*> kEntries[] = {{0.0f, "0"}, {1.0f, "1"},   {2.5f, "2.5"},
                                                  {5.0f, "5"}, {7.5f, "7.5"}, {kInfiniteSharpness, "inf"}};

int legendWidth(int scale) {
    const int rowHeight = labelSize("sharpness", scale)[1];
    int width = 8 * scale + labelSize("sharpness", scale)[0] + 2 * scale;
    for (const auto& entry : kEntries) width += rowHeight + labelSize(entry.second, scale)[0] + 3 * scale;
    return width;
}

}  // namespace

void drawSharpnessLegend(Image& image) {
    int scale = 2;
    while (scale > 1 && legendWidth(scale) > image.width) --scale;
    const std::array<int, 2> title = labelSize("sharpness", scale);
    const int rowHeight = title[1];
    int x = 8 * scale;
    const int y = image.height - rowHeight - 4 * scale;
    drawLabel(image, x, y, "sharpness", scale, {255, 255, 255});
    x += title[0] + 2 * scale;
    for (const auto& [sharpness, text] : kEntries) {
        const glm::vec3 c = sharpnessColor(sharpness) * 255.0f;
        const std::array<uint8_t, 3> rgb{uint8_t(std::lround(c.r)), uint8_t(std::lround(c.g)),
                                         uint8_t(std::lround(c.b))};
        fillRect(image, x, y + scale, x + rowHeight - 2 * scale, y + rowHeight - scale, rgb);
        x += rowHeight;
        drawLabel(image, x, y, text, scale, {255, 255, 255});
        x += labelSize(text, scale)[0] + 3 * scale;
    }
}

}  // namespace quadtri::render
