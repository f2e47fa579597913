// LimitSurface (quadtri/far/limit_surface.h): a point's face neighbourhood is refined locally
// towards it until it lies in a regular patch, or, past maxDepth, in a sub-face small enough to
// interpolate from its next level's exact limit points (docs/surface.md).
#include <quadtri/far/limit_surface.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <quadtri/far/refiner.h>
#include "far/internal/parallel.h"
#include "far/limit/limit_eigen.h"
#include "far/limit/limit_mask.h"
#include "far/limit/limit_ring.h"
#include "far/limit/limit_table.h"
#include "far/schemes/scheme.h"
#include "far/surface/local_mesh.h"
#include "far/surface/patch_basis.h"
#include "far/surface/regular_patch.h"

namespace quadtri {
inline namespace v0 {

using namespace internal;

namespace {

// The point in the followed sub-face's own (s, t), and d(s, t)/d(u, v) back to the base face.
struct Where {
    double s = 0, t = 0;
    double k[2][2] = {{1, 0}, {0, 1}};  // k[0]: ds/du, ds/dv; k[1]: dt/du, dt/dv

    // (s, t) <- a (s, t) + b, kept inside the domain against rounding.
    void map(const double a[2][2], double b0, double b1, bool triangle) {
        const double s1 = a[0][0] * s + a[0][1] * t + b0, t1 = a[1][0] * s + a[1][1] * t + b1;
        s = std::clamp(s1, 0.0, 1.0);
        t = std::clamp(t1, 0.0, 1.0);
        if (triangle && s + t > 1) {
            const double over = s + t;
            s /= over;
            t /= over;
        }
        double k1[2][2];
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) k1[i][j] = a[i][0] * k[0][j] + a[i][1] * k[1][j];
        std::copy(&k1[0][0], &k1[0][0] + 4, &k[0][0]);
    }
};

// The child of a quad (or triangle split in four) that holds the point, the point moved into it
// (children as refine_topology.cpp numbers them: corner i's first, a triangle's middle last).
int descend(bool quad, Where& w) {
    if (quad) {
        static constexpr double kA[4][2][2] = {
            {{2, 0}, {0, 2}}, {{0, 2}, {-2, 0}}, {{-2, 0}, {0, -2}}, {{0, -2}, {2, 0}}};
        static constexpr double kB[4][2] = {{0, 0}, {0, 2}, {2, 2}, {2, 0}};
        const int child = w.s < 0.5 ? (w.t < 0.5 ? 0 : 3) : (w.t < 0.5 ? 1 : 2);
        w.map(kA[child], kB[child][0], kB[child][1], false);
        return child;
    }
    static constexpr double kA[4][2][2] = {
        {{2, 0}, {0, 2}}, {{0, 2}, {-2, -2}}, {{-2, -2}, {2, 0}}, {{2, 2}, {-2, 0}}};
    static constexpr double kB[4][2] = {{0, 0}, {0, 2}, {2, 0}, {-1, 1}};
    const int child = w.s + w.t <= 0.5 ? 0 : w.s >= 0.5 ? 1 : w.t >= 0.5 ? 2 : 3;
    w.map(kA[child], kB[child][0], kB[child][1], true);
    return child;
}

// The sub-face of an n-gon's (u, v), checked to hold it, and the point in it.
int enterSubFace(const FaceParameterization& p, double u, double v, Where& w) {
    const int i = p.subFaceAt(u, v);
    static constexpr double kTwice[2][2] = {{2, 0}, {0, 2}};
    w.s = u;
    w.t = v;
    w.map(kTwice, -2.0 * (i % p.gridWidth), -2.0 * (i / p.gridWidth), false);
    return i;
}

}  // namespace

LimitSurface::LimitSurface(const Refiner& refiner, LimitSurfaceOptions surfaceOptions)
    : options_(refiner.options()), surfaceOptions_(surfaceOptions),
      base_(std::make_shared<const Topology>(refiner.level(0))) {
    if (surfaceOptions_.maxDepth < 1 || surfaceOptions_.maxDepth > 30)
        throw SurfaceError("LimitSurface: maxDepth " + std::to_string(surfaceOptions_.maxDepth) +
                           " is outside 1..30");
    if (surfaceOptions_.rings < 0) throw SurfaceError("LimitSurface: rings must be 0 (the scheme's) or more");
}

LimitSurface::~LimitSurface() = default;
LimitSurface::LimitSurface(LimitSurface&&) noexcept = default;
LimitSurface& LimitSurface::operator=(LimitSurface&&) noexcept = default;

int LimitSurface::numFaces() const { return base_->numFaces(); }
int LimitSurface::numControlVertices() const { return base_->numVertices; }

FaceParameterization LimitSurface::parameterization(int face) const {
    if (face < 0 || face >= numFaces())
        throw SurfaceError("face " + std::to_string(face) + " is out of range: the mesh has " +
                           std::to_string(numFaces()) + " faces");
    return FaceParameterization::of(options_.scheme, base_->faceSize(face));
}

bool LimitSurface::isHole(int face) const {
    parameterization(face);
    return base_->faceHole[face] != 0;
}

void LimitSurface::check(int face, double u, double v) const {
    const FaceParameterization p = parameterization(face);
    if (base_->faceHole[face]) throw SurfaceError("face " + std::to_string(face) + " is a hole: it has no surface");
    if (!p.contains(u, v))
        throw SurfaceError("face " + std::to_string(face) + ": (" + std::to_string(u) + ", " + std::to_string(v) +
                           ") is outside its domain (" + p.describe() + ")");
}

void LimitSurface::stencil(int face, double u, double v, LimitPointStencil& out) const {
    check(face, u, v);
    Options o = options_;
    o.leftHanded = false;  // every level stores its faces counter-clockwise already
    const SchemeRules& rules = rulesOf(o.scheme);
    const int rings = surfaceOptions_.rings > 0 ? surfaceOptions_.rings : rules.surfaceRings();
    thread_local WalkScratch baseScratch;  // sized to the base mesh once per thread
    WalkScratch scratch;
    std::vector<int> columns;
    LocalMesh mesh = cutBase(*base_, face, rings, o, baseScratch, columns);

    Where w;
    w.s = u;
    w.t = v;
    const FaceParameterization param = FaceParameterization::of(o.scheme, base_->faceSize(face));
    int depth = 0;
    if (param.type == FaceParameterization::Type::QuadSubFaces) {
        mesh = refineTowards(mesh, enterSubFace(param, u, v, w), rings, o, scratch);
        depth = 1;
    }

    LimitMask local;  // weights over the final local mesh's vertices
    std::vector<int> points;
    double wP[16], wDs[16], wDt[16];
    for (;; ++depth) {
        const PatchKind kind = regularPatch(mesh.topology, mesh.face, o, points);
        if (kind != PatchKind::None) {
            switch (kind) {
            case PatchKind::BSpline: bSplineWeights(w.s, w.t, wP, wDs, wDt); break;
            case PatchKind::BoxSpline: boxSplineWeights(w.s, w.t, wP, wDs, wDt); break;
            case PatchKind::Bilinear: bilinearWeights(w.s, w.t, wP, wDs, wDt); break;
            default: linearWeights(w.s, w.t, wP, wDs, wDt); break;
            }
            for (std::size_t i = 0; i < points.size(); ++i) local.add(points[i], wP[i], wDs[i], wDt[i]);
            break;
        }
        const bool quad = mesh.topology.faceSize(mesh.face) == 4;
        if (depth >= surfaceOptions_.maxDepth) {
            // The quadratic through the exact limit points of the sub-face's next level.
            std::vector<int> nodes;
            LocalMesh next = refineTowards(mesh, 0, rings, o, scratch, &nodes);
            if (quad)
                quadraticQuadWeights(w.s, w.t, wP, wDs, wDt);
            else
                quadraticTriangleWeights(w.s, w.t, wP, wDs, wDt);
            VertexRing ring;
            LimitMask limit;
            LimitMaskCache cache;
            for (std::size_t i = 0; i < nodes.size(); ++i) {
                orderVertexRing(next.topology, nodes[i], -1, ring);
                limit.clear();
                rules.limitMask(LimitVertex{next.topology, o, ring, limitRule(next.topology, ring)}, cache, limit);
                for (int k = 0; k < limit.size(); ++k)
                    local.add(limit.indices[k], wP[i] * limit.position[k], wDs[i] * limit.position[k],
                                   wDt[i] * limit.position[k]);
            }
            mesh = std::move(next);
            break;
        }
        const int child = descend(quad, w);
        mesh = refineTowards(mesh, child, rings, o, scratch);
    }

    // Over the base neighbourhood, then the control vertices; derivatives back to (u, v).
    const int n = mesh.numColumns;
    std::vector<double> p(n, 0.0), ds(n, 0.0), dt(n, 0.0);
    for (int k = 0; k < local.size(); ++k) {
        const double* row = mesh.row(local.indices[k]);
        const double a = local.position[k], b = local.du[k], c = local.dv[k];
        for (int j = 0; j < n; ++j) {
            p[j] += a * row[j];
            ds[j] += b * row[j];
            dt[j] += c * row[j];
        }
    }
    out.indices.clear();
    out.position.clear();
    out.du.clear();
    out.dv.clear();
    for (int j = 0; j < n; ++j) {
        if (p[j] == 0.0 && ds[j] == 0.0 && dt[j] == 0.0) continue;
        out.indices.push_back(columns[j]);
        out.position.push_back(p[j]);
        out.du.push_back(ds[j] * w.k[0][0] + dt[j] * w.k[1][0]);
        out.dv.push_back(ds[j] * w.k[0][1] + dt[j] * w.k[1][1]);
    }
}

LimitStencilTable LimitSurface::stencilTable(int count, const int* faces, const double* u, const double* v) const {
    for (int i = 0; i < count; ++i) {
        try {
            check(faces[i], u[i], v[i]);
        } catch (const SurfaceError& e) {
            throw SurfaceError("point " + std::to_string(i) + ": " + e.what());
        }
    }
    LimitStencilTableD table;
    table.numSourceVertices = numControlVertices();
    // Blocks of points side by side, each point's stencil its own: the same table on any threads.
    constexpr int kBlock = 4096;
    std::vector<LimitPointStencil> block(std::size_t(std::min(count, kBlock)));
    for (int first = 0; first < count; first += kBlock) {
        const int size = std::min(kBlock, count - first);
        parallel::forEachRange(0, size, 16, [&](int begin, int end) {
            for (int i = begin; i < end; ++i) stencil(faces[first + i], u[first + i], v[first + i], block[std::size_t(i)]);
        });
        for (int i = 0; i < size; ++i) {
            const LimitPointStencil& s = block[std::size_t(i)];
            table.offsets.push_back(int(table.indices.size()));
            table.sizes.push_back(s.size());
            table.indices.insert(table.indices.end(), s.indices.begin(), s.indices.end());
            for (int k = 0; k < s.size(); ++k) table.weights.insert(table.weights.end(), {s.position[k], s.du[k], s.dv[k]});
        }
    }
    return toFloatTable(table);
}

void LimitSurface::evaluate(int face, double u, double v, const float* control, int width, int stride,
                            float* position, float* dPdu, float* dPdv) const {
    LimitPointStencil s;
    stencil(face, u, v, s);
    for (int c = 0; c < width; ++c) {
        double p = 0, du = 0, dv = 0;
        for (int k = 0; k < s.size(); ++k) {
            const double x = control[std::size_t(s.indices[k]) * std::size_t(stride) + c];
            p += s.position[k] * x;
            du += s.du[k] * x;
            dv += s.dv[k] * x;
        }
        position[c] = float(p);
        if (dPdu) dPdu[c] = float(du);
        if (dPdv) dPdv[c] = float(dv);
    }
}

}  // namespace v0
}  // namespace quadtri
