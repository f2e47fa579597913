// A Vulkan instance and device for drawing: one queue family that does graphics and compute (and,
// for a window, presentation), handed to quadtri through VulkanContext::External exactly as an
// engine would hand its own, so that the evaluators run on the device the renderer draws with
// (docs/rendering.md).
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <quadtri/osd/vulkan_context.h>

namespace quadtri::render {

struct GpuDeviceOptions {
    // Extensions beyond the validation layer's (e.g. glfwGetRequiredInstanceExtensions' list).
    std::vector<std::string> instanceExtensions;
    // Device extensions, e.g. VK_KHR_swapchain; a device without them all is skipped.
    std::vector<std::string> deviceExtensions;
    // Whether queue family `family` of `device` can present (e.g. through
    // glfwGetPhysicalDevicePresentationSupport); unset: presentation is not needed.
    std::function<bool(VkInstance, VkPhysicalDevice, uint32_t family)> canPresent;
};

class GpuDevice {
public:
    // The first device (or the one QUADTRI_VK_DEVICE names, by index or name substring) with a
    // queue family doing graphics, compute and, if asked, presentation. QUADTRI_VK_VALIDATION=1
    // turns the Khronos validation layer on, with a messenger that prints and counts its
    // findings. Throws VulkanError, saying what is missing, when there is no driver or no such
    // device.
    explicit GpuDevice(const GpuDeviceOptions& options = {});
    ~GpuDevice();
    GpuDevice(const GpuDevice&) = delete;
    GpuDevice& operator=(const GpuDevice&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamilyIndex() const { return queueFamily_; }
    std::string deviceName() const;
    // quadtri's context over the handles above: the evaluators and the renderer use it.
    VulkanContext& context() { return *context_; }

    bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }
    // Warnings and errors the validation layer reported so far on this device's instance.
    int validationMessageCount() const { return messages_.load(); }
    // The same summed over every instance quadtri created in the process (GpuDevices and headless
    // VulkanContexts, destroyed ones included: messages from vkDestroyDevice / vkDestroyInstance
    // count too).
    static int totalValidationMessageCount();

private:
    void createInstance(const GpuDeviceOptions& options);
    void pickDevice(const GpuDeviceOptions& options);
    void createDevice(const GpuDeviceOptions& options);
    void destroy() noexcept;

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    std::atomic<int> messages_{0};  // counted by the messenger's callback
    std::unique_ptr<VulkanContext> context_;
};

}  // namespace quadtri::render
