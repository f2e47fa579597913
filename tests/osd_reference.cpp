#include "tests/osd_reference.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <opensubdiv/sdc/crease.h>
#include <opensubdiv/sdc/options.h>
#include <opensubdiv/sdc/types.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace quadtri::test {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;
namespace Bfr = OpenSubdiv::Bfr;

const char* toString(OsdScheme scheme) {
    switch (scheme) {
        case OsdScheme::Catmark: return "Catmark";
        case OsdScheme::Loop: return "Loop";
        case OsdScheme::Bilinear: return "Bilinear";
    }
    return "?";
}

const char* vertexRuleName(int rule) {
    switch (rule) {
        case Sdc::Crease::RULE_SMOOTH: return "smooth";
        case Sdc::Crease::RULE_DART: return "dart";
        case Sdc::Crease::RULE_CREASE: return "crease";
        case Sdc::Crease::RULE_CORNER: return "corner";
        default: return "unknown";
    }
}

int OsdRefinement::numHoleFaces(int level) const {
    const std::vector<char>& holes = faceHole.at(level);
    return int(std::count(holes.begin(), holes.end(), char(1)));
}

namespace {

// The primvar type Far::PrimvarRefiner interpolates: one xyz position.
struct Vertex {
    float p[3];
    void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0.0f; }
    void AddWithWeight(const Vertex& src, float weight) {
        p[0] += weight * src.p[0];
        p[1] += weight * src.p[1];
        p[2] += weight * src.p[2];
    }
};

Sdc::SchemeType sdcScheme(OsdScheme scheme) {
    switch (scheme) {
        case OsdScheme::Catmark: return Sdc::SCHEME_CATMARK;
        case OsdScheme::Loop: return Sdc::SCHEME_LOOP;
        case OsdScheme::Bilinear: return Sdc::SCHEME_BILINEAR;
    }
    throw std::invalid_argument("unknown OsdScheme");
}

Sdc::Options::VtxBoundaryInterpolation sdcBoundary(BoundaryInterpolation boundary) {
    switch (boundary) {
        case BoundaryInterpolation::EdgeOnly: return Sdc::Options::VTX_BOUNDARY_EDGE_ONLY;
        case BoundaryInterpolation::EdgeAndCorner: return Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER;
        case BoundaryInterpolation::None: return Sdc::Options::VTX_BOUNDARY_NONE;
    }
    throw std::invalid_argument("unknown BoundaryInterpolation");
}

Sdc::Options::CreasingMethod sdcCreasing(CreaseMethod method) {
    switch (method) {
        case CreaseMethod::Uniform: return Sdc::Options::CREASE_UNIFORM;
        case CreaseMethod::Chaikin: return Sdc::Options::CREASE_CHAIKIN;
    }
    throw std::invalid_argument("unknown CreaseMethod");
}

}  // namespace

