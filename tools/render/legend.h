// The sharpness colour code's legend (docs/rendering.md), drawn into an image on the CPU.
#pragma once

#include "tools/render/image.h"

namespace quadtri::render {

// A row of swatches with their sharpness (0, 1, 2.5, 5, 7.5, inf) along the image's bottom-left
// corner, at 2 pixels per font unit where that fits, else 1.
void drawSharpnessLegend(Image& image);

}  // namespace quadtri::render
