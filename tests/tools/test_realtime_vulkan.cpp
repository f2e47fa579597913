// The real-time loop on Vulkan (lavapipe here, validation on): the same frame through
// CpuEvaluator and VulkanFrameEvaluator agrees within 1e-5 on every table route (the normals of
// the per-level route within 1e-4), and recording
// the cage's upload and the evaluation into a caller's command buffer (as a renderer does) gives
// the same outputs.
#include <gtest/gtest.h>

#include "tests/tools/realtime_support.h"
#include "tests/osd/vulkan_test_support.h"
#include "tools/realtime/deforming_surface.h"
#include "tools/realtime/host_frame_evaluator.h"
#include "tools/realtime/vulkan_frame_evaluator.h"

namespace quadtri::test {
namespace {

using realtime::TableRoute;

class RealtimeVulkan : public VulkanTest {};

TEST_F(RealtimeVulkan, SameFrameAsTheCpuWithinRoundingOnEveryRoute) {
    const DemoCage cage = loadDemoCage(1);
    for (TableRoute route : {TableRoute::FactorizedLimit, TableRoute::LevelsThenLimit, TableRoute::Patches}) {
        const realtime::SurfaceTables tables(*cage.refiner, 1, route);
        realtime::DeformingSurface surface{realtime::TwoBoneSkin(cage.mesh.positions)};
        realtime::HostFrameEvaluator cpu(tables, false);
        realtime::VulkanFrameEvaluator vulkan(*ctx, tables);
        // On the per-level route the host's stencil loop (fused multiply-adds where the CPU has
        // them: docs/stencil_kernel.md) and the shader's (a multiply and an add) round the level's
        // points differently by an ulp; the limit normal, from differences of neighbouring points,
        // magnifies that by the inverse of the level's edge length.
        const float normalTolerance = route == TableRoute::LevelsThenLimit ? 1e-4f : 1e-5f;
        std::vector<float> p0, n0, p1, n1;
        for (float radians : {0.0f, 0.6f, 1.75f}) {
            surface.frame(cpu, radians);
            surface.frame(vulkan, radians);
            cpu.readBack(p0, n0);
            vulkan.readBack(p1, n1);
            EXPECT_LT(maxDifference(p0, p1), 1e-5f) << realtime::toString(route) << " at " << radians;
            EXPECT_LT(maxDifference(n0, n1), normalTolerance) << realtime::toString(route) << " at " << radians;
        }
        // The renderer's way: the cage's upload and the evaluation recorded into its own command
        // buffer, one submission.
        std::vector<float> bent(cage.mesh.positions.size());
        surface.skin().pose(0.9f, bent.data());
        ctx->submitAndWait([&](VkCommandBuffer cmd) {
            vulkan.recordCage(cmd, bent.data());
            vulkan.record(cmd);
        });
        vulkan.resetDescriptorSets();
        vulkan.readBack(p1, n1);
        surface.frame(vulkan, 0.9f);
        vulkan.readBack(p0, n0);
        EXPECT_EQ(p0, p1) << realtime::toString(route);
        EXPECT_EQ(n0, n1) << realtime::toString(route);
        EXPECT_EQ(vulkan.positions().numElements(), tables.numPoints);
    }
}

}  // namespace
}  // namespace quadtri::test
