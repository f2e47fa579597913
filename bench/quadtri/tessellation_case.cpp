#include "bench/quadtri/tessellation_case.h"

#include <tbb/task_arena.h>

#include <cmath>
#include <memory>

#include <quadtri/far/limit_surface.h>
#include <quadtri/far/tessellation.h>
#include <quadtri/osd/cpu_evaluator.h>

namespace quadtri::bench {

double trianglesArea(const std::vector<int>& triangles, const std::vector<float>& points) {
    double area = 0;
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const float* a = &points[3 * std::size_t(triangles[t])];
        const float* b = &points[3 * std::size_t(triangles[t + 1])];
        const float* c = &points[3 * std::size_t(triangles[t + 2])];
        double e[3], f[3];
        for (int k = 0; k < 3; ++k) e[k] = double(b[k]) - a[k], f[k] = double(c[k]) - a[k];
        const double n[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
        area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    return area;
}

namespace {

// The tessellation, its table and its evaluated points: what a renderer keeps between frames.
struct Tessellated {
    std::unique_ptr<LimitSurface> surface;
    std::unique_ptr<Tessellation> tessellation;
    LimitStencilTable table;
    std::vector<float> positions, normals;
};

void evaluate(const SurfaceCage& cage, Tessellated& t) {
    const BufferDescriptor xyz(0, 3, 3);
    t.positions.resize(3 * std::size_t(t.table.numStencils()));
    t.normals.resize(t.positions.size());
    if (t.table.numStencils() > 0)
        CpuEvaluator::EvalLimitStencils(cage.mesh.positions.data(), xyz, t.positions.data(), xyz, nullptr, {}, nullptr,
                                        {}, t.normals.data(), xyz, t.table);
}

void tessellate(const SurfaceCage& cage, int rate, Tessellated& t) {
    t.surface = std::make_unique<LimitSurface>(cage.descriptor(), cage.options);
    t.tessellation = std::make_unique<Tessellation>(*t.surface, rate);
    const Tessellation& tess = *t.tessellation;
    t.table = t.surface->stencilTable(tess.numPoints(), tess.faces(), tess.u(), tess.v());
    evaluate(cage, t);
}

}  // namespace

TessellationWay measureQuadtriTessellation(const SurfaceCage& cage, int rate, int reps) {
    TessellationWay way;
    way.library = "quadtri";
    way.way = "tessellation";
    // One thread, as Bfr's loop: LimitSurface::stencilTable runs its faces as oneTBB tasks.
    tbb::task_arena serial(1);
    Tessellated t;
    serial.execute([&] { tessellate(cage, rate, t); });
    way.points = t.tessellation->numPoints();
    way.triangles = t.tessellation->numTriangles();
    way.area = trianglesArea(t.tessellation->triangles(), t.positions);
    way.firstMs = timeMs(reps, [&] {
        serial.execute([&] {
            Tessellated fresh;
            tessellate(cage, rate, fresh);
        });
    });
    way.frameMs = timeMs(reps, [&] { evaluate(cage, t); });
    return way;
}

}  // namespace quadtri::bench
