// VkResult names and checks, and VulkanContext's device selection (QUADTRI_VK_DEVICE).
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string>
#include <vector>

#include <quadtri/osd/vulkan_context.h>

namespace quadtri {
inline namespace v0 {

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

const char* vkResultName(VkResult r) {
    switch (r) {
#define QUADTRI_CASE(x) case x: return #x;
    QUADTRI_CASE(VK_SUCCESS) QUADTRI_CASE(VK_NOT_READY) QUADTRI_CASE(VK_TIMEOUT) QUADTRI_CASE(VK_INCOMPLETE)
    QUADTRI_CASE(VK_ERROR_OUT_OF_HOST_MEMORY) QUADTRI_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    QUADTRI_CASE(VK_ERROR_INITIALIZATION_FAILED) QUADTRI_CASE(VK_ERROR_DEVICE_LOST)
    QUADTRI_CASE(VK_ERROR_MEMORY_MAP_FAILED) QUADTRI_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    QUADTRI_CASE(VK_ERROR_EXTENSION_NOT_PRESENT) QUADTRI_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    QUADTRI_CASE(VK_ERROR_INCOMPATIBLE_DRIVER) QUADTRI_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    QUADTRI_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED) QUADTRI_CASE(VK_ERROR_FRAGMENTED_POOL)
    QUADTRI_CASE(VK_ERROR_OUT_OF_POOL_MEMORY) QUADTRI_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    QUADTRI_CASE(VK_ERROR_UNKNOWN)
#undef QUADTRI_CASE
    default: return "VkResult(unknown)";
    }
}

void vkCheck(VkResult result, const char* call) {
    if (result != VK_SUCCESS)
        throw VulkanError(std::string(call) + " failed: " + vkResultName(result) + " (" + std::to_string(int(result)) + ")",
                          result);
}

int VulkanContext::computeQueueFamily(VkPhysicalDevice pd) {
    uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, families.data());
    for (uint32_t i = 0; i < n; ++i)
        if ((families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) && families[i].queueCount > 0) return int(i);
    return -1;
}

void VulkanContext::pickDevice() {
    uint32_t n = 0;
    vkCheck(vkEnumeratePhysicalDevices(instance_, &n, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(n);
    if (n) vkCheck(vkEnumeratePhysicalDevices(instance_, &n, devices.data()), "vkEnumeratePhysicalDevices");
    devices.resize(n);
    if (devices.empty()) throw VulkanError("no Vulkan device found (the driver reports no physical device)");

    auto usable = [](VkPhysicalDevice pd) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        return p.apiVersion >= VK_API_VERSION_1_1 && computeQueueFamily(pd) >= 0;
    };
    auto name = [](VkPhysicalDevice pd) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        return std::string(p.deviceName);
    };
    if (const char* want = std::getenv("QUADTRI_VK_DEVICE"); want && *want) {
        const std::string w(want);
        const bool isIndex = std::all_of(w.begin(), w.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
        // Digits are an index (compared as text, so that no number is too long); else a name part.
        const std::string index = isIndex ? w.substr(std::min(w.find_first_not_of('0'), w.size() - 1)) : w;
        std::string listing;
        for (size_t i = 0; i < devices.size(); ++i) {
            listing += (i ? ", " : "") + std::to_string(i) + " '" + name(devices[i]) + "'";
            const bool match = isIndex ? index == std::to_string(i) : lower(name(devices[i])).find(lower(w)) != std::string::npos;
            if (match && !physicalDevice_) physicalDevice_ = devices[i];
        }
        if (!physicalDevice_)
            throw VulkanError("QUADTRI_VK_DEVICE '" + w + "': no device " +
                              (isIndex ? "with that index" : "whose name contains it") + "; expected an index " +
                              (devices.size() == 1 ? "0" : "0.." + std::to_string(devices.size() - 1)) +
                              " or part of a name (" + listing + ")");
        if (!usable(physicalDevice_))
            throw VulkanError("Vulkan device '" + name(physicalDevice_) + "' lacks Vulkan 1.1 or a compute queue");
    } else {
        int best = -1;  // discrete, then integrated, then anything usable
        for (size_t i = 0; i < devices.size(); ++i) {
            if (!usable(devices[i])) continue;
            VkPhysicalDeviceProperties p;
            vkGetPhysicalDeviceProperties(devices[i], &p);
            const int rank = p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU     ? 3
                             : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU ? 2
                                                                                     : 1;
            if (rank > best) best = rank, physicalDevice_ = devices[i];
        }
        if (!physicalDevice_) throw VulkanError("no Vulkan 1.1 device with a compute queue found");
    }
    queueFamily_ = uint32_t(computeQueueFamily(physicalDevice_));
    vkGetPhysicalDeviceProperties(physicalDevice_, &properties_);
    vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memory_);
}

}  // namespace v0
}  // namespace quadtri
