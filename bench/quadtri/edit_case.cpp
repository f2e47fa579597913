#include "bench/quadtri/edit_case.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <quadtri/far/limit_table_update.h>
#include <quadtri/far/refiner.h>
#include <quadtri/osd/cpu_evaluator.h>

#include "bench/measure/timing.h"
#include "bench/opensubdiv/osd_edit_case.h"

namespace quadtri::bench {

const char* toString(EditKind kind) {
    switch (kind) {
        case EditKind::Edge: return "edge";
        case EditKind::EdgeLoop: return "edge_loop";
        case EditKind::Corner: return "corner";
        case EditKind::Hole: return "hole";
    }
    return "?";
}

namespace {

bool interiorVertex(const Topology& t, int v) { return !(t.vertFlags[std::size_t(v)] & (kVertexBoundary | kVertexNonManifold)); }

// The edge after `e` through its end `v` along a quad loop: where v has four edges, all between
// quads, the one that shares no face with e; -1 elsewhere.
int nextInLoop(const Topology& t, int e, int v) {
    if (t.vertexEdgeCount(v) != 4 || !interiorVertex(t, v)) return -1;
    for (int f : t.facesOfVertex(v))
        if (t.faceSize(f) != 4) return -1;
    for (int g : t.edgesOfVertex(v)) {
        if (g == e) continue;
        bool shares = false;
        for (int f : t.facesOfEdge(g))
            for (int h : t.facesOfEdge(e)) shares = shares || f == h;
        if (!shares) return g;
    }
    return -1;
}

}  // namespace

CageEdit chooseEdit(const SurfaceCage& cage, EditKind kind) {
    Refiner refiner(cage.descriptor(), cage.options);
    const Topology& t = refiner.level(0);
    CageEdit edit;
    if (kind == EditKind::Hole) {
        edit.hole = cage.mesh.numFaces() / 2;
        return edit;
    }
    if (kind == EditKind::Corner) {
        int v = t.numVertices / 2;
        while (!interiorVertex(t, v) || t.vertSharpness[std::size_t(v)] > 0.0f) v = (v + 1) % t.numVertices;
        edit.corner = v;
        return edit;
    }
    // The middle interior smooth edge (for a loop: the first from there that starts ten edges).
    const int wanted = kind == EditKind::EdgeLoop ? 10 : 1;
    for (int k = 0; k < t.numEdges(); ++k) {
        const int first = (t.numEdges() / 2 + k) % t.numEdges();
        if (t.edgeFaceCount(first) != 2 || t.edgeSharpness[std::size_t(first)] > 0.0f) continue;
        std::vector<int> loop{first};
        int e = first, v = t.edgeVerts[2 * std::size_t(first) + 1];
        while (int(loop.size()) < wanted) {
            const int next = nextInLoop(t, e, v);
            if (next < 0 || std::find(loop.begin(), loop.end(), next) != loop.end()) break;
            loop.push_back(next);
            v = t.otherVertex(next, v);
            e = next;
        }
        if (int(loop.size()) < wanted) continue;
        for (int g : loop) {
            edit.creasePairs.push_back(t.edgeVerts[2 * std::size_t(g)]);
            edit.creasePairs.push_back(t.edgeVerts[2 * std::size_t(g) + 1]);
        }
        return edit;
    }
    throw std::runtime_error(cage.mesh.name + ": no interior edge loop of " + std::to_string(wanted) + " edges to edit");
}

SurfaceCage withEdit(const SurfaceCage& cage, const CageEdit& edit) {
    SurfaceCage out = cage;
    out.creasePairs.insert(out.creasePairs.end(), edit.creasePairs.begin(), edit.creasePairs.end());
    out.creaseSharpness.insert(out.creaseSharpness.end(), edit.creasePairs.size() / 2, edit.sharpness);
    if (edit.corner >= 0) out.corners.push_back(edit.corner), out.cornerSharpness.push_back(edit.sharpness);
    if (edit.hole >= 0) out.holes.push_back(edit.hole);
    return out;
}

namespace {

std::vector<float> limitPoints(const LimitStencilTable& table, const std::vector<float>& cage) {
    std::vector<float> points(3 * std::size_t(table.numStencils()));
    const BufferDescriptor xyz(0, 3, 3);
    CpuEvaluator::EvalLimitStencils(cage.data(), xyz, points.data(), xyz, nullptr, xyz, nullptr, xyz, nullptr, xyz, table);
    return points;
}

}  // namespace

EditCaseResult runEditCase(const SurfaceCage& cage, const std::string& scheme, int level, EditKind kind, int reps,
                           std::optional<OsdScheme> osd) {
    EditCaseResult r;
    r.mesh = cage.mesh.name;
    r.scheme = scheme;
    r.level = level;
    r.edit = toString(kind);
    const CageEdit edit = chooseEdit(cage, kind);

    // The Refiner and the frame's table, as the viewer keeps them; the edit, and back.
    Refiner refiner(cage.descriptor(), cage.options);
    refiner.refineUniform(level, TopologyDetail::Full);
    LimitStencilTable table = refiner.factorizedLimitStencils(level);
    LimitTableUpdate update(refiner, level, LimitTableUpdate::Sources::Control);
    r.points = table.numStencils();
    TagEdits apply, undo;
    const Topology& level0 = refiner.level(0);
    for (std::size_t k = 0; k < edit.creasePairs.size(); k += 2) {
        const int a = edit.creasePairs[k], b = edit.creasePairs[k + 1];
        apply.setCrease(a, b, edit.sharpness);
        undo.setCrease(a, b, level0.edgeSharpness[std::size_t(findEdge(level0, a, b))]);
    }
    if (edit.corner >= 0) {
        apply.setCorner(edit.corner, edit.sharpness);
        undo.setCorner(edit.corner, level0.vertSharpness[std::size_t(edit.corner)]);
    }
    if (edit.hole >= 0) {
        apply.setHole(edit.hole, true);
        undo.setHole(edit.hole, false);
    }
    std::vector<double> times;
    for (int i = 0; i <= reps; ++i) {  // the first untimed; the last left edited
        const Stopwatch watch;
        const EditReport report = refiner.applyEdits(apply);
        r.stencilsWritten = int(update.update(report, table).stencils.size());
        if (i > 0) times.push_back(watch.elapsedMs());
        if (i < reps) update.update(refiner.applyEdits(undo), table);
    }
    r.updateMs = summarize(times);

    // The same table built again from the edited cage; the two tables' points on the cage.
    const SurfaceCage edited = withEdit(cage, edit);
    LimitStencilTable rebuilt;
    std::vector<double> rebuildTimes;
    for (int i = 0; i < (level >= 4 ? std::min(reps, 3) : reps); ++i) {
        const Stopwatch watch;
        Refiner fresh(edited.descriptor(), edited.options);
        fresh.refineUniform(level);
        rebuilt = fresh.factorizedLimitStencils(level);
        rebuildTimes.push_back(watch.elapsedMs());
    }
    r.rebuildMs = summarize(rebuildTimes);
    const std::vector<float> a = limitPoints(table, cage.mesh.positions), b = limitPoints(rebuilt, cage.mesh.positions);
    if (a.size() != b.size()) throw std::runtime_error(r.mesh + ": the updated table has another size than the rebuilt one");
    double largest = 0;
    for (std::size_t k = 0; k < a.size(); k += 3)
        largest = std::max(largest, std::hypot(double(a[k]) - b[k], double(a[k + 1]) - b[k + 1], double(a[k + 2]) - b[k + 2]));
    r.maxDifference = largest / cage.mesh.boundingBoxDiagonal();
    if (osd) {
        const OsdTags tags{edited.creasePairs, edited.creaseSharpness, edited.corners, edited.cornerSharpness, edited.holes};
        r.osdRebuildMs = osdRebuild(cage.mesh, *osd, tags, level, level >= 4 ? std::min(reps, 3) : reps);
        r.osdScheme = *osd == OsdScheme::Catmark ? "catmark" : "loop";
    }
    return r;
}

}  // namespace quadtri::bench
