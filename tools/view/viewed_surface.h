// One viewport's surface: the Refiner of the document's cage under one set of options, the
// real-time loop's tables and evaluator (CPU, oneTBB or Vulkan on the viewer's device), the
// two-bone skin, and the Renderer that draws it all (docs/viewer.md).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <quadtri/far/refiner.h>
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
    std::string routeDescription() const { return tables_ ? realtime::toString(tables_->route) : ""; }
    bool ready() const { return refiner_ != nullptr; }

    // The cage posed at `radians` (0: rest) through the evaluator into the draw's buffers, the
    // cage's colours from `selection`; with `curvature` the mean curvature for its shading too.
    // Returns the phase times (deform, evaluate, normals).
    realtime::PhaseTimes update(float radians, const std::vector<std::pair<int, int>>& selectedEdges,
                                const std::vector<int>& selectedVertices, bool curvature);

    render::Renderer& renderer() { return renderer_; }
    const Refiner& refiner() const { return *refiner_; }
    // The cage as posed by the last update (3 floats per vertex), and its edges (2 per edge).
    const std::vector<float>& cage() const { return cage_; }
    const std::vector<uint32_t>& edges() const { return edges_; }
    float curvatureRange() const { return curvatureRange_; }
    // Why the cage cannot bend (a flat cage), empty when it can.
    const std::string& skinProblem() const { return skinProblem_; }

private:
    VulkanContext& ctx_;
    render::Renderer renderer_;
    std::unique_ptr<Refiner> refiner_;
    std::unique_ptr<realtime::SurfaceTables> tables_;
    std::unique_ptr<realtime::FrameEvaluator> evaluator_;
    std::optional<realtime::TwoBoneSkin> skin_;
    std::string skinProblem_;
    std::vector<float> rest_, cage_;
    std::vector<uint32_t> edges_;
    int level_ = 0;
    bool onDevice_ = false;
    // On the device under the patch route: each level vertex's element in the evaluator's
    // buffers (the patch table's order), which the draw and the curvature follow; else empty.
    std::vector<int> elementOfVertex_;
    float curvatureRange_ = 0.0f;  // until a curvature update
};

}  // namespace quadtri::view
