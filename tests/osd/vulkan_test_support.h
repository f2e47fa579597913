// Shared by the Vulkan tests: a fixture that opens a VulkanContext with the Khronos validation
// layer on (skipping, with the reason, when there is no Vulkan device unless
// QUADTRI_REQUIRE_VULKAN is set) and checks that the layer reported nothing.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include <quadtri/osd/buffer_descriptor.h>
#include <quadtri/osd/vulkan_buffer.h>
#include <quadtri/osd/vulkan_context.h>

namespace quadtri::test {

// Whether QUADTRI_REQUIRE_VULKAN is set (CI): then a missing device fails instead of skipping.
bool vulkanRequired();
// Turns validation on for the contexts the tests create (QUADTRI_VK_VALIDATION=1 unless set).
void enableValidation();
// Whether the Khronos validation layer is installed.
bool validationLayerInstalled();

// Keeps the Vulkan driver and layer libraries the loader has opened (libvulkan_*.so,
// libVkLayer_*.so) loaded until the process exits. vkDestroyInstance dlcloses them, and
// LeakSanitizer then reports the blocks their globals still pointed at as leaks from an
// "<unknown module>" (lavapipe: 128 bytes), which no suppression can name. Pinned, they are
// reachable and nothing is reported.
void pinVulkanLibraries();

class VulkanTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;  // destroys ctx, then expects no validation message at all
    std::unique_ptr<VulkanContext> ctx;
};

// Floats of a buffer holding `count` elements laid out by `d` (offset, then count strides).
inline std::size_t layoutFloats(const BufferDescriptor& d, int count) {
    return std::size_t(d.offset) + std::size_t(count) * std::size_t(d.stride);
}

// A buffer of `stride`-float elements holding `data` from float 0, the last element's floats
// past it `fill`.
VulkanVertexBuffer uploadPadded(VulkanContext& ctx, const std::vector<float>& data, int stride, float fill);
// The first `floats` floats of `b`.
std::vector<float> downloadFloats(const VulkanVertexBuffer& b, std::size_t floats);

// Per-vertex data of `width` floats derived from 3-float positions (same scale as the mesh).
std::vector<float> primvar(const std::vector<float>& xyz, int width);

// `values` (width floats per element, packed) laid out by `d` over `count` elements; every other
// float is `fill`.
std::vector<float> layout(const std::vector<float>& values, const BufferDescriptor& d, int count, float fill);

// Expects a == b: within `tol` on the first d.length floats of every element, bitwise equal
// everywhere else (offset floats and padding).
void expectSameLayout(const std::vector<float>& a, const std::vector<float>& b, const BufferDescriptor& d,
                      double tol, const std::string& what);

}  // namespace quadtri::test
