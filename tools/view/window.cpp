#include "tools/view/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdlib>

namespace quadtri::view {

namespace {

std::string glfwProblem() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "no reason given";
}

}  // namespace

Window::Window(int width, int height, const std::string& title) {
    if (!glfwInit()) {
        const bool noDisplay = !std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY");
        throw WindowError(noDisplay ? "no display: set DISPLAY (or WAYLAND_DISPLAY), or run under xvfb-run"
                                    : "cannot open the display (" + glfwProblem() + ")");
    }
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw WindowError("no Vulkan loader or driver for windows (install libvulkan1 and a driver, e.g. "
                          "mesa-vulkan-drivers)");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string why = glfwProblem();
        glfwTerminate();
        throw WindowError("cannot create the window (" + why + ")");
    }
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<std::string> Window::requiredInstanceExtensions() {
    uint32_t n = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&n);
    if (!names) throw WindowError("GLFW finds no Vulkan surface extensions (" + glfwProblem() + ")");
    return {names, names + n};
}

bool Window::canPresent(VkInstance instance, VkPhysicalDevice device, uint32_t family) {
    return glfwGetPhysicalDevicePresentationSupport(instance, device, family) == GLFW_TRUE;
}

WindowSurface::WindowSurface(const Window& window, VkInstance instance) : instance_(instance) {
    if (glfwCreateWindowSurface(instance, window.handle(), nullptr, &surface_) != VK_SUCCESS)
        throw WindowError("cannot create the window's Vulkan surface (" + glfwProblem() + ")");
}

WindowSurface::~WindowSurface() { vkDestroySurfaceKHR(instance_, surface_, nullptr); }

VkExtent2D Window::framebufferSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_); }
void Window::setShouldClose(bool close) { glfwSetWindowShouldClose(window_, close); }
void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

}  // namespace quadtri::view
