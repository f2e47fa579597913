// The Vulkan side of quadtri's evaluators: an instance, device and compute queue, either created
// here (headless, Vulkan 1.1) or adopted from the caller (a game engine's own device), plus the
// compute pipelines of the stencil shader (shaders/stencil_eval.comp, embedded as SPIR-V).
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <quadtri/export.h>

namespace quadtri {
inline namespace v0 {

// A failed Vulkan call ("vkCreateDevice failed: VK_ERROR_OUT_OF_HOST_MEMORY"), or no usable
// driver or device.
class QUADTRI_API VulkanError : public std::runtime_error {
public:
    explicit VulkanError(const std::string& what, VkResult result = VK_SUCCESS)
        : std::runtime_error(what), result_(result) {}
    VkResult result() const { return result_; }

private:
    VkResult result_;
};

QUADTRI_API const char* vkResultName(VkResult result);

namespace detail {
// A zero-initialized Vulkan struct with its sType set.
template <class T>
T vkStruct(VkStructureType type) {
    T value{};
    value.sType = type;
    return value;
}
}  // namespace detail

// Throws VulkanError "<call> failed: <VkResult>" unless result is VK_SUCCESS.
QUADTRI_API void vkCheck(VkResult result, const char* call);

class QUADTRI_API VulkanContext {
public:
    // Handles owned by the caller; the context uses them and never destroys them. The queue must
    // belong to queueFamilyIndex and support compute; the device must be Vulkan 1.1 or newer.
    struct External {
        VkInstance instance = VK_NULL_HANDLE;
        VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
        VkDevice device = VK_NULL_HANDLE;
        VkQueue queue = VK_NULL_HANDLE;
        uint32_t queueFamilyIndex = 0;
    };

    // Creates a headless instance and device. Environment: QUADTRI_VK_VALIDATION=1 enables
    // VK_LAYER_KHRONOS_validation (when installed) with a messenger that prints and counts its
    // warnings and errors; QUADTRI_VK_DEVICE picks the device by index or by name substring;
    // QUADTRI_VK_NO_TEXEL_BUFFERS=1 makes the evaluators read everything through storage buffers
    // (texelBufferLimit() 0). Throws VulkanError when there is no driver or no device with a compute queue.
    VulkanContext();
    // Adopts the caller's handles (see External).
    explicit VulkanContext(const External& external);
    ~VulkanContext();
    VulkanContext(const VulkanContext&) = delete;
    VulkanContext& operator=(const VulkanContext&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamilyIndex() const { return queueFamily_; }
    bool ownsDevice() const { return ownsDevice_; }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    std::string deviceName() const { return properties_.deviceName; }

    // Validation: whether the layer is on, and how many warnings/errors (of the validation or
    // performance type) it reported so far.
    bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }
    int validationMessageCount() const { return validationMessages_.load(); }
    // The same summed over every instance quadtri created in the process, destroyed ones
    // included (messages from vkDestroyDevice / vkDestroyInstance count too).
    static int totalValidationMessageCount();

    // A memory type of the physical device allowed by typeBits with all of `required`.
    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const;

    // Records into a fresh primary command buffer of the context's pool, submits it to the
    // queue and waits on a fence. Not for use while another thread uses the queue.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record);

    // The stencil shader's layouts, and its pipeline for one (length, srcStride, dstStride),
    // created on first use and cached. stencilPipeline may be called from several threads at
    // once (evaluators of one context recording on different threads).
    VkDescriptorSetLayout descriptorSetLayout() const { return setLayout_; }
    VkPipelineLayout pipelineLayout() const { return pipelineLayout_; }
    VkPipeline stencilPipeline(int length, int srcStride, int dstStride);
    // The same, reading the table's pools (poolTexels) and the source (sourceTexels) through the
    // layout's texel-buffer bindings instead of its storage buffers (docs/decisions/0003-vulkan-on-lavapipe.md).
    VkPipeline stencilPipeline(int length, int srcStride, int dstStride, bool poolTexels, bool sourceTexels);
    uint32_t workgroupSize() const { return workgroupSize_; }
    // The most elements the evaluators read through one uniform texel buffer view (tables' pools,
    // VulkanVertexBuffer::texels()): min(maxTexelBufferElements, 2^31 - 1), texelFetch taking an
    // int; 0 under QUADTRI_VK_NO_TEXEL_BUFFERS=1 (adopted devices too).
    std::size_t texelBufferLimit() const { return texelBufferLimit_; }

private:
    static int computeQueueFamily(VkPhysicalDevice pd);  // first family with compute, or -1
    void createInstance();
    void pickDevice();
    void createDevice();
    void createShared();  // command pool, shader module, layouts
    void destroy() noexcept;

    VkInstance instance_ = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    bool ownsInstance_ = false, ownsDevice_ = false;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memory_{};

    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::atomic<int> validationMessages_{0};

    VkCommandPool commandPool_ = VK_NULL_HANDLE;
    VkShaderModule shader_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    uint32_t workgroupSize_ = 64;
    std::size_t texelBufferLimit_ = 0;
    struct CachedPipeline {
        int length, srcStride, dstStride;
        bool poolTexels, sourceTexels;
        VkPipeline pipeline;
    };
    std::vector<CachedPipeline> pipelines_;
    std::mutex pipelinesMutex_;  // guards pipelines_
};

}  // namespace v0
}  // namespace quadtri
