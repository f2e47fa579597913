// The game-engine case: the test owns the VkInstance, VkDevice, queue, buffers, command buffer
// and fence; quadtri adopts them, records into the test's command buffer and never destroys
// the test's handles. The test's own validation messenger must stay silent.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/vulkan_evaluator.h>
#include "tests/test_support.h"
#include "tests/osd/vulkan_test_support.h"

namespace quadtri::test {
namespace {

int g_messages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL countMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                            VkDebugUtilsMessageTypeFlagsEXT types,
                                            const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    if (types & VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT) ++g_messages;
    std::fprintf(stderr, "engine validation: %s\n", data->pMessage);
    return VK_FALSE;
}

#define CHECK_VK(call) ASSERT_EQ((call), VK_SUCCESS) << #call

// What an engine owns: created and destroyed by the test.
struct Engine {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t family = 0;
};

// A host-visible storage buffer of the engine's.
struct EngineBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    float* data = nullptr;
};

void createEngine(Engine& e, bool& skipped) {
    skipped = false;
    const bool validation = validationLayerInstalled();
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.apiVersion = VK_API_VERSION_1_1;
    VkDebugUtilsMessengerCreateInfoEXT mi{};
    mi.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    mi.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    mi.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
    mi.pfnUserCallback = countMessage;
    VkInstanceCreateInfo ii{};
    ii.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    ii.pApplicationInfo = &app;
    ii.enabledLayerCount = validation ? 1 : 0;
    ii.ppEnabledLayerNames = &layer;
    ii.enabledExtensionCount = validation ? 1 : 0;
    ii.ppEnabledExtensionNames = &extension;
    const VkResult r = vkCreateInstance(&ii, nullptr, &e.instance);
    uint32_t n = 0;
    if (r == VK_SUCCESS) vkEnumeratePhysicalDevices(e.instance, &n, nullptr);
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER || (r == VK_SUCCESS && n == 0)) {
        skipped = true;
        return;
    }
    CHECK_VK(r);
    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(e.instance, "vkCreateDebugUtilsMessengerEXT"));
        CHECK_VK(create(e.instance, &mi, nullptr, &e.messenger));
    }
    std::vector<VkPhysicalDevice> devices(n);
    CHECK_VK(vkEnumeratePhysicalDevices(e.instance, &n, devices.data()));
    e.physical = devices[0];
    uint32_t nf = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(e.physical, &nf, nullptr);
    std::vector<VkQueueFamilyProperties> families(nf);
    vkGetPhysicalDeviceQueueFamilyProperties(e.physical, &nf, families.data());
    while (e.family < nf && !(families[e.family].queueFlags & VK_QUEUE_COMPUTE_BIT)) ++e.family;
    ASSERT_LT(e.family, nf) << "no compute queue";
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qi{};
    qi.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    qi.queueFamilyIndex = e.family;
    qi.queueCount = 1;
    qi.pQueuePriorities = &priority;
    VkDeviceCreateInfo di{};
    di.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    di.queueCreateInfoCount = 1;
    di.pQueueCreateInfos = &qi;
    CHECK_VK(vkCreateDevice(e.physical, &di, nullptr, &e.device));
    vkGetDeviceQueue(e.device, e.family, 0, &e.queue);
}

