#include "tools/view/viewed_surface.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>

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
    kind_ = kind;
    limitSurface_.reset();
    tessellation_.reset();
    deviceTessellation_.reset();
    edgeRates_.clear();
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

bool ViewedSurface::adapt(const render::ViewSettings& view, VkExtent2D extent, float pixelsPerSegment) {
    if (!ready()) return false;
    if (!limitSurface_) limitSurface_ = std::make_unique<LimitSurface>(*refiner_);
    const Topology& base = limitSurface_->topology();
    std::vector<int> rates(std::size_t(base.numEdges()), 1);
    for (int e = 0; e < base.numEdges(); ++e) {
        const float* a = &rest_[3 * std::size_t(base.edgeVerts[2 * std::size_t(e)])];
        const float* b = &rest_[3 * std::size_t(base.edgeVerts[2 * std::size_t(e) + 1])];
        const glm::vec3 p = render::toPixel(view, extent, {a[0], a[1], a[2]});
        const glm::vec3 q = render::toPixel(view, extent, {b[0], b[1], b[2]});
        if (p.z <= 0.0f || q.z <= 0.0f) continue;  // behind the eye
        const float segments = std::hypot(p.x - q.x, p.y - q.y) / std::max(pixelsPerSegment, 1e-3f);
        int rate = 1;
        while (rate < kMaxAdaptiveRate && float(rate) < segments) rate *= 2;
        rates[std::size_t(e)] = rate;
    }
    if (tessellation_ && rates == edgeRates_) return false;
    auto tessellation = std::make_unique<Tessellation>(*limitSurface_, rates);
    LimitStencilTable table = limitSurface_->stencilTable(tessellation->numPoints(), tessellation->faces(),
                                                          tessellation->u(), tessellation->v());
    DrawBuffers draw;
    draw.triangles.assign(tessellation->triangles().begin(), tessellation->triangles().end());
    draw.vertexOf.resize(std::size_t(tessellation->numPoints()));
    for (std::size_t k = 0; k < draw.vertexOf.size(); ++k) draw.vertexOf[k] = int(k);
    draw.numLevelVertices = tessellation->numPoints();
    std::vector<uint32_t> origins;
    for (int f : tessellation->triangleFaces()) {
        const int n = base.faceSize(f);
        origins.push_back(n == 3 ? render::kFromTriangle : n == 4 ? render::kFromQuad : render::kFromOtherPolygon);
    }
    const int n = tessellation->numPoints();
    std::unique_ptr<DeviceTessellation> device;
    if (onDevice_) {
        if (!limitEvaluator_) limitEvaluator_ = std::make_unique<VulkanLimitEvaluator>(ctx_);
        device.reset(new DeviceTessellation{VulkanLimitStencilTable(ctx_, table),
                                            VulkanVertexBuffer::create(ctx_, int(rest_.size() / 3), 3),
                                            VulkanVertexBuffer::create(ctx_, n, 3), VulkanVertexBuffer::create(ctx_, n, 3)});
    }
    // The renderer lets go of the old buffers before they go.
    renderer_.setSurface(draw, nullptr, origins);
    tessellation_ = std::move(tessellation);
    tessellationTable_ = std::move(table);
    edgeRates_ = std::move(rates);
    deviceTessellation_ = std::move(device);
    tessellationPositions_.assign(3 * std::size_t(n), 0.0f);
    tessellationNormals_ = tessellationPositions_;
    if (deviceTessellation_)
        renderer_.useVertexBuffers({deviceTessellation_->positions.buffer(), 0}, {deviceTessellation_->normals.buffer(), 0});
    else
        renderer_.uploadVertices(tessellationPositions_.data(), tessellationNormals_.data(), n);
    return true;
}

std::string ViewedSurface::adaptiveSummary() const {
    if (!tessellation_) return "";
    const auto [low, high] = std::minmax_element(edgeRates_.begin(), edgeRates_.end());
    return "rates " + std::to_string(edgeRates_.empty() ? 0 : *low) + "-" + std::to_string(edgeRates_.empty() ? 0 : *high) +
           " per edge, " + std::to_string(tessellation_->numTriangles()) + " triangles";
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
    if (tessellation_) {
        times.deformMs = msSince(start);
        const Clock::time_point evaluation = Clock::now();
        const BufferDescriptor xyz(0, 3, 3);
        if (DeviceTessellation* d = deviceTessellation_.get()) {
            d->cage.updateData(cage_.data(), 0, int(cage_.size() / 3));
            limitEvaluator_->EvalLimitStencilsAndWait(d->cage, xyz, &d->positions, xyz, nullptr, xyz, nullptr, xyz,
                                                      &d->normals, xyz, d->table);
            times.evaluateMs = msSince(evaluation);
        } else {
            auto limit = kind_ == cli::EvaluatorKind::Cpu ? CpuEvaluator::EvalLimitStencils : TbbEvaluator::EvalLimitStencils;
            if (tessellationTable_.numStencils() > 0)
                limit(cage_.data(), xyz, tessellationPositions_.data(), xyz, nullptr, xyz, nullptr, xyz,
                      tessellationNormals_.data(), xyz, tessellationTable_, nullptr, 0, -1);
            times.evaluateMs = msSince(evaluation);
            renderer_.uploadVertices(tessellationPositions_.data(), tessellationNormals_.data(), tessellation_->numPoints());
        }
        curvatureRange_ = 0.0f;  // no mean curvature on a tessellation
        showCage(selectedEdges, selectedVertices);
        return times;
    }
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
    showCage(selectedEdges, selectedVertices);
    return times;
}

void ViewedSurface::showCage(const std::vector<std::pair<int, int>>& selectedEdges,
                             const std::vector<int>& selectedVertices) {
    const Topology& level0 = refiner_->level(0);
    std::vector<int> edges;
    for (const auto& [a, b] : selectedEdges) edges.push_back(edgeBetween(level0, a, b));
    renderer_.setCage(render::cageOf(level0, cage_.data(), edges, selectedVertices));
}

}  // namespace quadtri::view
