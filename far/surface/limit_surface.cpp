// LimitSurface (quadtri/far/limit_surface.h): a point's face neighbourhood is refined locally
// towards it until it lies in a regular patch, or, past maxDepth, in a sub-face small enough to
// interpolate from its next level's exact limit points (docs/surface.md).
#include <quadtri/far/limit_surface.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <quadtri/far/refiner.h>
#include "far/fvar/fvar_channel.h"
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

// Under Sharpen::All a face is its corners' bilinear (linear) patch.
PatchKind linearPatch(const LocalMesh& mesh, std::vector<int>& points) {
    const IndexSpan corners = mesh.topology.verticesOfFace(mesh.face);
    points.assign(corners.begin(), corners.end());
    return corners.size() == 4 ? PatchKind::Bilinear : PatchKind::Linear;
}

// The weights of (u, v) of `face` over `base`'s vertices (`o` with counter-clockwise faces).
void localStencil(const Topology& base, const Options& o, const LimitSurfaceOptions& surfaceOptions, Sharpen sharpen,
                  int face, double u, double v, LimitPointStencil& out) {
    const SchemeRules& rules = rulesOf(o.scheme);
    const int rings = surfaceOptions.rings > 0 ? surfaceOptions.rings : rules.surfaceRings();
    const bool linear = sharpen == Sharpen::All && rules.surfacePatches().sharpIsLinear;
    thread_local WalkScratch baseScratch;  // sized to the largest base mesh once per thread
    WalkScratch scratch;
    std::vector<int> columns;
    LocalMesh mesh = cutBase(base, face, rings, o, baseScratch, columns, sharpen);

    Where w;
    w.s = u;
    w.t = v;
    const FaceParameterization param = FaceParameterization::of(o.scheme, base.faceSize(face));
    int depth = 0;
    if (param.type == FaceParameterization::Type::QuadSubFaces) {
        mesh = refineTowards(mesh, enterSubFace(param, u, v, w), rings, o, scratch, nullptr, sharpen);
        depth = 1;
    }

    LimitMask local;  // weights over the final local mesh's vertices
    std::vector<int> points;
    double wP[16], wDs[16], wDt[16];
    for (;; ++depth) {
        const PatchKind kind = linear ? linearPatch(mesh, points) : regularPatch(mesh.topology, mesh.face, o, points);
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
        if (depth >= surfaceOptions.maxDepth) {
            // The quadratic through the exact limit points of the sub-face's next level.
            std::vector<int> nodes;
            LocalMesh next = refineTowards(mesh, 0, rings, o, scratch, &nodes, sharpen);
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
        mesh = refineTowards(mesh, child, rings, o, scratch, nullptr, sharpen);
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

// The stencil applied to `control`.
void apply(const LimitPointStencil& s, const float* control, int width, int stride, float* position, float* dPdu,
           float* dPdv) {
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

}  // namespace

// A face-varying channel: its value mesh, refined locally as the mesh is, with the sharpness
// its seams take (docs/surface.md, "Face-varying values").
struct LimitSurface::Channel {
    Topology values;
    std::vector<int> valueOf;       // per vertex of `values`: the channel's value
    std::vector<int> cornerValues;  // per corner of `values` (the mesh's faces): the channel's value
    int numValues = 0;
    Options options;           // the mesh's, but a value-mesh corner is sharp by its tag only
    Sharpen sharpen = Sharpen::None;
};

LimitSurface::LimitSurface(const Refiner& refiner, LimitSurfaceOptions surfaceOptions)
    : options_(refiner.options()), surfaceOptions_(surfaceOptions),
      base_(std::make_shared<const Topology>(refiner.level(0))) {
    if (surfaceOptions_.maxDepth < 1 || surfaceOptions_.maxDepth > 30)
        throw SurfaceError("LimitSurface: maxDepth " + std::to_string(surfaceOptions_.maxDepth) +
                           " is outside 1..30");
    if (surfaceOptions_.rings < 0) throw SurfaceError("LimitSurface: rings must be 0 (the scheme's) or more");
    for (int c = 0; c < refiner.numFVarChannels(); ++c) {
        const FVarChannelRefinement& source = refiner.channel(c);
        auto channel = std::make_shared<Channel>();
        channel->values = source.surfaceMesh();
        channel->valueOf = source.valueOfVertex();
        channel->numValues = source.numValues(0);
        for (int p : channel->values.faceVerts) channel->cornerValues.push_back(channel->valueOf[std::size_t(p)]);
        channel->options = options_;
        channel->options.leftHanded = false;
        channel->options.boundary = BoundaryInterpolation::EdgeOnly;
        switch (options_.fvarLinearInterpolation) {
            case FVarLinearInterpolation::Boundaries: channel->sharpen = Sharpen::Boundaries; break;
            case FVarLinearInterpolation::All: channel->sharpen = Sharpen::All; break;
            default: break;
        }
        channels_.push_back(std::move(channel));
    }
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
    localStencil(*base_, o, surfaceOptions_, Sharpen::None, face, u, v, out);
}

void LimitSurface::evaluate(int face, double u, double v, const float* control, int width, int stride,
                            float* position, float* dPdu, float* dPdv) const {
    LimitPointStencil s;
    stencil(face, u, v, s);
    apply(s, control, width, stride, position, dPdu, dPdv);
}

LimitStencilTable LimitSurface::stencilTable(int count, const int* faces, const double* u, const double* v) const {
    return tableOf(count, faces, u, v, numControlVertices(),
                   [this](int face, double u, double v, LimitPointStencil& s) { stencil(face, u, v, s); });
}

const LimitSurface::Channel& LimitSurface::channel(int c) const {
    if (c < 0 || c >= numFVarChannels())
        throw SurfaceError("face-varying channel " + std::to_string(c) + " asked for; the mesh has " +
                           std::to_string(numFVarChannels()));
    return *channels_[std::size_t(c)];
}

int LimitSurface::numFVarValues(int c) const { return channel(c).numValues; }

IndexSpan LimitSurface::fvarValuesOfFace(int c, int face) const {
    const Channel& ch = channel(c);
    parameterization(face);  // the range check
    const int* corners = ch.cornerValues.data();
    return {corners + base_->faceOffsets[std::size_t(face)], corners + base_->faceOffsets[std::size_t(face) + 1]};
}

// Over the value mesh's vertices first, then over the channel's values: value-vertices that
// carry the same value merge.
void LimitSurface::fvarStencil(int c, int face, double u, double v, LimitPointStencil& out) const {
    const Channel& ch = channel(c);
    check(face, u, v);
    LimitPointStencil local;
    localStencil(ch.values, ch.options, surfaceOptions_, ch.sharpen, face, u, v, local);
    out.indices.clear();
    out.position.clear();
    out.du.clear();
    out.dv.clear();
    for (int k = 0; k < local.size(); ++k) {
        const int value = ch.valueOf[std::size_t(local.indices[std::size_t(k)])];
        const auto at = std::find(out.indices.begin(), out.indices.end(), value);
        if (at == out.indices.end()) {
            out.indices.push_back(value);
            out.position.push_back(local.position[std::size_t(k)]);
            out.du.push_back(local.du[std::size_t(k)]);
            out.dv.push_back(local.dv[std::size_t(k)]);
            continue;
        }
        const std::size_t j = std::size_t(at - out.indices.begin());
        out.position[j] += local.position[std::size_t(k)];
        out.du[j] += local.du[std::size_t(k)];
        out.dv[j] += local.dv[std::size_t(k)];
    }
}

void LimitSurface::evaluateFVar(int c, int face, double u, double v, const float* values, int width, int stride,
                                float* value, float* dValuedu, float* dValuedv) const {
    LimitPointStencil s;
    fvarStencil(c, face, u, v, s);
    apply(s, values, width, stride, value, dValuedu, dValuedv);
}

LimitStencilTable LimitSurface::fvarStencilTable(int c, int count, const int* faces, const double* u,
                                                 const double* v) const {
    return tableOf(count, faces, u, v, numFVarValues(c),
                   [this, c](int face, double u, double v, LimitPointStencil& s) { fvarStencil(c, face, u, v, s); });
}

template <class StencilOf>
LimitStencilTable LimitSurface::tableOf(int count, const int* faces, const double* u, const double* v,
                                        int numSources, const StencilOf& stencilOf) const {
    for (int i = 0; i < count; ++i) {
        try {
            check(faces[i], u[i], v[i]);
        } catch (const SurfaceError& e) {
            throw SurfaceError("point " + std::to_string(i) + ": " + e.what());
        }
    }
    LimitStencilTableD table;
    table.numSourceVertices = numSources;
    // Blocks of points side by side, each point's stencil its own: the same table on any threads.
    constexpr int kBlock = 4096;
    std::vector<LimitPointStencil> block(std::size_t(std::min(count, kBlock)));
    for (int first = 0; first < count; first += kBlock) {
        const int size = std::min(kBlock, count - first);
        parallel::forEachRange(0, size, 16, [&](int begin, int end) {
            for (int i = begin; i < end; ++i)
                stencilOf(faces[first + i], u[first + i], v[first + i], block[std::size_t(i)]);
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

}  // namespace v0
}  // namespace quadtri
