// LimitSurface (quadtri/far/limit_surface.h): a point's face neighbourhood is refined locally
// towards it until it lies in a regular patch, or, past maxDepth, in a sub-face small enough to
// interpolate from its next level's exact limit points (docs/surface.md).
#include <quadtri/far/limit_surface.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include <quadtri/far/refiner.h>
#include "far/fvar/fvar_channel.h"
#include "far/internal/parallel.h"
#include "far/limit/limit_eigen.h"
#include "far/limit/limit_mask.h"
#include "far/limit/limit_ring.h"
#include "far/limit/limit_table.h"
#include "far/schemes/scheme.h"
#include "far/surface/face_tree.h"
#include "far/surface/patch_basis.h"
#include "far/surface/patch_points.h"
#include "far/topology/topology_builder.h"

namespace quadtri {
inline namespace v0 {

using namespace internal;

namespace {

Options counterClockwise(Options o) {
    o.leftHanded = false;  // every level stores its faces counter-clockwise already
    return o;
}

// A value mesh's stencil over the channel's values: value-vertices that carry the same value merge.
void mergeValues(const std::vector<int>& valueOf, const LimitPointStencil& local, LimitPointStencil& out) {
    out.indices.clear();
    out.position.clear();
    out.du.clear();
    out.dv.clear();
    for (int k = 0; k < local.size(); ++k) {
        const int value = valueOf[std::size_t(local.indices[std::size_t(k)])];
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

// The weights of (u, v) of `face` over `base`'s vertices (`o` with counter-clockwise faces), on
// a tree of its own.
void localStencil(const Topology& base, const Options& o, const LimitSurfaceOptions& surfaceOptions, Sharpen sharpen,
                  int face, double u, double v, LimitPointStencil& out) {
    thread_local WalkScratch baseScratch;  // sized to the largest base mesh once per thread
    FaceTrees trees(base, o, surfaceOptions, sharpen, baseScratch);
    std::vector<int> columns;
    trees.treeOf(face, columns).stencil(u, v, columns.data(), out);
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
    : LimitSurface(refiner.options(), surfaceOptions, std::make_shared<const Topology>(refiner.level(0))) {
    for (int c = 0; c < refiner.numFVarChannels(); ++c) addChannel(refiner.channel(c));
}

LimitSurface::LimitSurface(const TopologyDescriptor& desc, const Options& options, LimitSurfaceOptions surfaceOptions)
    : LimitSurface(options, surfaceOptions, std::make_shared<const Topology>(buildBaseTopology(desc, options))) {
    for (int c = 0; c < desc.numFVarChannels; ++c) addChannel(FVarChannelRefinement(desc, c, *base_, options_));
}

LimitSurface::LimitSurface(const Options& options, LimitSurfaceOptions surfaceOptions,
                           std::shared_ptr<const Topology> base)
    : options_(options), surfaceOptions_(surfaceOptions), base_(std::move(base)) {
    if (surfaceOptions_.maxDepth < 1 || surfaceOptions_.maxDepth > 30)
        throw SurfaceError("LimitSurface: maxDepth " + std::to_string(surfaceOptions_.maxDepth) +
                           " is outside 1..30");
    if (surfaceOptions_.rings < 0) throw SurfaceError("LimitSurface: rings must be 0 (the scheme's) or more");
}

void LimitSurface::addChannel(const FVarChannelRefinement& source) {
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
    localStencil(*base_, counterClockwise(options_), surfaceOptions_, Sharpen::None, face, u, v, out);
}

void LimitSurface::evaluate(int face, double u, double v, const float* control, int width, int stride,
                            float* position, float* dPdu, float* dPdv) const {
    LimitPointStencil s;
    stencil(face, u, v, s);
    apply(s, control, width, stride, position, dPdu, dPdv);
}

LimitStencilTable LimitSurface::stencilTable(int count, const int* faces, const double* u, const double* v) const {
    return tableOf(-1, count, faces, u, v);
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

void LimitSurface::fvarStencil(int c, int face, double u, double v, LimitPointStencil& out) const {
    const Channel& ch = channel(c);
    check(face, u, v);
    LimitPointStencil local;
    localStencil(ch.values, ch.options, surfaceOptions_, ch.sharpen, face, u, v, local);
    mergeValues(ch.valueOf, local, out);
}

void LimitSurface::evaluateFVar(int c, int face, double u, double v, const float* values, int width, int stride,
                                float* value, float* dValuedu, float* dValuedv) const {
    LimitPointStencil s;
    fvarStencil(c, face, u, v, s);
    apply(s, values, width, stride, value, dValuedu, dValuedv);
}

LimitStencilTable LimitSurface::fvarStencilTable(int c, int count, const int* faces, const double* u,
                                                 const double* v) const {
    channel(c);  // the range check
    return tableOf(c, count, faces, u, v);
}

// Points grouped by face (groups of at most kGroup points, the threads' tasks), each thread's
// trees kept for the whole table: the same stencils as one point at a time, in any order, on any
// number of threads.
LimitStencilTable LimitSurface::tableOf(int c, int count, const int* faces, const double* u, const double* v) const {
    for (int i = 0; i < count; ++i) {
        try {
            check(faces[i], u[i], v[i]);
        } catch (const SurfaceError& e) {
            throw SurfaceError("point " + std::to_string(i) + ": " + e.what());
        }
    }
    const Channel* ch = c >= 0 ? &channel(c) : nullptr;
    const Topology& topology = ch ? ch->values : *base_;
    const Options o = ch ? ch->options : counterClockwise(options_);
    const Sharpen sharpen = ch ? ch->sharpen : Sharpen::None;

    LimitStencilTableD table;
    table.numSourceVertices = ch ? ch->numValues : numControlVertices();
    constexpr int kBlock = 16384, kGroup = 256;
    std::vector<LimitPointStencil> block(std::size_t(std::min(count, kBlock)));
    std::vector<int> order, groups;
    // Each thread's trees, shared by its faces of one shape for the whole table.
    parallel::ThreadLocal<std::unique_ptr<FaceTrees>> treesOfThread([] { return std::unique_ptr<FaceTrees>(); });
    for (int first = 0; first < count; first += kBlock) {
        const int size = std::min(kBlock, count - first);
        order.resize(std::size_t(size));
        for (int i = 0; i < size; ++i) order[std::size_t(i)] = i;
        std::stable_sort(order.begin(), order.end(),
                         [&](int a, int b) { return faces[first + a] < faces[first + b]; });
        groups.assign(1, 0);
        for (int i = 1; i < size; ++i)
            if (faces[first + order[std::size_t(i)]] != faces[first + order[std::size_t(i) - 1]] ||
                i - groups.back() == kGroup)
                groups.push_back(i);
        groups.push_back(size);
        parallel::forEachRange(0, int(groups.size()) - 1, 1, [&](int begin, int end) {
            thread_local WalkScratch baseScratch;
            std::unique_ptr<FaceTrees>& trees = treesOfThread.local();
            if (!trees) {
                trees = std::make_unique<FaceTrees>(topology, o, surfaceOptions_, sharpen, baseScratch);
                trees->keepRings();
            }
            LimitPointStencil local;
            std::vector<int> columns;
            for (int g = begin; g < end; ++g) {
                const int face = faces[first + order[std::size_t(groups[std::size_t(g)])]];
                FaceTree& tree = trees->treeOf(face, columns);
                for (int k = groups[std::size_t(g)]; k < groups[std::size_t(g) + 1]; ++k) {
                    const int i = order[std::size_t(k)];
                    LimitPointStencil& s = block[std::size_t(i)];
                    if (!ch) {
                        tree.stencil(u[first + i], v[first + i], columns.data(), s);
                        continue;
                    }
                    tree.stencil(u[first + i], v[first + i], columns.data(), local);
                    mergeValues(ch->valueOf, local, s);
                }
            }
        });
        if (first == 0) {
            // The whole table reserved at the first block's entries a point: growing the double
            // arrays by doubling costs more than the stencils (copies and fresh pages of tens of MB).
            std::size_t entries = 0;
            for (int i = 0; i < size; ++i) entries += std::size_t(block[std::size_t(i)].size());
            const std::size_t estimate = entries / std::size_t(size) * std::size_t(count) + entries;
            table.offsets.reserve(std::size_t(count));
            table.sizes.reserve(std::size_t(count));
            table.indices.reserve(estimate);
            table.weights.reserve(3 * estimate);
        }
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

namespace {

// N components of a located point's leaf points (its rows over the control values, column j at
// control[sources[j] * stride + c]), in double: what every point in that leaf sums. The leaf's
// columns are read once each, then the rows sum them.
template <int N>
void leafPoints(const FaceTree& tree, const FaceTree::Located& at, const int* sources, const float* control,
                int stride, int c, double points[][N]) {
    thread_local std::vector<double> columns;
    columns.resize(std::size_t(at.numColumns) * N);
    for (int i = 0; i < at.numColumns; ++i) {
        const float* src = control + std::size_t(sources[tree.leafColumn(at.firstColumn + i)]) * std::size_t(stride) + c;
        for (int j = 0; j < N; ++j) columns[std::size_t(i) * N + std::size_t(j)] = src[j];
    }
    for (int i = 0; i < at.count; ++i) {
        double q[N] = {};
        const int row = at.firstRow + i;
        for (int k = tree.rowBegin(row); k < tree.rowBegin(row + 1); ++k) {
            const double x = tree.rowWeight(k);
            const double* column = &columns[std::size_t(tree.rowSlot(k)) * N];
            for (int j = 0; j < N; ++j) q[j] += x * column[j];
        }
        for (int j = 0; j < N; ++j) points[i][j] = q[j];
    }
}

// Components [c, c + N) of a located point from its leaf's points: the basis's sums, the
// derivatives taken to the face's (u, v).
template <int N>
void leafPoint(const FaceTree::Located& at, const double points[][N], int c, float* position, float* dPdu,
               float* dPdv) {
    double p[N] = {}, s[N] = {}, t[N] = {};
    for (int i = 0; i < at.count; ++i)
        for (int j = 0; j < N; ++j) {
            p[j] += at.wP[i] * points[i][j];
            s[j] += at.wDs[i] * points[i][j];
            t[j] += at.wDt[i] * points[i][j];
        }
    for (int j = 0; j < N; ++j) {
        position[c + j] = float(p[j]);
        if (dPdu) dPdu[c + j] = float(s[j] * at.k[0][0] + t[j] * at.k[1][0]);
        if (dPdv) dPdv[c + j] = float(s[j] * at.k[0][1] + t[j] * at.k[1][1]);
    }
}

// Components [c0, c0 + N) of a point and its derivatives from their sums in double.
template <int N>
void storeSums(const double p[N], const double su[N], const double sv[N], int c0, float* position, float* dPdu,
               float* dPdv) {
    for (int c = 0; c < N; ++c) {
        position[c0 + c] = float(p[c]);
        if (dPdu) dPdu[c0 + c] = float(su[c]);
        if (dPdv) dPdv[c0 + c] = float(sv[c]);
    }
}

// N components of a regular quad's point straight from its 16 points (point k's components at
// points[k][in0 ..], written to position[out0 ..]): the basis is a tensor product, so each row's
// curve first, then the rows, in double. The same sums as the tree's weights in another order:
// within rounding of the stencil applied.
template <int N, class T>
void bSplinePoint(const double bs[4], const double ds[4], const double bt[4], const double dt[4],
                  const T* const points[16], int in0, int out0, float* position, float* dPdu, float* dPdv) {
    double p[N] = {}, su[N] = {}, sv[N] = {};
    for (int r = 0; r < 4; ++r) {
        double q[N] = {}, dq[N] = {};
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < N; ++c) {
                const double x = points[4 * r + k][in0 + c];
                q[c] += bs[k] * x;
                dq[c] += ds[k] * x;
            }
        for (int c = 0; c < N; ++c) {
            p[c] += bt[r] * q[c];
            su[c] += bt[r] * dq[c];
            sv[c] += dt[r] * q[c];
        }
    }
    storeSums<N>(p, su, sv, out0, position, dPdu, dPdv);
}

void bSplinePoint(double u, double v, const int* sources, const float* control, int width, int stride,
                  float* position, float* dPdu, float* dPdv) {
    double bs[4], ds[4], bt[4], dt[4];
    internal::cubicBSplineWeights(u, bs, ds);
    internal::cubicBSplineWeights(v, bt, dt);
    const float* points[16];
    for (int k = 0; k < 16; ++k) points[k] = control + std::size_t(sources[k]) * std::size_t(stride);
    byComponentGroups(width, [&](auto n, int c) {
        bSplinePoint<decltype(n)::value>(bs, ds, bt, dt, points, c, c, position, dPdu, dPdv);
    });
}

// N components of a regular triangle's point straight from its 12 points (as bSplinePoint):
// the box spline's weights at (u, v), then each sum in double.
template <int N>
void boxSplinePoint(const double wP[12], const double wDs[12], const double wDt[12], const float* const points[12],
                    int c0, float* position, float* dPdu, float* dPdv) {
    double p[N] = {}, su[N] = {}, sv[N] = {};
    for (int k = 0; k < 12; ++k)
        for (int c = 0; c < N; ++c) {
            const double x = points[k][c0 + c];
            p[c] += wP[k] * x;
            su[c] += wDs[k] * x;
            sv[c] += wDt[k] * x;
        }
    storeSums<N>(p, su, sv, c0, position, dPdu, dPdv);
}

void boxSplinePoint(double u, double v, const int* sources, const float* control, int width, int stride,
                    float* position, float* dPdu, float* dPdv) {
    double wP[12], wDs[12], wDt[12];
    internal::boxSplineWeights(u, v, wP, wDs, wDt);
    const float* points[12];
    for (int k = 0; k < 12; ++k) points[k] = control + std::size_t(sources[k]) * std::size_t(stride);
    byComponentGroups(width, [&](auto n, int c) {
        boxSplinePoint<decltype(n)::value>(wP, wDs, wDt, points, c, position, dPdu, dPdv);
    });
}

}  // namespace

// The factory's trees and the scratch they cut with, kept alive by every FaceSurface it made.
struct FaceSurfaceFactory::Shared {
    Shared(const Topology& base, const Options& o, const LimitSurfaceOptions& so, Sharpen sharpen)
        : trees(base, o, so, sharpen, scratch) {}
    WalkScratch scratch;
    FaceTrees trees;
};

FaceSurfaceFactory::FaceSurfaceFactory(const LimitSurface& surface, int channel) : surface_(&surface) {
    if (channel >= 0 || channel < -1) {
        const LimitSurface::Channel& ch = surface.channel(channel);
        valueOf_ = &ch.valueOf;
        shared_ = std::make_shared<Shared>(ch.values, ch.options, surface.surfaceOptions_, ch.sharpen);
    } else {
        shared_ = std::make_shared<Shared>(*surface.base_, counterClockwise(surface.options_), surface.surfaceOptions_,
                                           Sharpen::None);
    }
}

FaceSurfaceFactory::~FaceSurfaceFactory() = default;

int FaceSurfaceFactory::numShapes() const { return shared_->trees.numShapes(); }

FaceSurface FaceSurfaceFactory::faceSurface(int face) {
    FaceSurface out;
    faceSurface(face, out);
    return out;
}

void FaceSurfaceFactory::faceSurface(int face, FaceSurface& out) {
    const Topology& base = surface_->topology();
    if (face < 0 || face >= base.numFaces()) surface_->parameterization(face);  // throws: out of range
    if (base.faceHole[std::size_t(face)])
        throw SurfaceError("face " + std::to_string(face) + " is a hole: it has no surface");
    if (out.shared_ != shared_) out.shared_ = shared_;
    out.face_ = face;
    const internal::FaceTrees::Kept& kept = shared_->trees.keptTreeOf(face);
    out.tree_ = kept.tree;
    out.columns_ = kept.columns;
    out.valueOf_ = valueOf_;
    if (valueOf_) {
        out.sources_.resize(std::size_t(kept.numColumns));
        for (int j = 0; j < kept.numColumns; ++j) out.sources_[std::size_t(j)] = (*valueOf_)[std::size_t(kept.columns[j])];
    }
}

FaceSurface::FaceSurface() = default;
FaceSurface::~FaceSurface() = default;
FaceSurface::FaceSurface(FaceSurface&&) noexcept = default;
FaceSurface& FaceSurface::operator=(FaceSurface&&) noexcept = default;

int FaceSurface::face() const { return face_; }

const FaceParameterization& FaceSurface::parameterization() const {
    if (!tree_) throw SurfaceError("FaceSurface: empty (FaceSurfaceFactory::faceSurface makes them)");
    return tree_->parameterization();
}

void FaceSurface::stencil(double u, double v, LimitPointStencil& out) {
    check(u, v, -1);
    if (!valueOf_) return tree_->stencil(u, v, columns_, out);
    tree_->stencil(u, v, columns_, local_);
    mergeValues(*valueOf_, local_, out);
}

void FaceSurface::check(double u, double v, int point) const {
    const FaceParameterization& p = parameterization();
    if (p.contains(u, v)) return;
    throw SurfaceError("face " + std::to_string(face()) + (point >= 0 ? ", point " + std::to_string(point) : "") +
                       ": (" + std::to_string(u) + ", " + std::to_string(v) + ") is outside its domain (" +
                       p.describe() + ")");
}

void FaceSurface::evaluate(double u, double v, const float* control, int width, int stride, float* position,
                           float* dPdu, float* dPdv) {
    check(u, v, -1);
    const int* sources = valueOf_ ? sources_.data() : columns_;
    switch (tree_->regularBasis()) {
    case FaceTree::Leaf::BSpline: return bSplinePoint(u, v, sources, control, width, stride, position, dPdu, dPdv);
    case FaceTree::Leaf::BoxSpline: return boxSplinePoint(u, v, sources, control, width, stride, position, dPdu, dPdv);
    default: break;
    }
    FaceTree::Located at;
    tree_->locate(u, v, at);
    byComponentGroups(width, [&](auto n, int c) {
        double points[16][decltype(n)::value];
        leafPoints<decltype(n)::value>(*tree_, at, sources, control, stride, c, points);
        leafPoint<decltype(n)::value>(at, points, c, position, dPdu, dPdv);
    });
}

void FaceSurface::evaluate(int count, const double* u, const double* v, const float* control, int width, int stride,
                           float* position, float* dPdu, float* dPdv, int outStride) {
    parameterization();  // SurfaceError for an empty surface
    if (count < 0) throw SurfaceError("FaceSurface::evaluate: " + std::to_string(count) + " points");
    if (outStride != 0 && outStride < width)
        throw SurfaceError("FaceSurface::evaluate: outputs " + std::to_string(outStride) + " floats apart hold " +
                           std::to_string(width) + " each");
    for (int i = 0; i < count; ++i) check(u[i], v[i], i);
    const PatchPoints points{count, u, v, width, position, dPdu, dPdv, outStride > 0 ? outStride : width};
    const int* sources = valueOf_ ? sources_.data() : columns_;
    switch (tree_->regularBasis()) {
    case FaceTree::Leaf::BSpline: return bSplinePoints(sources, control, stride, points);
    case FaceTree::Leaf::BoxSpline: return boxSplinePoints(sources, control, stride, points);
    default: break;
    }
    // Any other face: each point located in the tree, then the points leaf by leaf, each leaf's
    // points summed once for all of its points (the same sums as one point at a time); in chunks,
    // so that the scratch stays small whatever the batch.
    constexpr int kChunk = 256;
    thread_local std::vector<FaceTree::Located> located;
    thread_local std::vector<int> order;
    for (int begin = 0; begin < count; begin += kChunk) {
        const int size = std::min(kChunk, count - begin);
        located.resize(std::size_t(size));
        order.resize(std::size_t(size));
        for (int i = 0; i < size; ++i) {
            tree_->locate(u[begin + i], v[begin + i], located[std::size_t(i)]);
            order[std::size_t(i)] = i;
        }
        auto leafOf = [&](int k) { return located[std::size_t(order[std::size_t(k)])].firstRow; };
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
            return located[std::size_t(a)].firstRow < located[std::size_t(b)].firstRow;
        });
        for (int first = 0, end = 0; first < size; first = end) {
            while (end < size && leafOf(end) == leafOf(first)) ++end;
            byComponentGroups(width, [&](auto n, int c) {
                constexpr int N = decltype(n)::value;
                double leafValues[16][N];
                leafPoints<N>(*tree_, located[std::size_t(order[std::size_t(first)])], sources, control, stride, c,
                              leafValues);
                for (int k = first; k < end; ++k) {
                    const int i = order[std::size_t(k)];
                    const std::size_t at = std::size_t(begin + i) * std::size_t(points.outStride);
                    leafPoint<N>(located[std::size_t(i)], leafValues, c, position + at, dPdu ? dPdu + at : nullptr,
                                 dPdv ? dPdv + at : nullptr);
                }
            });
        }
    }
}

}  // namespace v0
}  // namespace quadtri
