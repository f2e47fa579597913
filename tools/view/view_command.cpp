#include "tools/view/view_command.h"

#include <cstdio>

#include "tools/view/viewer.h"

namespace quadtri::view {

int runView(const ViewerArgs& args) {
    int status = 2;
    int validation = 0;
    try {
        Viewer viewer(args);
        status = viewer.run();
    } catch (const WindowError& e) {
        std::fprintf(stderr, "quadtri: view needs a window: %s\n", e.what());
        return 2;
    } catch (const VulkanError& e) {
        if (e.result() == VK_ERROR_DEVICE_LOST)
            std::fprintf(stderr, "quadtri: the Vulkan device was lost (%s)\n", e.what());
        else
            std::fprintf(stderr, "quadtri: view needs a Vulkan device that can draw to the window: %s\n", e.what());
        return 2;
    } catch (const ScriptError& e) {
        std::fprintf(stderr, "quadtri: %s\n", e.what());
        return 2;
    }
    validation = render::GpuDevice::totalValidationMessageCount();
    if (validation > 0) std::fprintf(stderr, "quadtri: the Vulkan validation layer reported %d problems\n", validation);
    return status;
}

}  // namespace quadtri::view