namespace {

// `mesh`'s faces, creases, corners and holes as OpenSubdiv's descriptor (pointing into `mesh`).
Far::TopologyDescriptor osdDescriptorOf(const io::ObjMesh& mesh) {
    Far::TopologyDescriptor desc;
    desc.numVertices = mesh.numVertices();
    desc.numFaces = mesh.numFaces();
    desc.numVertsPerFace = mesh.faceSizes.data();
    desc.vertIndicesPerFace = mesh.faceVerts.data();
    desc.numCreases = int(mesh.creaseSharpness.size());
    desc.creaseVertexIndexPairs = mesh.creasePairs.data();
    desc.creaseWeights = mesh.creaseSharpness.data();
    desc.numCorners = int(mesh.cornerSharpness.size());
    desc.cornerVertexIndices = mesh.corners.data();
    desc.cornerWeights = mesh.cornerSharpness.data();
    desc.numHoles = int(mesh.holes.size());
    desc.holeIndices = mesh.holes.data();
    return desc;
}

// OpenSubdiv's refiner of `desc` (not yet refined); std::runtime_error if it refuses the topology.
std::unique_ptr<Far::TopologyRefiner> refinerOf(const Far::TopologyDescriptor& desc, OsdScheme scheme,
                                                const Sdc::Options& sdcOptions) {
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(
        Factory::Create(desc, Factory::Options(sdcScheme(scheme), sdcOptions)));
    if (!refiner) throw std::runtime_error("OpenSubdiv refused the topology (see its error output)");
    return refiner;
}

// OpenSubdiv's refiner of `mesh` (not yet refined): creases, corners and holes through the
// Far::TopologyDescriptor, the Sdc options from the arguments.
std::unique_ptr<Far::TopologyRefiner> createRefiner(const io::ObjMesh& mesh, OsdScheme scheme,
                                                    BoundaryInterpolation boundary, CreaseMethod creaseMethod,
                                                    bool smoothTriangles, bool leftHanded) {
    Sdc::Options sdcOptions;
    sdcOptions.SetVtxBoundaryInterpolation(sdcBoundary(boundary));
    sdcOptions.SetCreasingMethod(sdcCreasing(creaseMethod));
    sdcOptions.SetTriangleSubdivision(smoothTriangles ? Sdc::Options::TRI_SUB_SMOOTH : Sdc::Options::TRI_SUB_CATMARK);

    Far::TopologyDescriptor desc = osdDescriptorOf(mesh);
    desc.isLeftHanded = leftHanded;
    return refinerOf(desc, scheme, sdcOptions);
}

}  // namespace

OsdRefinement osdRefine(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                        CreaseMethod creaseMethod, int maxLevel, bool smoothTriangles) {
    if (maxLevel < 0) throw std::invalid_argument("osdRefine: negative level");
    // Orientation does not change any vertex position, so isLeftHanded keeps its default.
    std::unique_ptr<Far::TopologyRefiner> refiner =
        createRefiner(mesh, scheme, boundary, creaseMethod, smoothTriangles, false);

    Far::TopologyRefiner::UniformOptions uniform(maxLevel);
    uniform.fullTopologyInLastLevel = true;
    refiner->RefineUniform(uniform);

    OsdRefinement out;
    std::vector<std::vector<Vertex>> levels(maxLevel + 1);
    levels[0].resize(mesh.numVertices());
    for (int v = 0; v < mesh.numVertices(); ++v)
        for (int c = 0; c < 3; ++c) levels[0][v].p[c] = mesh.positions[3 * size_t(v) + c];

    Far::PrimvarRefiner primvar(*refiner);
    for (int L = 1; L <= maxLevel; ++L) {
        levels[L].resize(refiner->GetLevel(L).GetNumVertices());
        const Vertex* src = levels[L - 1].data();
        Vertex* dst = levels[L].data();
        primvar.Interpolate(L, src, dst);
    }

    for (int L = 0; L <= maxLevel; ++L) {
        const Far::TopologyLevel& level = refiner->GetLevel(L);
        out.numVertices.push_back(level.GetNumVertices());
        out.numFaces.push_back(level.GetNumFaces());
        std::vector<char> holes(level.GetNumFaces());
        for (int f = 0; f < level.GetNumFaces(); ++f) holes[f] = level.IsFaceHole(f) ? 1 : 0;
        out.faceHole.push_back(std::move(holes));
        std::vector<float> xyz(levels[L].size() * 3);
        for (size_t v = 0; v < levels[L].size(); ++v)
            for (int c = 0; c < 3; ++c) xyz[3 * v + c] = levels[L][v].p[c];
        out.positions.push_back(std::move(xyz));

        OsdLevelTopology t;
        const bool hasChildren = L < maxLevel;
        // Splitting into triangles (Loop) gives faces no child vertex; the table is empty then.
        const bool faceChildren = hasChildren && Sdc::SchemeTypeTraits::GetTopologicalSplitType(sdcScheme(scheme)) ==
                                                     Sdc::SPLIT_TO_QUADS;
        for (int f = 0; f < level.GetNumFaces(); ++f) {
            Far::ConstIndexArray fv = level.GetFaceVertices(f);
            for (int k = 0; k < fv.size(); ++k) t.faceVerts.push_back(fv[k]);
            t.faceOffsets.push_back(int(t.faceVerts.size()));
            t.faceChild.push_back(faceChildren ? level.GetFaceChildVertex(f) : -1);
        }
        for (int e = 0; e < level.GetNumEdges(); ++e) {
            Far::ConstIndexArray ev = level.GetEdgeVertices(e);
            t.edgeVerts.push_back(ev[0]);
            t.edgeVerts.push_back(ev[1]);
            t.edgeChild.push_back(hasChildren ? level.GetEdgeChildVertex(e) : -1);
            t.edgeSharpness.push_back(level.GetEdgeSharpness(e));
            t.edgeNonManifold.push_back(level.IsEdgeNonManifold(e) ? 1 : 0);
        }
        for (int v = 0; v < level.GetNumVertices(); ++v) {
            t.vertexChild.push_back(hasChildren ? level.GetVertexChildVertex(v) : -1);
            t.vertexSharpness.push_back(level.GetVertexSharpness(v));
            t.vertexRule.push_back(int(level.GetVertexRule(v)));
            t.vertexBoundary.push_back(level.IsVertexBoundary(v) ? 1 : 0);
            t.vertexNonManifold.push_back(level.IsVertexNonManifold(v) ? 1 : 0);
        }
        out.topology.push_back(std::move(t));
    }
    return out;
}