void createBuffer(const Engine& e, VkDeviceSize bytes, EngineBuffer& b) {
    VkBufferCreateInfo bi{};
    bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    bi.size = bytes;
    bi.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    CHECK_VK(vkCreateBuffer(e.device, &bi, nullptr, &b.buffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(e.device, b.buffer, &req);
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(e.physical, &mp);
    const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    uint32_t type = 0;
    while (type < mp.memoryTypeCount &&
           !((req.memoryTypeBits & (1u << type)) && (mp.memoryTypes[type].propertyFlags & want) == want))
        ++type;
    ASSERT_LT(type, mp.memoryTypeCount);
    VkMemoryAllocateInfo ai{};
    ai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = type;
    CHECK_VK(vkAllocateMemory(e.device, &ai, nullptr, &b.memory));
    CHECK_VK(vkBindBufferMemory(e.device, b.buffer, b.memory, 0));
    void* p = nullptr;
    CHECK_VK(vkMapMemory(e.device, b.memory, 0, VK_WHOLE_SIZE, 0, &p));
    b.data = static_cast<float*>(p);
}

TEST(VulkanAdoption, RecordsIntoTheEnginesCommandBuffer) {
    Engine e;
    bool skipped = false;
    createEngine(e, skipped);
    if (skipped) {
        if (e.instance) vkDestroyInstance(e.instance, nullptr);
        if (vulkanRequired()) FAIL() << "QUADTRI_REQUIRE_VULKAN is set but there is no Vulkan device";
        GTEST_SKIP() << "no Vulkan device; set QUADTRI_REQUIRE_VULKAN=1 to fail instead";
    }
    ASSERT_TRUE(e.device);
    pinVulkanLibraries();
    const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 2);
    const StencilTable& level1 = r.refiner->levelStencils(1);
    const StencilTable level2 = r.refiner->factorizedStencils(2);
    const int n0 = r.mesh.numVertices(), n1 = level1.numStencils(), n2 = level2.numStencils();
    const BufferDescriptor d(0, 3, 3);
    // Source at byte 12 (not a storage-buffer offset alignment), level 1 and level 2 after it.
    const VkDeviceSize srcAt = 12, dst1At = 4096 + 4, dst2At = 8192 + 4 * (3 * std::size_t(n1) + 1);
    EngineBuffer src, dst;
    createBuffer(e, srcAt + 12 * VkDeviceSize(n0), src);
    createBuffer(e, dst2At + 12 * VkDeviceSize(n2), dst);
    std::memcpy(reinterpret_cast<char*>(src.data) + srcAt, r.mesh.positions.data(), 12 * std::size_t(n0));
    {
        VulkanContext ctx(VulkanContext::External{e.instance, e.physical, e.device, e.queue, e.family});
        EXPECT_FALSE(ctx.ownsDevice());
        VulkanStencilTable t1(ctx, level1), t2(ctx, level2);
        VulkanEvaluator evaluator(ctx);

        VkCommandPoolCreateInfo pi{};
        pi.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
        pi.queueFamilyIndex = e.family;
        VkCommandPool pool;
        CHECK_VK(vkCreateCommandPool(e.device, &pi, nullptr, &pool));
        VkCommandBufferAllocateInfo ai{};
        ai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
        ai.commandPool = pool;
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = 1;
        VkCommandBuffer cmd;
        CHECK_VK(vkAllocateCommandBuffers(e.device, &ai, &cmd));
        VkCommandBufferBeginInfo bi{};
        bi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
        CHECK_VK(vkBeginCommandBuffer(cmd, &bi));
        evaluator.EvalStencils(cmd, {src.buffer, srcAt}, d, {dst.buffer, dst1At}, d, t1);
        evaluator.EvalStencils(cmd, {src.buffer, srcAt}, d, {dst.buffer, dst2At}, d, t2);
        CHECK_VK(vkEndCommandBuffer(cmd));
        VkFenceCreateInfo fi{};
        fi.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
        VkFence fence;
        CHECK_VK(vkCreateFence(e.device, &fi, nullptr, &fence));
        VkSubmitInfo si{};
        si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
        si.commandBufferCount = 1;
        si.pCommandBuffers = &cmd;
        CHECK_VK(vkQueueSubmit(e.queue, 1, &si, fence));
        CHECK_VK(vkWaitForFences(e.device, 1, &fence, VK_TRUE, UINT64_MAX));
        evaluator.resetDescriptorSets();
        vkDestroyFence(e.device, fence, nullptr);
        vkDestroyCommandPool(e.device, pool, nullptr);
    }
    const double tol = 1e-5 * boundingBoxDiagonal(r.mesh.positions);
    std::vector<float> want1(3 * std::size_t(n1)), want2(3 * std::size_t(n2));
    CpuEvaluator::EvalStencils(r.mesh.positions.data(), d, want1.data(), d, level1);
    CpuEvaluator::EvalStencils(r.mesh.positions.data(), d, want2.data(), d, level2);
    const float* got1 = reinterpret_cast<const float*>(reinterpret_cast<const char*>(dst.data) + dst1At);
    const float* got2 = reinterpret_cast<const float*>(reinterpret_cast<const char*>(dst.data) + dst2At);
    for (std::size_t i = 0; i < want1.size(); ++i) ASSERT_NEAR(got1[i], want1[i], tol) << "level 1 float " << i;
    for (std::size_t i = 0; i < want2.size(); ++i) ASSERT_NEAR(got2[i], want2[i], tol) << "level 2 float " << i;

    // Everything quadtri created is gone: the layer would report leaks at vkDestroyDevice.
    for (EngineBuffer* b : {&src, &dst}) {
        vkDestroyBuffer(e.device, b->buffer, nullptr);
        vkFreeMemory(e.device, b->memory, nullptr);
    }
    vkDestroyDevice(e.device, nullptr);
    if (e.messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(e.instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(e.instance, e.messenger, nullptr);
    }
    vkDestroyInstance(e.instance, nullptr);
    if (vulkanRequired()) {
        EXPECT_TRUE(e.messenger) << "the Khronos validation layer is not installed";
    }
    EXPECT_EQ(g_messages, 0) << "the validation layer reported problems (above)";
}

}  // namespace
}  // namespace quadtri::test
