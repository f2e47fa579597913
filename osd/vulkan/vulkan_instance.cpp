#include "osd/vulkan/vulkan_instance.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <quadtri/osd/vulkan_context.h>

namespace quadtri {
inline namespace v0 {
namespace detail {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasLayer(const char* name) {
    uint32_t n = 0;
    if (vkEnumerateInstanceLayerProperties(&n, nullptr) != VK_SUCCESS) return false;
    std::vector<VkLayerProperties> layers(n);
    if (vkEnumerateInstanceLayerProperties(&n, layers.data()) != VK_SUCCESS) return false;
    for (const auto& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

std::atomic<int>& totalMessages() {
    static std::atomic<int> count{0};
    return count;
}

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT types,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void* counter) {
    // Every message is printed; the layer's findings are counted, not the loader's own
    // (general) messages such as a missing driver.
    if (types & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT)) {
        static_cast<std::atomic<int>*>(counter)->fetch_add(1);
        totalMessages().fetch_add(1);
    }
    std::fprintf(stderr, "quadtri: Vulkan validation %s: %s\n",
                 severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning",
                 data && data->pMessage ? data->pMessage : "(no message)");
    return VK_FALSE;
}

}  // namespace

int totalValidationMessages() { return totalMessages().load(); }

bool environmentFlag(const char* name) {
    const char* v = std::getenv(name);
    return v && *v && std::strcmp(v, "0") != 0;
}

ValidatedInstance createValidatedInstance(const std::vector<const char*>& extensions, std::atomic<int>* counter) {
    auto app = vkStruct<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "quadtri";
    app.pEngineName = "quadtri";
    app.apiVersion = VK_API_VERSION_1_1;

    const bool validation = environmentFlag("QUADTRI_VK_VALIDATION") && hasLayer(kValidationLayer);
    if (environmentFlag("QUADTRI_VK_VALIDATION") && !validation)
        std::fprintf(stderr, "quadtri: QUADTRI_VK_VALIDATION is set but %s is not installed\n", kValidationLayer);
    std::vector<const char*> enabled = extensions;
    std::vector<const char*> layers;
    if (validation) {
        enabled.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        layers.push_back(kValidationLayer);
    }

    auto msg = vkStruct<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    msg.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    msg.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                      VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    msg.pfnUserCallback = &onMessage;
    msg.pUserData = counter;

    auto info = vkStruct<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    info.pApplicationInfo = &app;
    if (validation) info.pNext = &msg;  // also covers vkCreateInstance / vkDestroyInstance themselves
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(enabled.size());
    info.ppEnabledExtensionNames = enabled.data();
    ValidatedInstance result;
    const VkResult r = vkCreateInstance(&info, nullptr, &result.instance);
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw VulkanError("no Vulkan driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER); install one, "
                          "e.g. Debian's mesa-vulkan-drivers for the lavapipe CPU driver", r);
    if (r == VK_ERROR_EXTENSION_NOT_PRESENT) {
        std::string names;
        for (const char* e : extensions) names += std::string(names.empty() ? "" : ", ") + e;
        throw VulkanError("the Vulkan driver lacks an instance extension of " + names +
                          " (vkCreateInstance: VK_ERROR_EXTENSION_NOT_PRESENT)", r);
    }
    vkCheck(r, "vkCreateInstance");
    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(result.instance, "vkCreateDebugUtilsMessengerEXT"));
        const VkResult m = create ? create(result.instance, &msg, nullptr, &result.messenger)
                                  : VK_ERROR_EXTENSION_NOT_PRESENT;
        if (m != VK_SUCCESS) {
            vkDestroyInstance(result.instance, nullptr);
            vkCheck(m, "vkCreateDebugUtilsMessengerEXT");
        }
    }
    return result;
}

void destroyValidatedInstance(ValidatedInstance& instance) noexcept {
    if (!instance.instance) return;
    if (instance.messenger) {
        auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance.instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroyMessenger) destroyMessenger(instance.instance, instance.messenger, nullptr);
    }
    vkDestroyInstance(instance.instance, nullptr);
    instance = {};
}

}  // namespace detail
}  // namespace v0
}  // namespace quadtri
