#include "tools/render/gpu_device.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace quadtri::render {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool envFlag(const char* name) {
    const char* v = std::getenv(name);
    return v && *v && std::strcmp(v, "0") != 0;
}

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
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    // The layer's findings are counted, not the loader's general messages.
    if (types & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT)) {
        static_cast<std::atomic<int>*>(user)->fetch_add(1);
        totalMessages().fetch_add(1);
    }
    std::fprintf(stderr, "quadtri: Vulkan validation %s: %s\n",
                 severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning",
                 data && data->pMessage ? data->pMessage : "(no message)");
    return VK_FALSE;
}

bool hasExtensions(VkPhysicalDevice pd, const std::vector<std::string>& wanted) {
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> all(n);
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, all.data());
    for (const std::string& w : wanted) {
        bool found = false;
        for (const auto& e : all) found = found || w == e.extensionName;
        if (!found) return false;
    }
    return true;
}

std::vector<const char*> pointers(const std::vector<std::string>& names) {
    std::vector<const char*> out;
    for (const std::string& n : names) out.push_back(n.c_str());
    return out;
}

}  // namespace

int GpuDevice::totalValidationMessageCount() { return totalMessages().load(); }

GpuDevice::GpuDevice(const GpuDeviceOptions& options) {
    try {
        createInstance(options);
        pickDevice(options);
        createDevice(options);
        context_ = std::make_unique<VulkanContext>(
            VulkanContext::External{instance_, physicalDevice_, device_, queue_, queueFamily_});
    } catch (...) {
        destroy();
        throw;
    }
}

GpuDevice::~GpuDevice() { destroy(); }

std::string GpuDevice::deviceName() const { return context_->deviceName(); }

void GpuDevice::createInstance(const GpuDeviceOptions& options) {
    auto app = detail::vkStruct<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "quadtri";
    app.pEngineName = "quadtri";
    app.apiVersion = VK_API_VERSION_1_1;

    const bool validation = envFlag("QUADTRI_VK_VALIDATION") && hasLayer(kValidationLayer);
    if (envFlag("QUADTRI_VK_VALIDATION") && !validation)
        std::fprintf(stderr, "quadtri: QUADTRI_VK_VALIDATION is set but %s is not installed\n", kValidationLayer);
    std::vector<const char*> extensions = pointers(options.instanceExtensions);
    std::vector<const char*> layers;
    if (validation) {
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        layers.push_back(kValidationLayer);
    }

    auto msg =
        detail::vkStruct<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    msg.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    msg.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                      VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    msg.pfnUserCallback = &onMessage;
    msg.pUserData = &messages_;

    auto info = detail::vkStruct<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    info.pApplicationInfo = &app;
    if (validation) info.pNext = &msg;  // also covers vkCreateInstance / vkDestroyInstance
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    const VkResult r = vkCreateInstance(&info, nullptr, &instance_);
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw VulkanError(
            "no Vulkan driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER); install one, "
            "e.g. Debian's mesa-vulkan-drivers for the lavapipe CPU driver",
            r);
    if (r == VK_ERROR_EXTENSION_NOT_PRESENT)
        throw VulkanError("the Vulkan driver lacks an instance extension the window needs", r);
    vkCheck(r, "vkCreateInstance");
    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (!create) throw VulkanError("vkCreateDebugUtilsMessengerEXT not available");
        vkCheck(create(instance_, &msg, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
    }
}

void GpuDevice::pickDevice(const GpuDeviceOptions& options) {
    uint32_t n = 0;
    vkCheck(vkEnumeratePhysicalDevices(instance_, &n, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(n);
    vkCheck(vkEnumeratePhysicalDevices(instance_, &n, devices.data()), "vkEnumeratePhysicalDevices");
    if (devices.empty()) throw VulkanError("no Vulkan device found");
    const char* wanted = std::getenv("QUADTRI_VK_DEVICE");
    const std::string want = wanted ? wanted : "";
    for (uint32_t d = 0; d < n; ++d) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(devices[d], &props);
        if (!want.empty() && want != std::to_string(d) && std::string(props.deviceName).find(want) == std::string::npos)
            continue;
        if (props.apiVersion < VK_API_VERSION_1_1 || !hasExtensions(devices[d], options.deviceExtensions)) continue;
        uint32_t nf = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(devices[d], &nf, nullptr);
        std::vector<VkQueueFamilyProperties> families(nf);
        vkGetPhysicalDeviceQueueFamilyProperties(devices[d], &nf, families.data());
        for (uint32_t f = 0; f < nf; ++f) {
            const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
            if ((families[f].queueFlags & need) != need) continue;
            if (options.canPresent && !options.canPresent(instance_, devices[d], f)) continue;
            physicalDevice_ = devices[d];
            queueFamily_ = f;
            return;
        }
    }
    std::string what = "no Vulkan device with a queue family for graphics and compute";
    if (options.canPresent) what += " that can present to the window";
    if (!options.deviceExtensions.empty()) what += " and the extension " + options.deviceExtensions[0];
    if (!want.empty()) what += " matches QUADTRI_VK_DEVICE=" + want;
    throw VulkanError(what);
}

void GpuDevice::createDevice(const GpuDeviceOptions& options) {
    const float priority = 1.0f;
    auto q = detail::vkStruct<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    q.queueFamilyIndex = queueFamily_;
    q.queueCount = 1;
    q.pQueuePriorities = &priority;
    const std::vector<const char*> extensions = pointers(options.deviceExtensions);
    auto info = detail::vkStruct<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &q;
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    vkCheck(vkCreateDevice(physicalDevice_, &info, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
}

void GpuDevice::destroy() noexcept {
    context_.reset();  // its pipelines and pool go before the device
    if (device_) vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
    if (instance_) {
        if (messenger_) {
            auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
            if (destroyMessenger) destroyMessenger(instance_, messenger_, nullptr);
            messenger_ = VK_NULL_HANDLE;
        }
        vkDestroyInstance(instance_, nullptr);
    }
    instance_ = VK_NULL_HANDLE;
}

}  // namespace quadtri::render
