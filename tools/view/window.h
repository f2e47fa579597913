// The viewer's window: GLFW without a client API, and its Vulkan surface. Failures (no display,
// no Vulkan loader) are WindowError with one sentence saying what is missing (docs/viewer.md).
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>
#include <vector>

struct GLFWwindow;

namespace quadtri::view {

class WindowError : public std::runtime_error {
public:
    explicit WindowError(const std::string& what) : std::runtime_error(what) {}
};

class Window {
public:
    // glfwInit and a window of `width` x `height` screen units titled `title`.
    Window(int width, int height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    // The instance extensions GLFW needs for a surface (VK_KHR_surface and the platform's).
    static std::vector<std::string> requiredInstanceExtensions();
    // Whether queue family `family` of `device` can present to this platform's windows.
    static bool canPresent(VkInstance instance, VkPhysicalDevice device, uint32_t family);


    VkExtent2D framebufferSize() const;
    bool shouldClose() const;
    void setShouldClose(bool close);
    void setTitle(const std::string& title);

private:
    GLFWwindow* window_ = nullptr;
};

// The window's Vulkan surface on an instance; declare it after the instance's owner, so that it
// goes first.
class WindowSurface {
public:
    WindowSurface(const Window& window, VkInstance instance);
    ~WindowSurface();
    WindowSurface(const WindowSurface&) = delete;
    WindowSurface& operator=(const WindowSurface&) = delete;
    VkSurfaceKHR handle() const { return surface_; }

private:
    VkInstance instance_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
};

}  // namespace quadtri::view
