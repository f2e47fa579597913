#include "tools/render/gpu_device.h"

#include "osd/vulkan/vulkan_instance.h"

#include <cstdlib>

namespace quadtri::render {

namespace {

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

int GpuDevice::totalValidationMessageCount() { return detail::totalValidationMessages(); }

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
    const detail::ValidatedInstance created = detail::createValidatedInstance(pointers(options.instanceExtensions), &messages_);
    instance_ = created.instance;
    messenger_ = created.messenger;
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
    detail::ValidatedInstance owned{instance_, messenger_};
    detail::destroyValidatedInstance(owned);
    messenger_ = VK_NULL_HANDLE;
    instance_ = VK_NULL_HANDLE;
}

}  // namespace quadtri::render