namespace {

template <class Real>
struct UVOf {
    Real p[2];
    void Clear(void* = nullptr) { p[0] = p[1] = Real(0); }
    void AddWithWeight(const UVOf& src, Real weight) {
        p[0] += weight * src.p[0];
        p[1] += weight * src.p[1];
    }
};
using UV = UVOf<float>;

Sdc::Options::FVarLinearInterpolation sdcFVar(FVarLinearInterpolation fvar) {
    switch (fvar) {
        case FVarLinearInterpolation::None: return Sdc::Options::FVAR_LINEAR_NONE;
        case FVarLinearInterpolation::CornersOnly: return Sdc::Options::FVAR_LINEAR_CORNERS_ONLY;
        case FVarLinearInterpolation::CornersPlus1: return Sdc::Options::FVAR_LINEAR_CORNERS_PLUS1;
        case FVarLinearInterpolation::CornersPlus2: return Sdc::Options::FVAR_LINEAR_CORNERS_PLUS2;
        case FVarLinearInterpolation::Boundaries: return Sdc::Options::FVAR_LINEAR_BOUNDARIES;
        case FVarLinearInterpolation::All: return Sdc::Options::FVAR_LINEAR_ALL;
    }
    throw std::invalid_argument("unknown FVarLinearInterpolation");
}

}  // namespace

namespace {

// OpenSubdiv's refiner of `mesh` with its UVs as face-varying channel 0, refined uniformly to
// `maxLevel` (full topology in the last level, which the limit needs; not refined for -1).
std::unique_ptr<Far::TopologyRefiner> createFVarRefiner(const io::ObjMesh& mesh, OsdScheme scheme,
                                                        BoundaryInterpolation boundary, CreaseMethod creaseMethod,
                                                        FVarLinearInterpolation fvar, int maxLevel,
                                                        bool leftHanded = false) {
    if (!mesh.hasUVs()) throw std::invalid_argument("osdFaceVarying: the mesh has no UVs");
    Sdc::Options sdcOptions;
    sdcOptions.SetVtxBoundaryInterpolation(sdcBoundary(boundary));
    sdcOptions.SetCreasingMethod(sdcCreasing(creaseMethod));
    sdcOptions.SetFVarLinearInterpolation(sdcFVar(fvar));

    using Descriptor = Far::TopologyDescriptor;
    Descriptor desc = osdDescriptorOf(mesh);
    Descriptor::FVarChannel channel;
    channel.numValues = mesh.numUVs();
    channel.valueIndices = mesh.faceUVs.data();
    desc.numFVarChannels = 1;
    desc.fvarChannels = &channel;
    desc.isLeftHanded = leftHanded;

    std::unique_ptr<Far::TopologyRefiner> refiner = refinerOf(desc, scheme, sdcOptions);
    if (maxLevel < 0) return refiner;
    Far::TopologyRefiner::UniformOptions uniform(maxLevel);
    uniform.fullTopologyInLastLevel = true;
    refiner->RefineUniform(uniform);
    return refiner;
}

// Level L's faces: their vertices and their values of channel 0, corner by corner.
void faceCornersOf(const Far::TopologyLevel& level, std::vector<int>& offsets, std::vector<int>& verts,
                   std::vector<int>& values) {
    offsets.assign(1, 0);
    verts.clear();
    values.clear();
    for (int f = 0; f < level.GetNumFaces(); ++f) {
        Far::ConstIndexArray fv = level.GetFaceVertices(f);
        Far::ConstIndexArray fu = level.GetFaceFVarValues(f, 0);
        for (int k = 0; k < fv.size(); ++k) {
            verts.push_back(fv[k]);
            values.push_back(fu[k]);
        }
        offsets.push_back(int(verts.size()));
    }
}

}  // namespace

