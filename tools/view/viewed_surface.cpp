#include "tools/view/viewed_surface.h"

#include <algorithm>
#include <chrono>
#include <future>
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

namespace {

// The UVs of level L on the CPU (they do not move with the skin), none without a channel.
std::vector<float> levelUVs(const Refiner& refiner, int level, const std::vector<float>& controlUVs) {
    if (refiner.numFVarChannels() == 0) return {};
    return std::move(cli::evaluateLevels(cli::EvaluatorKind::Cpu, {cli::fvarLevels(refiner, 0, level, controlUVs, 2)})[0]);
}

std::unique_ptr<realtime::FrameEvaluator> makeEvaluator(VulkanContext& ctx, const realtime::SurfaceTables& tables,
                                                        cli::EvaluatorKind kind) {
    if (kind == cli::EvaluatorKind::Vulkan) return std::make_unique<realtime::VulkanFrameEvaluator>(ctx, tables, true);
    return std::make_unique<realtime::HostFrameEvaluator>(tables, kind == cli::EvaluatorKind::Tbb);
}

}  // namespace

void ViewedSurface::rebuild(const io::ObjMesh& mesh, const Options& options, int level, cli::EvaluatorKind kind,
                            realtime::TableRoute route) {
    auto refiner = std::make_unique<Refiner>(cli::makeRefiner(mesh, options));
    refiner->refineUniform(level, TopologyDetail::Full);  // an edit's limit table update reads level N in full
    // Level 0 has neither a factorized table nor patches; where the budget refuses the factorized
    // table, the per-level route.
    auto tables = std::make_unique<realtime::SurfaceTables>(
        level == 0 ? realtime::SurfaceTables(*refiner, 0, realtime::TableRoute::LevelsThenLimit)
        : route == realtime::TableRoute::FactorizedLimit ? realtime::fastestSurfaceTables(*refiner, level)
                                                          : realtime::SurfaceTables(*refiner, level, route));
    std::unique_ptr<realtime::FrameEvaluator> evaluator = makeEvaluator(ctx_, *tables, kind);
    const std::vector<float> uvs = levelUVs(*refiner, level, mesh.uvs);

    // Everything that can throw is done. The renderer lets go of the old evaluator's buffers
    // before they go (the new evaluator's, or its own, zero until the first update), and is
    // given them again after the new level's surface.
    onDevice_ = kind == cli::EvaluatorKind::Vulkan;
    evaluator_.swap(evaluator);
    tables_.swap(tables);
    bindVertices();
    evaluator.reset();  // the old one, which read the old tables
    tables.reset();
    pendingLimitUpdate_ = {};  // waits for the old one, which reads the old Refiner
    limitUpdate_.reset();
    refiner_ = std::move(refiner);
    if (!tables_->patches) {
        // What an edit's update of the limit table needs (the level's limit masks) is made on
        // another thread while the surface is shown, so that the first edit need not wait for it.
        const LimitTableUpdate::Sources sources = tables_->route == realtime::TableRoute::FactorizedLimit
                                                      ? LimitTableUpdate::Sources::Control
                                                      : LimitTableUpdate::Sources::Level;
        pendingLimitUpdate_ = std::async(std::launch::async, [&r = *refiner_, level, sources] {
            return std::make_unique<LimitTableUpdate>(r, level, sources);
        });
    }
    level_ = level;
    kind_ = kind;
    controlUVs_ = mesh.uvs;
    present(uvs);
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

double ViewedSurface::edit(const TagEdits& edits) {
    if (!ready()) return 0.0;
    const Clock::time_point start = Clock::now();
    if (!limitUpdate_ && pendingLimitUpdate_.valid()) limitUpdate_ = pendingLimitUpdate_.get();  // before the Refiner changes
    const EditReport report = refiner_->applyEdits(edits);
    if (!report.changed()) return msSince(start);
    realtime::SurfaceTables& tables = *tables_;
    // Copies of the per-level tables that changed; the limit table updated in place; the patch
    // table made again (which faces are regular patches may change).
    bool holesChanged = false;
    std::vector<int> changedLevels;
    for (std::size_t L = 1; L < report.levels.size(); ++L) {
        holesChanged = holesChanged || !report.levels[L].faces.empty();
        if (L > tables.levels.size() || report.levels[L].stencils.empty()) continue;
        tables.levels[L - 1] = refiner_->levelStencils(int(L));
        changedLevels.push_back(int(L));
    }
    LimitTableChange change;
    if (tables.patches) {
        *tables.patches = refiner_->levelPatches(level_, realtime::patchLevelFor(level_));
    } else {
        change = limitUpdate_->update(report, tables.limit);
        if (holesChanged && tables.route == realtime::TableRoute::LevelsThenLimit)
            tables.fallback = buildMeshNormalTable(refiner_->faces(level_));
    }
    // The host evaluators read the limit table where it is; what they derive from the per-level
    // tables is made again. The device's tables are updated by range where they can be (the
    // per-level tables where their entries did not move), else uploaded again.
    bool newEvaluator = tables.patches || (!changedLevels.empty() && !onDevice_);
    if (onDevice_ && !newEvaluator) {
        auto& device = static_cast<realtime::VulkanFrameEvaluator&>(*evaluator_);
        newEvaluator = holesChanged || !device.updateLimit(tables.limit, change);
        for (int L : changedLevels)
            newEvaluator = newEvaluator || !device.updateLevel(L, tables.levels[std::size_t(L) - 1], report.levels[std::size_t(L)]);
    }
    const bool show = holesChanged || refiner_->numFVarChannels() > 0 || tessellation_ || (onDevice_ && tables.patches);
    if (newEvaluator) {
        std::unique_ptr<realtime::FrameEvaluator> evaluator = makeEvaluator(ctx_, tables, kind_);
        evaluator_.swap(evaluator);
        bindVertices();
        evaluator.reset();
    }
    if (show) present(levelUVs(*refiner_, level_, controlUVs_));
    return msSince(start);
}

void ViewedSurface::bindVertices() {
    if (!onDevice_) {
        const std::vector<float> zeros(3 * std::size_t(tables_->numPoints), 0.0f);
        return renderer_.uploadVertices(zeros.data(), zeros.data(), tables_->numPoints);
    }
    auto& device = static_cast<realtime::VulkanFrameEvaluator&>(*evaluator_);
    renderer_.useVertexBuffers({device.positions().buffer(), 0}, {device.normals().buffer(), 0});
}

void ViewedSurface::present(const std::vector<float>& uvs) {
    limitSurface_.reset();
    tessellation_.reset();
    deviceTessellation_.reset();
    edgeRates_.clear();
    // The host evaluators' read-back is in level order; the device's buffers are the table's.
    elementOfVertex_.clear();
    if (onDevice_ && tables_->patches) elementOfVertex_ = tables_->patches->pointOfVertex();
    render::showLevel(renderer_, *refiner_, level_, uvs.empty() ? nullptr : uvs.data(),
                      elementOfVertex_.empty() ? nullptr : &elementOfVertex_);
    bindVertices();
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
