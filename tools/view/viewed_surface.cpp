#include "tools/view/viewed_surface.h"

#include <chrono>

#include "tools/realtime/host_frame_evaluator.h"
#include "tools/realtime/vulkan_frame_evaluator.h"
#include "tools/render/level_surface.h"
#include "tools/render/surface_data.h"

namespace quadtri::view {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The edge between a and b in `level0`, or -1.
int edgeBetween(const Topology& level0, int a, int b) {
    for (int e = 0; e < level0.numEdges(); ++e) {
        const int p = level0.edgeVerts[2 * std::size_t(e)], q = level0.edgeVerts[2 * std::size_t(e) + 1];
        if ((p == a && q == b) || (p == b && q == a)) return e;
    }
    return -1;
}

}  // namespace

ViewedSurface::ViewedSurface(VulkanContext& ctx, VkRenderPass renderPass, const render::Image* texture)
    : ctx_(ctx), renderer_(ctx, renderPass) {
    renderer_.setTexture(texture);
}

void ViewedSurface::rebuild(const io::ObjMesh& mesh, const Options& options, int level, cli::EvaluatorKind kind,
                            realtime::TableRoute route) {
    auto refiner = std::make_unique<Refiner>(cli::makeRefiner(mesh, options));
    refiner->refineUniform(level);
    // Level 0 has neither a factorized table nor patches; where the budget refuses the factorized
    // table, the per-level route.
    auto tables = std::make_unique<realtime::SurfaceTables>(
        level == 0 ? realtime::SurfaceTables(*refiner, 0, realtime::TableRoute::LevelsThenLimit)
        : route == realtime::TableRoute::FactorizedLimit ? realtime::fastestSurfaceTables(*refiner, level)
                                                          : realtime::SurfaceTables(*refiner, level, route));
    std::unique_ptr<realtime::FrameEvaluator> evaluator;
    if (kind == cli::EvaluatorKind::Vulkan)
        evaluator = std::make_unique<realtime::VulkanFrameEvaluator>(ctx_, *tables);
    else
        evaluator = std::make_unique<realtime::HostFrameEvaluator>(*tables, kind == cli::EvaluatorKind::Tbb);
    // The UVs on the CPU: they do not move with the skin.
    std::vector<float> uvs;
    if (refiner->numFVarChannels() > 0)
        uvs = std::move(cli::evaluateLevels(cli::EvaluatorKind::Cpu, {cli::fvarLevels(*refiner, 0, level, mesh.uvs, 2)})[0]);

    // Everything that can throw is done. The renderer lets go of the old evaluator's buffers
    // before they go (the new evaluator's, or its own, zero until the first update), and is
    // given them again after the new level's surface.
    onDevice_ = kind == cli::EvaluatorKind::Vulkan;
    const std::vector<float> zeros(onDevice_ ? 0 : 3 * std::size_t(tables->numPoints), 0.0f);
    auto bindVertices = [&] {
        if (!onDevice_) return renderer_.uploadVertices(zeros.data(), zeros.data(), tables_->numPoints);
        auto& device = static_cast<realtime::VulkanFrameEvaluator&>(*evaluator_);
        renderer_.useVertexBuffers({device.positions().buffer(), 0}, {device.normals().buffer(), 0});
    };
    evaluator_.swap(evaluator);
    tables_.swap(tables);
    bindVertices();
    evaluator.reset();  // the old one, which read the old tables
    tables.reset();
    refiner_ = std::move(refiner);
    level_ = level;
    // The host evaluators' read-back is in level order; the device's buffers are the table's.
    elementOfVertex_.clear();
    if (onDevice_ && tables_->patches) elementOfVertex_ = tables_->patches->pointOfVertex();
    render::showLevel(renderer_, *refiner_, level, uvs.empty() ? nullptr : uvs.data(),
                      elementOfVertex_.empty() ? nullptr : &elementOfVertex_);
    bindVertices();
    rest_ = mesh.positions;
    cage_ = rest_;
    skin_.reset();
    skinProblem_.clear();
    try {
        skin_.emplace(rest_);
    } catch (const std::invalid_argument& e) {
        skinProblem_ = e.what();
    }
    const Topology& level0 = refiner_->level(0);
    edges_.assign(level0.edgeVerts.begin(), level0.edgeVerts.begin() + 2 * std::ptrdiff_t(level0.numEdges()));
}

realtime::PhaseTimes ViewedSurface::update(float radians, const std::vector<std::pair<int, int>>& selectedEdges,
                                           const std::vector<int>& selectedVertices, bool curvature) {
    realtime::PhaseTimes times;
    if (!ready()) return times;
    const Clock::time_point start = Clock::now();
    if (skin_ && radians != 0.0f)
        skin_->pose(radians, cage_.data());
    else
        cage_ = rest_;
    evaluator_->setCage(cage_.data());
    times.deformMs = msSince(start);
    evaluator_->evaluate(times);

    std::vector<float> positions, normals;
    if (!onDevice_ || curvature) evaluator_->readBack(positions, normals);
    if (!onDevice_) renderer_.uploadVertices(positions.data(), normals.data(), tables_->numPoints);
    if (curvature) {
        std::vector<float> h = render::meanCurvature(refiner_->faces(level_), positions.data(), normals.data());
        curvatureRange_ = render::curvatureRange(h);
        if (!elementOfVertex_.empty()) {
            std::vector<float> atElement(h.size());
            for (std::size_t v = 0; v < h.size(); ++v) atElement[std::size_t(elementOfVertex_[v])] = h[v];
            h.swap(atElement);
        }
        renderer_.uploadCurvature(h);
    }
    const Topology& level0 = refiner_->level(0);
    std::vector<int> edges;
    for (const auto& [a, b] : selectedEdges) edges.push_back(edgeBetween(level0, a, b));
    renderer_.setCage(render::cageOf(level0, cage_.data(), edges, selectedVertices));
    return times;
}

}  // namespace quadtri::view
