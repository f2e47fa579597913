// One viewport's surface: the Refiner of the document's cage under one set of options, the
// real-time loop's tables and evaluator (CPU, oneTBB or Vulkan on the viewer's device), the
// two-bone skin, and the Renderer that draws it all (docs/viewer.md).
#pragma once

#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <quadtri/far/limit_surface.h>
#include <quadtri/far/limit_table_update.h>
#include <quadtri/far/refiner.h>
#include <quadtri/far/tessellation.h>
#include <quadtri/osd/vulkan_buffer.h>
#include <quadtri/osd/vulkan_limit_evaluator.h>
#include <quadtri/osd/vulkan_limit_tables.h>
#include "tools/commands.h"
#include "tools/realtime/frame_evaluator.h"
#include "tools/realtime/surface_tables.h"
#include "tools/realtime/two_bone_skin.h"
#include "tools/render/renderer.h"

namespace quadtri::view {

class ViewedSurface {
public:
    ViewedSurface(VulkanContext& ctx, VkRenderPass renderPass, const render::Image* texture);

    // Refines `mesh` under `options` to `level` and uploads what the draw reads; the evaluator
    // `kind` then runs each update through `route`'s tables. Throws the Refiner's errors (TopologyError, MemoryBudgetError)
    // and leaves the previous surface in place when it does.
    void rebuild(const io::ObjMesh& mesh, const Options& options, int level, cli::EvaluatorKind kind,
                 realtime::TableRoute route = realtime::TableRoute::FactorizedLimit);
    // The route the tables took (the panel shows it): the one asked for, or the per-level route
    // where the budget refused the factorized table or at level 0.
    // The edits (the cage's sharpness and holes) applied in place (Refiner::applyEdits): the
    // tables and the draw's buffers updated, not rebuilt (docs/edits.md, "In the viewer").
    // Returns the milliseconds it took. Throws the Refiner's TopologyError for an edit it refuses,
    // the surface unchanged.
    double edit(const TagEdits& edits);
    std::string routeDescription() const { return tables_ ? realtime::toString(tables_->route) : ""; }
    bool ready() const { return refiner_ != nullptr; }

    // The cage posed at `radians` (0: rest) through the evaluator into the draw's buffers, the
    // cage's colours from `selection`; with `curvature` the mean curvature for its shading too.
    // Returns the phase times (deform, evaluate, normals).
    realtime::PhaseTimes update(float radians, const std::vector<std::pair<int, int>>& selectedEdges,
                                const std::vector<int>& selectedVertices, bool curvature);

    // Adaptive tessellation (docs/viewer.md): instead of the uniform level, every base face cut
    // at a rate per edge, the cage edge's projected length (at rest: the bend does not change
    // the rates) in `extent` under `view` over
    // `pixelsPerSegment`, rounded up to a power of two (1 to kMaxAdaptiveRate), evaluated by the
    // surface's evaluator (on the device, into the buffers the draw reads). Rebuilds the
    // tessellation and its stencil table where a rate changed; returns whether it did (the next
    // update evaluates it). A rebuild goes back to the level.
    static constexpr int kMaxAdaptiveRate = 64;
    bool adapt(const render::ViewSettings& view, VkExtent2D extent, float pixelsPerSegment);
    bool adaptive() const { return tessellation_ != nullptr; }
    // "rates 1-16 per edge, 123456 triangles" while adaptive, else empty.
    std::string adaptiveSummary() const;

    render::Renderer& renderer() { return renderer_; }
    const Refiner& refiner() const { return *refiner_; }
    // The cage as posed by the last update (3 floats per vertex), and its edges (2 per edge).
    const std::vector<float>& cage() const { return cage_; }
    const std::vector<uint32_t>& edges() const { return edges_; }
    float curvatureRange() const { return curvatureRange_; }
    // Why the cage cannot bend (a flat cage), empty when it can.
    const std::string& skinProblem() const { return skinProblem_; }

private:
    // The evaluator's outputs given to the renderer (zeros on the host until the first update).
    void bindVertices();
    // The level drawn again (its faces, `uvs` and the evaluator's buffers), the adaptive
    // tessellation let go.
    void present(const std::vector<float>& uvs);
    // The posed cage with the selection's colours.
    void showCage(const std::vector<std::pair<int, int>>& selectedEdges, const std::vector<int>& selectedVertices);

    VulkanContext& ctx_;
    render::Renderer renderer_;
    std::unique_ptr<Refiner> refiner_;
    std::unique_ptr<realtime::SurfaceTables> tables_;
    std::unique_ptr<realtime::FrameEvaluator> evaluator_;
    std::unique_ptr<LimitTableUpdate> limitUpdate_;  // taken from pendingLimitUpdate_ at the first edit
    std::future<std::unique_ptr<LimitTableUpdate>> pendingLimitUpdate_;  // made after refiner_: goes first
    std::vector<float> controlUVs_;
    std::optional<realtime::TwoBoneSkin> skin_;
    std::string skinProblem_;
    std::vector<float> rest_, cage_;
    std::vector<uint32_t> edges_;
    int level_ = 0;
    bool onDevice_ = false;
    // Adaptive tessellation: the surface (made on first use), the rates, the tessellation, its
    // stencils over the cage, and the evaluated points.
    std::unique_ptr<LimitSurface> limitSurface_;
    std::vector<int> edgeRates_;
    std::unique_ptr<Tessellation> tessellation_;
    LimitStencilTable tessellationTable_;
    std::vector<float> tessellationPositions_, tessellationNormals_;
    // The same on the device: the cage, the table and the outputs the draw reads.
    struct DeviceTessellation {
        VulkanLimitStencilTable table;
        VulkanVertexBuffer cage, positions, normals;
    };
    std::unique_ptr<DeviceTessellation> deviceTessellation_;
    std::unique_ptr<VulkanLimitEvaluator> limitEvaluator_;  // made on first use
    cli::EvaluatorKind kind_ = cli::EvaluatorKind::Cpu;
    // On the device under the patch route: each level vertex's element in the evaluator's
    // buffers (the patch table's order), which the draw and the curvature follow; else empty.
    std::vector<int> elementOfVertex_;
    float curvatureRange_ = 0.0f;  // until a curvature update
};

}  // namespace quadtri::view