OsdFaceVarying osdFaceVarying(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                              CreaseMethod creaseMethod, FVarLinearInterpolation fvar, int maxLevel) {
    const std::unique_ptr<Far::TopologyRefiner> refiner =
        createFVarRefiner(mesh, scheme, boundary, creaseMethod, fvar, maxLevel);
    OsdFaceVarying out;
    std::vector<Vertex> positions(mesh.numVertices());
    for (int v = 0; v < mesh.numVertices(); ++v)
        for (int c = 0; c < 3; ++c) positions[v].p[c] = mesh.positions[3 * size_t(v) + c];
    std::vector<UV> uvs(mesh.numUVs());
    for (int i = 0; i < mesh.numUVs(); ++i)
        for (int c = 0; c < 2; ++c) uvs[i].p[c] = mesh.uvs[2 * size_t(i) + c];
    Far::PrimvarRefiner primvar(*refiner);
    for (int L = 0; L <= maxLevel; ++L) {
        const Far::TopologyLevel& level = refiner->GetLevel(L);
        if (L > 0) {
            std::vector<Vertex> nextPositions(level.GetNumVertices());
            std::vector<UV> nextUVs(level.GetNumFVarValues(0));
            const Vertex* src = positions.data();
            Vertex* dst = nextPositions.data();
            primvar.Interpolate(L, src, dst);
            const UV* uvSrc = uvs.data();
            UV* uvDst = nextUVs.data();
            primvar.InterpolateFaceVarying(L, uvSrc, uvDst, 0);
            positions = std::move(nextPositions);
            uvs = std::move(nextUVs);
        }
        std::vector<float> xyz, st;
        for (const Vertex& v : positions) xyz.insert(xyz.end(), v.p, v.p + 3);
        for (const UV& u : uvs) st.insert(st.end(), u.p, u.p + 2);
        std::vector<int> offsets, verts, values;
        faceCornersOf(level, offsets, verts, values);
        out.positions.push_back(std::move(xyz));
        out.uvs.push_back(std::move(st));
        out.faceOffsets.push_back(std::move(offsets));
        out.faceVerts.push_back(std::move(verts));
        out.faceValues.push_back(std::move(values));
    }
    return out;
}

