// Dear ImGui over the viewer's window and device: its GLFW back end for input, its Vulkan back
// end drawing into the viewer's render pass after the scene (docs/viewer.md).
#pragma once

#include <vulkan/vulkan.h>

#include <quadtri/osd/vulkan_context.h>

struct GLFWwindow;

namespace quadtri::view {

class ImGuiLayer {
public:
    // Install GLFW callbacks of your own before this: ImGui's chain to them.
    ImGuiLayer(GLFWwindow* window, VulkanContext& ctx, VkRenderPass renderPass, uint32_t minImages, uint32_t images);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    // `deltaSeconds` > 0 replaces the back end's clock for this frame (a script's fixed frame
    // time, so that Dear ImGui's fades do not depend on the machine's speed).
    void newFrame(float deltaSeconds = 0.0f);
    // Ends the frame's UI; draws it into `cmd` inside the render pass when `draw`.
    void render(VkCommandBuffer cmd, bool draw);
    // Whether the UI has the mouse / the keyboard (the view then ignores them).
    bool wantsMouse() const;
    bool wantsKeyboard() const;

private:
    void shutdown() noexcept;

    VulkanContext& ctx_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    bool glfwInitialized_ = false, vulkanInitialized_ = false;
};

}  // namespace quadtri::view
