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
    destroySurface();
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

VkSurfaceKHR Window::surface(VkInstance instance) {
    if (surface_) return surface_;
    const VkResult r = glfwCreateWindowSurface(instance, window_, nullptr, &surface_);
    if (r != VK_SUCCESS) throw WindowError("cannot create the window's Vulkan surface (" + glfwProblem() + ")");
    instance_ = instance;
    return surface_;
}

void Window::destroySurface() noexcept {
    if (surface_) vkDestroySurfaceKHR(instance_, surface_, nullptr);
    surface_ = VK_NULL_HANDLE;
}

VkExtent2D Window::framebufferSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_); }
void Window::setShouldClose(bool close) { glfwSetWindowShouldClose(window_, close); }
void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

}  // namespace quadtri::view
