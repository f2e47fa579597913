// The Vulkan instance of quadtri's own devices (the headless VulkanContext, the tools' GpuDevice):
// Vulkan 1.1 and, when QUADTRI_VK_VALIDATION is set and the Khronos layer is installed, the
// validation layer with a messenger that prints its findings and counts them, per instance and
// over the process. One place, so that every device quadtri creates is checked the same way.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <vector>

namespace quadtri {
inline namespace v0 {
namespace detail {

struct ValidatedInstance {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;  // VK_NULL_HANDLE: validation off
};

// Creates the instance with `extensions` (and the debug-utils one under validation); each
// finding of the layer adds 1 to `*counter` and to totalValidationMessages(). `counter` must
// outlive the instance. Throws VulkanError naming a missing driver or instance extension.
ValidatedInstance createValidatedInstance(const std::vector<const char*>& extensions, std::atomic<int>* counter);
// Destroys the messenger, then the instance (either may be null).
void destroyValidatedInstance(ValidatedInstance& instance) noexcept;
// Findings counted by every messenger of the process so far, destroyed ones included.
int totalValidationMessages();
// Whether environment variable `name` is set to something other than "" or "0" (the
// QUADTRI_VK_* switches).
bool environmentFlag(const char* name);

}  // namespace detail
}  // namespace v0
}  // namespace quadtri