namespace {

// A primvar of OpenSubdiv's PrimvarRefiner in Real: double for the limit reference (its own
// rounding stays well below what the limit tests compare), float for what an engine running
// OpenSubdiv in float gets.
template <class Real>
struct VertexOf {
    Real p[3];
    void Clear(void* = nullptr) { p[0] = p[1] = p[2] = Real(0); }
    void AddWithWeight(const VertexOf& src, Real weight) {
        p[0] += weight * src.p[0];
        p[1] += weight * src.p[1];
        p[2] += weight * src.p[2];
    }
};

template <class Real>
OsdLimit limitIn(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary, CreaseMethod creaseMethod,
                 int level, bool smoothTriangles, bool leftHanded) {
    using Vertex = VertexOf<Real>;
    if (level < 0) throw std::invalid_argument("osdLimit: negative level");
    std::unique_ptr<Far::TopologyRefiner> refiner =
        createRefiner(mesh, scheme, boundary, creaseMethod, smoothTriangles, leftHanded);
    Far::TopologyRefiner::UniformOptions uniform(level);
    uniform.fullTopologyInLastLevel = true;  // Limit needs the last level's incidences
    refiner->RefineUniform(uniform);

    std::vector<Vertex> current(mesh.numVertices());
    for (int v = 0; v < mesh.numVertices(); ++v)
        for (int c = 0; c < 3; ++c) current[v].p[c] = Real(mesh.positions[3 * size_t(v) + c]);
    Far::PrimvarRefinerReal<Real> primvar(*refiner);
    for (int L = 1; L <= level; ++L) {
        std::vector<Vertex> next(refiner->GetLevel(L).GetNumVertices());
        const Vertex* src = current.data();
        Vertex* dst = next.data();
        primvar.Interpolate(L, src, dst);
        current = std::move(next);
    }
    const size_t n = current.size();
    std::vector<Vertex> position(n), du(n), dv(n);
    const Vertex* src = current.data();
    Vertex *dstPosition = position.data(), *dstDu = du.data(), *dstDv = dv.data();
    primvar.Limit(src, dstPosition, dstDu, dstDv);

    OsdLimit out;
    const Far::TopologyLevel& last = refiner->GetLevel(level);
    for (size_t v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c) {
            out.refined.push_back(float(current[v].p[c]));
            out.position.push_back(position[v].p[c]);
            out.du.push_back(du[v].p[c]);
            out.dv.push_back(dv[v].p[c]);
        }
    for (int v = 0; v < last.GetNumVertices(); ++v) {
        out.vertexRule.push_back(int(last.GetVertexRule(v)));
        out.vertexNonManifold.push_back(last.IsVertexNonManifold(v) ? 1 : 0);
    }
    return out;
}

}  // namespace

OsdVarying osdVarying(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                      CreaseMethod creaseMethod, int level, bool smoothTriangles) {
    using Vertex = VertexOf<double>;
    std::unique_ptr<Far::TopologyRefiner> refiner = createRefiner(mesh, scheme, boundary, creaseMethod, smoothTriangles, false);
    refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(level));
    std::vector<Vertex> vertex(mesh.numVertices());
    for (int v = 0; v < mesh.numVertices(); ++v)
        for (int c = 0; c < 3; ++c) vertex[v].p[c] = mesh.positions[3 * size_t(v) + c];
    std::vector<Vertex> varying = vertex;
    Far::PrimvarRefinerReal<double> primvar(*refiner);
    for (int L = 1; L <= level; ++L) {
        const int n = refiner->GetLevel(L).GetNumVertices();
        std::vector<Vertex> nextVertex(n), nextVarying(n);
        const Vertex* src = vertex.data();
        Vertex* dst = nextVertex.data();
        primvar.Interpolate(L, src, dst);
        const Vertex* varyingSrc = varying.data();
        Vertex* varyingDst = nextVarying.data();
        primvar.InterpolateVarying(L, varyingSrc, varyingDst);
        vertex = std::move(nextVertex);
        varying = std::move(nextVarying);
    }
    OsdVarying out;
    for (size_t v = 0; v < vertex.size(); ++v)
        for (int c = 0; c < 3; ++c) {
            out.refined.push_back(float(vertex[v].p[c]));
            out.varying.push_back(varying[v].p[c]);
        }
    return out;
}

OsdLimit osdLimit(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                  CreaseMethod creaseMethod, int level, bool smoothTriangles, bool leftHanded) {
    return limitIn<double>(mesh, scheme, boundary, creaseMethod, level, smoothTriangles, leftHanded);
}

OsdLimit osdLimitInFloat(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                         CreaseMethod creaseMethod, int level, bool smoothTriangles, bool leftHanded) {
    return limitIn<float>(mesh, scheme, boundary, creaseMethod, level, smoothTriangles, leftHanded);
}

