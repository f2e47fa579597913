#include "tests/osd/vulkan_test_support.h"

#include <dlfcn.h>
#include <link.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace quadtri::test {

bool vulkanRequired() {
    const char* v = std::getenv("QUADTRI_REQUIRE_VULKAN");
    return v && *v && std::strcmp(v, "0") != 0;
}

void enableValidation() { setenv("QUADTRI_VK_VALIDATION", "1", /*overwrite=*/0); }

bool validationLayerInstalled() {
    uint32_t n = 0;
    if (vkEnumerateInstanceLayerProperties(&n, nullptr) != VK_SUCCESS) return false;
    std::vector<VkLayerProperties> layers(n);
    if (vkEnumerateInstanceLayerProperties(&n, layers.data()) != VK_SUCCESS) return false;
    for (const auto& l : layers)
        if (std::strcmp(l.layerName, "VK_LAYER_KHRONOS_validation") == 0) return true;
    return false;
}

void pinVulkanLibraries() {
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void*) {
            const std::string path = info->dlpi_name ? info->dlpi_name : "";
            const std::string file = path.substr(path.find_last_of('/') + 1);
            if (file.rfind("libvulkan_", 0) == 0 || file.rfind("libVkLayer_", 0) == 0)
                dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);  // a reference never released
            return 0;
        },
        nullptr);
}

void VulkanTest::SetUp() {
    enableValidation();
    try {
        ctx = std::make_unique<VulkanContext>();
    } catch (const VulkanError& e) {
        if (vulkanRequired()) FAIL() << "QUADTRI_REQUIRE_VULKAN is set but Vulkan is unusable: " << e.what();
        GTEST_SKIP() << "no Vulkan device (" << e.what() << "); set QUADTRI_REQUIRE_VULKAN=1 to fail instead";
    }
    pinVulkanLibraries();
    std::printf("Vulkan device: %s, validation layer %s\n", ctx->deviceName().c_str(),
                ctx->validationEnabled() ? "on" : "off");
    if (vulkanRequired()) {
        EXPECT_TRUE(ctx->validationEnabled()) << "the Khronos validation layer is not installed";
    }
}

void VulkanTest::TearDown() {
    if (!ctx) return;  // skipped or failed in SetUp
    ctx.reset();
    EXPECT_EQ(VulkanContext::totalValidationMessageCount(), 0) << "the validation layer reported problems (above)";
}

std::vector<float> primvar(const std::vector<float>& xyz, int width) {
    const std::size_t n = xyz.size() / 3;
    std::vector<float> out(n * std::size_t(width));
    for (std::size_t v = 0; v < n; ++v)
        for (int c = 0; c < width; ++c)
            out[v * width + c] = xyz[3 * v + c % 3] + 0.5f * float(c / 3) * xyz[3 * v + (c + 1) % 3];
    return out;
}

std::vector<float> layout(const std::vector<float>& values, const BufferDescriptor& d, int count, float fill) {
    std::vector<float> out(layoutFloats(d, count), fill);
    for (int i = 0; i < count && std::size_t(i + 1) * d.length <= values.size(); ++i)
        for (int c = 0; c < d.length; ++c) out[d.offset + std::size_t(i) * d.stride + c] = values[std::size_t(i) * d.length + c];
    return out;
}

void expectSameLayout(const std::vector<float>& a, const std::vector<float>& b, const BufferDescriptor& d,
                      double tol, const std::string& what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    int bad = 0;
    for (std::size_t f = 0; f < a.size() && bad < 5; ++f) {
        const bool data = f >= std::size_t(d.offset) && (f - d.offset) % d.stride < std::size_t(d.length);
        const bool ok = data ? std::fabs(double(a[f]) - double(b[f])) <= tol : std::memcmp(&a[f], &b[f], sizeof(float)) == 0;
        if (!ok) {
            ++bad;
            ADD_FAILURE() << what << ": float " << f << " (" << (data ? "data" : "padding") << ") " << a[f]
                          << " vs " << b[f] << ", tolerance " << tol;
        }
    }
}

VulkanVertexBuffer uploadPadded(VulkanContext& ctx, const std::vector<float>& data, int stride, float fill) {
    const int elements = int((data.size() + std::size_t(stride) - 1) / std::size_t(stride));
    std::vector<float> padded(std::size_t(elements) * std::size_t(stride), fill);
    std::copy(data.begin(), data.end(), padded.begin());
    VulkanVertexBuffer b = VulkanVertexBuffer::create(ctx, elements, stride);
    b.updateData(padded.data(), 0, elements);
    return b;
}

std::vector<float> downloadFloats(const VulkanVertexBuffer& b, std::size_t floats) {
    std::vector<float> out(b.numFloats());
    b.readBack(out.data());
    out.resize(floats);
    return out;
}

}  // namespace quadtri::test
