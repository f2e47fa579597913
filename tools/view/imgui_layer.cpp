#include "tools/view/imgui_layer.h"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

namespace quadtri::view {

namespace {

void checkResult(VkResult r) { vkCheck(r, "Dear ImGui's Vulkan back end"); }

}  // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window, VulkanContext& ctx, VkRenderPass renderPass, uint32_t minImages,
                       uint32_t images)
    : ctx_(ctx) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written into the user's folder
    ImGui::StyleColorsDark();
    try {
        // The font texture's one combined image sampler, with room to spare.
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8};
        auto pi = detail::vkStruct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
        pi.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
        pi.maxSets = 8;
        pi.poolSizeCount = 1;
        pi.pPoolSizes = &size;
        vkCheck(vkCreateDescriptorPool(ctx.device(), &pi, nullptr, &pool_), "vkCreateDescriptorPool");
        glfwInitialized_ = ImGui_ImplGlfw_InitForVulkan(window, true);
        ImGui_ImplVulkan_InitInfo info{};
        info.Instance = ctx.instance();
        info.PhysicalDevice = ctx.physicalDevice();
        info.Device = ctx.device();
        info.QueueFamily = ctx.queueFamilyIndex();
        info.Queue = ctx.queue();
        info.DescriptorPool = pool_;
        info.MinImageCount = minImages;
        info.ImageCount = images;
        info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
        info.CheckVkResultFn = &checkResult;
        vulkanInitialized_ = ImGui_ImplVulkan_Init(&info, renderPass);
        if (!glfwInitialized_ || !vulkanInitialized_) throw VulkanError("Dear ImGui's back ends failed to start");
        ctx.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
        ImGui_ImplVulkan_DestroyFontUploadObjects();
    } catch (...) {
        shutdown();
        throw;
    }
}

ImGuiLayer::~ImGuiLayer() { shutdown(); }

void ImGuiLayer::shutdown() noexcept {
    vkDeviceWaitIdle(ctx_.device());
    if (vulkanInitialized_) ImGui_ImplVulkan_Shutdown();
    if (glfwInitialized_) ImGui_ImplGlfw_Shutdown();
    vulkanInitialized_ = glfwInitialized_ = false;
    if (pool_) vkDestroyDescriptorPool(ctx_.device(), pool_, nullptr);
    pool_ = VK_NULL_HANDLE;
    if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
}

void ImGuiLayer::newFrame(float deltaSeconds) {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();  // sets DeltaTime from glfwGetTime
    if (deltaSeconds > 0.0f) ImGui::GetIO().DeltaTime = deltaSeconds;
    ImGui::NewFrame();
}

void ImGuiLayer::render(VkCommandBuffer cmd, bool draw) {
    ImGui::Render();
    if (draw) ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}

bool ImGuiLayer::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace quadtri::view