namespace {

// The channel of `mesh` renumbered in OpenSubdiv's order of level 0's vertex values: vertex by
// vertex, each vertex's values in the order of its faces (a value at two vertices becomes two).
io::ObjMesh inVertexValueOrder(const io::ObjMesh& mesh, const Far::TopologyLevel& level0) {
    io::ObjMesh out = mesh;
    out.uvs.clear();
    std::vector<int> faceStart{0};
    for (int size : mesh.faceSizes) faceStart.push_back(faceStart.back() + size);
    for (int v = 0; v < level0.GetNumVertices(); ++v) {
        const Far::ConstIndexArray faces = level0.GetVertexFaces(v);
        const Far::ConstLocalIndexArray corners = level0.GetVertexFaceLocalIndices(v);
        std::vector<std::pair<int, int>> renamed;  // (the channel's value, its vertex value)
        for (int i = 0; i < faces.size(); ++i) {
            const int corner = faceStart[std::size_t(faces[i])] + corners[i], value = mesh.faceUVs[std::size_t(corner)];
            auto found = std::find_if(renamed.begin(), renamed.end(), [&](const auto& r) { return r.first == value; });
            if (found == renamed.end()) {
                renamed.emplace_back(value, int(out.uvs.size() / 2));
                out.uvs.insert(out.uvs.end(), {mesh.uvs[2 * std::size_t(value)], mesh.uvs[2 * std::size_t(value) + 1]});
                found = renamed.end() - 1;
            }
            out.faceUVs[std::size_t(corner)] = found->second;
        }
    }
    return out;
}

// Positions and UVs of `mesh` refined by `refiner` (refined to `level`) in double, and
// LimitFaceVarying of the last level.
OsdFaceVaryingLimit limitFaceVarying(const io::ObjMesh& mesh, const Far::TopologyRefiner& refiner, int level) {
    using Point = VertexOf<double>;
    using UVd = UVOf<double>;
    std::vector<Point> positions(mesh.numVertices());
    for (int v = 0; v < mesh.numVertices(); ++v)
        for (int c = 0; c < 3; ++c) positions[v].p[c] = mesh.positions[3 * size_t(v) + c];
    std::vector<UVd> uvs(mesh.numUVs());
    for (int i = 0; i < mesh.numUVs(); ++i)
        for (int c = 0; c < 2; ++c) uvs[i].p[c] = mesh.uvs[2 * size_t(i) + c];
    Far::PrimvarRefinerReal<double> primvar(refiner);
    for (int L = 1; L <= level; ++L) {
        const Far::TopologyLevel& refined = refiner.GetLevel(L);
        std::vector<Point> nextPositions(refined.GetNumVertices());
        std::vector<UVd> nextUVs(refined.GetNumFVarValues(0));
        const Point* src = positions.data();
        Point* dst = nextPositions.data();
        primvar.Interpolate(L, src, dst);
        const UVd* uvSrc = uvs.data();
        UVd* uvDst = nextUVs.data();
        primvar.InterpolateFaceVarying(L, uvSrc, uvDst, 0);
        positions = std::move(nextPositions);
        uvs = std::move(nextUVs);
    }
    std::vector<UVd> limit(uvs.size());
    const UVd* uvSrc = uvs.data();
    UVd* limitDst = limit.data();
    primvar.LimitFaceVarying(uvSrc, limitDst, 0);

    OsdFaceVaryingLimit out;
    for (const Point& p : positions)
        for (int c = 0; c < 3; ++c) out.positions.push_back(float(p.p[c]));
    for (std::size_t i = 0; i < uvs.size(); ++i)
        for (int c = 0; c < 2; ++c) {
            out.uvs.push_back(uvs[i].p[c]);
            out.limit.push_back(limit[i].p[c]);
        }
    faceCornersOf(refiner.GetLevel(level), out.faceOffsets, out.faceVerts, out.faceValues);
    return out;
}

}  // namespace

