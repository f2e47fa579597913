// `quadtri view` in a build without Vulkan, GLFW or Dear ImGui.
#include <cstdio>

#include "tools/view/view_command.h"

namespace quadtri::view {

int runView(const ViewerArgs&) {
    std::fprintf(stderr, "quadtri: this build has no viewer (it needs Vulkan, GLFW and Dear ImGui: "
                         "libvulkan-dev, libglfw3-dev, libimgui-dev)\n");
    return 2;
}

}  // namespace quadtri::view