OsdFaceVaryingLimit osdFaceVaryingLimit(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                                        CreaseMethod creaseMethod, FVarLinearInterpolation fvar, int level) {
    if (level < 0) throw std::invalid_argument("osdFaceVaryingLimit: negative level");
    std::unique_ptr<Far::TopologyRefiner> refiner = createFVarRefiner(mesh, scheme, boundary, creaseMethod, fvar, level);
    if (level == 0) {
        // Level 0's value tags are numbered per vertex value (its siblings, vertex by vertex), but
        // LimitFaceVarying looks them up by the channel's value index: read in that numbering, the
        // channel is what every refined level is (one value per vertex and sibling).
        const io::ObjMesh renumbered = inVertexValueOrder(mesh, refiner->GetLevel(0));
        refiner = createFVarRefiner(renumbered, scheme, boundary, creaseMethod, fvar, 0);
        return limitFaceVarying(renumbered, *refiner, 0);
    }
    return limitFaceVarying(mesh, *refiner, level);
}

namespace {

// Each point on its face's Bfr surface with both approximation levels at `approxLevel`:
// `face(factory, f, surface)` initializes face f's surface (false: none), `data` holds `width`
// doubles per point the surfaces read.
template <class InitFace>
OsdSurfacePoints bfrPoints(const Far::TopologyRefiner& refiner, int approxLevel, const InitFace& face,
                           const std::vector<double>& data, int width, const std::vector<int>& faces,
                           const std::vector<double>& uv) {
    Bfr::RefinerSurfaceFactory<>::Options options;
    options.SetApproxLevelSmooth(approxLevel);
    options.SetApproxLevelSharp(approxLevel);
    const Bfr::RefinerSurfaceFactory<> factory(refiner, options);
    const Bfr::Surface<double>::PointDescriptor layout(width);
    OsdSurfacePoints out;
    out.position.assign(std::size_t(width) * faces.size(), 0.0);
    out.du = out.dv = out.position;
    out.evaluated.assign(faces.size(), 0);
    Bfr::Surface<double> surface;
    std::vector<double> patchPoints;
    int prepared = -1;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        if (faces[i] != prepared) {
            prepared = -1;
            if (!face(factory, faces[i], surface)) continue;
            patchPoints.resize(std::size_t(surface.GetNumPatchPoints()) * std::size_t(width));
            surface.PreparePatchPoints(data.data(), layout, patchPoints.data(), layout);
            prepared = faces[i];
        }
        const std::size_t at = std::size_t(width) * i;
        surface.Evaluate(&uv[2 * i], patchPoints.data(), layout, &out.position[at], &out.du[at], &out.dv[at]);
        out.evaluated[i] = 1;
    }
    return out;
}

}  // namespace

OsdSurfacePoints osdSurfacePoints(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                                  CreaseMethod creaseMethod, int approxLevel, const std::vector<int>& faces,
                                  const std::vector<double>& uv, bool leftHanded) {
    std::unique_ptr<Far::TopologyRefiner> refiner = createRefiner(mesh, scheme, boundary, creaseMethod, false, leftHanded);
    auto vertexSurface = [](const Bfr::RefinerSurfaceFactory<>& factory, int f, Bfr::Surface<double>& surface) {
        return factory.InitVertexSurface(f, &surface);
    };
    return bfrPoints(*refiner, approxLevel, vertexSurface, std::vector<double>(mesh.positions.begin(), mesh.positions.end()),
                     3, faces, uv);
}

OsdSurfacePoints osdSurfaceUVs(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                               CreaseMethod creaseMethod, FVarLinearInterpolation fvar, int approxLevel,
                               const std::vector<int>& faces, const std::vector<double>& uv, bool leftHanded) {
    std::unique_ptr<Far::TopologyRefiner> refiner =
        createFVarRefiner(mesh, scheme, boundary, creaseMethod, fvar, -1, leftHanded);
    auto uvSurface = [](const Bfr::RefinerSurfaceFactory<>& factory, int f, Bfr::Surface<double>& surface) {
        return factory.InitFaceVaryingSurface(f, &surface, 0);
    };
    return bfrPoints(*refiner, approxLevel, uvSurface, std::vector<double>(mesh.uvs.begin(), mesh.uvs.end()), 2, faces,
                     uv);
}

}  // namespace quadtri::test
