// Templates for the factorized stencils of regular control faces (far/tables/regular_patches.h).
//
// Everything here is combinatorial: a face's patch is walked from its own corner 0 and its
// children are visited in the order refine_topology.cpp makes them, so the k-th child visited
// under one regular face and under the reference torus's face is the same point of the same
// local picture. The masks of a scheme whose regular masks depend on face size and valence only
// (SchemeRules::regularMasksApply) give that point the same weights over the same patch corners.
#include "far/tables/regular_patches.h"

#include <quadtri/far/refiner.h>

#include <algorithm>
#include <exception>
#include <memory>

#include "far/topology/refine_topology.h"
#include "far/schemes/scheme.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// What a regular patch is made of, per kind: 0 quads (valence 4, 16 patch vertices), 1 triangles
// (valence 6, 12 patch vertices). A cell of either kind has 4 children; its children's points are
// its corners' vertex points, its edges' edge points, and a quad's face point.
constexpr int kFaceSize[2] = {4, 3}, kValence[2] = {4, 6}, kPatchSize[2] = {16, 12}, kPointsPerCell[2] = {9, 6};
constexpr int kMaxPatch = 16;

int kindOfSize(int n) { return n == 4 ? 0 : n == 3 ? 1 : -1; }

// Templates of level l: one per point of each cell of level l - 1.
int numPositions(int kind, int l) { return kPointsPerCell[kind] << (2 * (l - 1)); }

// Whether a control vertex may lie in a regular patch of `kind`: interior, manifold, smooth, of
// the kind's valence, every face around it of the kind's size and no hole, every edge plain.
bool regularVertex(const Topology& t, int v, int kind) {
    if (t.vertFlags[v] != 0 || t.vertSharpness[v] != 0.0f) return false;
    if (t.vertexFaceCount(v) != kValence[kind] || t.vertexEdgeCount(v) != kValence[kind]) return false;
    for (int f : t.facesOfVertex(v))
        if (t.faceSize(f) != kFaceSize[kind] || t.faceHole[f] != 0) return false;
    for (int e : t.edgesOfVertex(v))
        if (t.edgeSharpness[e] != 0.0f || t.edgeFlags[e] != 0 || t.edgeFaceCount(e) != 2) return false;
    return true;
}

// The face across the edge that leaves corner v of face a (the walk's step around v).
int faceAcross(const Topology& t, int a, int v) {
    const IndexSpan across = t.facesOfEdge(t.edgeOfCorner(a, t.cornerOfVertex(a, v)));
    return across[0] == a ? across[1] : across[0];
}

// The faces around each regular vertex of one kind in the walk's order: from one of them,
// faceAcross the kind's valence times, once per vertex. The patches of a vertex's faces then read
// its ring instead of walking it again, once per face around it (six times for a triangle
// vertex), each step a chain of dependent loads. Held while the regular faces are found (an int
// per vertex and valence).
class Rings {
public:
    Rings(const Topology& t, int kind) : t_(t), valence_(kValence[kind]), state_(std::size_t(t.numVertices), kUnknown) {}

    // Vertex v's faces from a face `valence` steps round to that face again, or null where they do
    // not close after the kind's valence, visiting each once.
    const int* of(int v) {
        std::uint8_t& state = state_[std::size_t(v)];
        if (state == kUnknown) state = walk(v) ? kClosed : kOpen;
        return state == kClosed ? ring_.data() + std::size_t(v) * valence_ : nullptr;
    }

private:
    static constexpr std::uint8_t kUnknown = 0, kClosed = 1, kOpen = 2;
    bool walk(int v) {
        if (ring_.empty()) ring_.resize(std::size_t(t_.numVertices) * valence_);
        int* ring = ring_.data() + std::size_t(v) * valence_;
        const int start = t_.facesOfVertex(v)[0];
        int a = start;
        for (int k = 0; k < valence_; ++k) {
            a = faceAcross(t_, a, v);
            if (std::find(ring, ring + k, a) != ring + k) return false;
            ring[k] = a;
        }
        return a == start;
    }
    const Topology& t_;
    int valence_;
    std::vector<std::uint8_t> state_;
    std::vector<int> ring_;  // per vertex, its valence's faces (filled for those asked)
};

// The patch of face f (of `kind`, with regular corners): its corners, then for each corner the
// vertices of the faces around it, walked from f across the edge leaving the corner, each vertex
// once (`added[v] == f` marks those taken). Its size, or 0 where the walk does not close after
// the kind's valence or the patch has not the kind's size (a small torus wraps onto itself).
// With `rings`, a corner's faces come from its ring (the same faces in the same order, from f's
// place in it), walked only where the ring is not there.
template <int Kind>
int walkPatchOf(const Topology& t, int f, int* patch, int* added, Rings* rings) {
    constexpr int n = kFaceSize[Kind], valence = kValence[Kind];
    int size = 0;
    auto add = [&](int v) {
        if (added[v] == f) return true;
        if (size == kPatchSize[Kind]) return false;
        added[v] = f;
        patch[size++] = v;
        return true;
    };
    // Face a's vertices after v in its corner order (a corner wraps without a division).
    auto addFan = [&](int a, int v) {
        const int* verts = t.verticesOfFace(a).begin();
        const int c = t.cornerOfVertex(a, v);
        for (int j = 1, k = c + 1; j < n; ++j, ++k)
            if (!add(verts[k < n ? k : k - n])) return false;
        return true;
    };
    const int* corners = t.verticesOfFace(f).begin();
    for (int i = 0; i < n; ++i)
        if (!add(corners[i])) return 0;
    for (int i = 0; i < n; ++i) {
        const int v = corners[i];
        const int* ring = rings ? rings->of(v) : nullptr;
        const int* self = ring ? std::find(ring, ring + valence, f) : nullptr;
        if (self && self != ring + valence) {
            // The walk from f takes the ring's faces after f, round to f itself.
            for (int k = 1, at = int(self - ring); k <= valence; ++k)
                if (!addFan(ring[(at + k) % valence], v)) return 0;
            continue;
        }
        int a = f;
        for (int step = 0; step < valence; ++step) {
            a = faceAcross(t, a, v);
            if (!addFan(a, v)) return 0;
        }
        if (a != f) return 0;
    }
    return size == kPatchSize[Kind] ? size : 0;
}

int walkPatch(const Topology& t, int f, int kind, int* patch, int* added, Rings* rings = nullptr) {
    return kind == 0 ? walkPatchOf<0>(t, f, patch, added, rings) : walkPatchOf<1>(t, f, patch, added, rings);
}

// One level down the children of some control faces: `cells` holds each face's cells (its
// descendants at `level`, 4^level per face, in the order refine_topology.cpp makes them); every
// point of every cell is handed to visit(face's slot, position, child vertex), and with
// `keepCells` the cells become the next level's.
template <class Visit>
void descendCells(const Refiner& refiner, int level, std::vector<int>& cells, const std::vector<std::uint8_t>& kinds,
                  bool keepCells, Visit visit) {
    const Topology& t = refiner.level(level);
    const ChildNumbering num = numberChildren(t, rulesOf(refiner.options().scheme).triangleSplit());
    std::vector<int> firstChild;
    if (keepCells) {
        firstChild.resize(std::size_t(t.numFaces()));
        for (int f = 0, next = 0; f < t.numFaces(); ++f) {
            firstChild[std::size_t(f)] = next;
            next += num.splitsInFour(t.faceSize(f)) ? 4 : t.faceSize(f);
        }
    }
    const std::size_t perFace = std::size_t(1) << (2 * level);
    std::vector<int> next(keepCells ? 4 * cells.size() : 0);
    for (std::size_t r = 0; r < kinds.size(); ++r) {
        const int kind = kinds[r], per = kPointsPerCell[kind];
        for (std::size_t c = 0; c < perFace; ++c) {
            const int f = cells[r * perFace + c];
            const IndexSpan corners = t.verticesOfFace(f), sides = t.edgesOfFace(f);
            int p = int(c) * per;
            for (int v : corners) visit(r, p++, num.vertexPoint(v));
            for (int e : sides) visit(r, p++, num.edgePoint(e));
            if (kind == 0) visit(r, p, num.facePoint[std::size_t(f)]);
            if (keepCells)
                for (int i = 0; i < 4; ++i) next[(r * perFace + c) * 4 + std::size_t(i)] = firstChild[std::size_t(f)] + i;
        }
    }
    cells.swap(next);
}

// A torus of 6 x 6 vertices, every vertex regular: quads, or each quad split along one diagonal.
struct ReferenceTorus {
    static constexpr int kN = 6;
    std::vector<int> sizes, verts;

    explicit ReferenceTorus(int kind) {
        auto at = [](int i, int j) { return (i % kN) * kN + j % kN; };
        for (int i = 0; i < kN; ++i)
            for (int j = 0; j < kN; ++j) {
                const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
                if (kind == 0) {
                    sizes.push_back(4);
                    verts.insert(verts.end(), {a, b, c, d});
                } else {
                    sizes.insert(sizes.end(), {3, 3});
                    verts.insert(verts.end(), {a, b, c, a, c, d});
                }
            }
    }
    TopologyDescriptor descriptor() const {
        TopologyDescriptor d;
        d.numVertices = kN * kN;
        d.numFaces = int(sizes.size());
        d.numVertsPerFace = sizes.data();
        d.faceVertIndices = verts.data();
        return d;
    }
};

}  // namespace

RegularPatches::RegularPatches(const Refiner& refiner, int maxLevel) : refiner_(refiner), maxLevel_(maxLevel) {
    const SchemeRules& rules = rulesOf(refiner.options().scheme);
    // A kind's templates are worth their reference torus (36 quads, 72 triangles) only on meshes
    // with at least twice as many faces of the kind.
    int count[2] = {0, 0};
    const Topology& t = refiner.level(0);
    for (int f = 0; f < t.numFaces(); ++f)
        if (kindOfSize(t.faceSize(f)) >= 0) ++count[kindOfSize(t.faceSize(f))];
    const bool kinds[2] = {rules.regularMasksApply() && rules.acceptsNonTriangles() && count[0] >= 72,
                           rules.regularMasksApply() && rules.triangleSplit() == TriangleSplit::FourTriangles && count[1] >= 144};
    for (int kind = 0; kind < 2; ++kind)
        if (kinds[kind]) buildTemplates(kind);
    findRegularFaces();
}

void RegularPatches::buildTemplates(int kind) {
    const ReferenceTorus torus(kind);
    std::unique_ptr<Refiner> made;
    try {
        made = std::make_unique<Refiner>(torus.descriptor(), refiner_.options());
        made->refineUniform(maxLevel_);
    } catch (const std::exception&) {
        return;  // options the torus cannot take (a budget too small for it): everything is composed
    }
    const Refiner& reference = *made;
    const Topology& t0 = reference.level(0);
    int patch[kMaxPatch];
    std::vector<int> added(std::size_t(t0.numVertices), -1);
    if (walkPatch(t0, 0, kind, patch, added.data()) == 0) return;
    std::vector<int> corner(std::size_t(t0.numVertices), -1);
    for (int k = 0; k < kPatchSize[kind]; ++k) corner[std::size_t(patch[k])] = k;

    Templates& out = templates_[kind];
    std::vector<int> cells{0};
    const std::vector<std::uint8_t> kinds{std::uint8_t(kind)};
    StencilTableD composed;
    for (int l = 1; l <= maxLevel_; ++l) {
        composed = l == 1 ? toDoubleTable(reference.levelStencils(1)) : composeStencils(reference.levelStencils(l), composed);
        std::vector<int> vertexAt(std::size_t(numPositions(kind, l)));
        descendCells(reference, l - 1, cells, kinds, l < maxLevel_, [&](std::size_t, int p, int v) { vertexAt[std::size_t(p)] = v; });
        std::vector<int> offsets{0};
        std::vector<std::uint8_t> corners;
        std::vector<double> weights;
        for (int v : vertexAt) {
            for (int e = composed.offsets[std::size_t(v)], end = e + composed.sizes[std::size_t(v)]; e < end; ++e) {
                const int k = corner[std::size_t(composed.indices[std::size_t(e)])];
                if (k < 0) return;  // reaches past the patch: the masks are not local after all
                corners.push_back(std::uint8_t(k));
                weights.push_back(composed.weights[std::size_t(e)]);
            }
            offsets.push_back(int(corners.size()));
        }
        out.offsets.push_back(std::move(offsets));
        out.corners.push_back(std::move(corners));
        out.weights.push_back(std::move(weights));
    }
}

void RegularPatches::findRegularFaces() {
    const Topology& t = refiner_.level(0);
    patchStart_.assign(std::size_t(t.numFaces()), -1);
    faceKind_.assign(std::size_t(t.numFaces()), 0);
    std::vector<std::uint8_t> regular[2];  // per vertex: 0 unknown, 1 regular, 2 not
    std::vector<int> added(std::size_t(t.numVertices), -1);  // walkPatch's marks
    Rings rings[2] = {Rings(t, 0), Rings(t, 1)};
    auto isRegular = [&](int v, int kind) {
        std::uint8_t& r = regular[kind][std::size_t(v)];
        if (r == 0) r = regularVertex(t, v, kind) ? 1 : 2;
        return r == 1;
    };
    for (int f = 0; f < t.numFaces(); ++f) {
        const int kind = kindOfSize(t.faceSize(f));
        if (kind < 0 || int(templates_[kind].offsets.size()) != maxLevel_) continue;
        if (regular[kind].empty()) regular[kind].assign(std::size_t(t.numVertices), 0);
        const IndexSpan corners = t.verticesOfFace(f);
        if (!std::all_of(corners.begin(), corners.end(), [&](int v) { return isRegular(v, kind); })) continue;
        int patch[kMaxPatch];
        const int size = walkPatch(t, f, kind, patch, added.data(), &rings[kind]);
        if (size == 0 || !std::all_of(patch, patch + size, [&](int v) { return isRegular(v, kind); })) continue;
        patchStart_[std::size_t(f)] = int(patchVerts_.size());
        patchVerts_.insert(patchVerts_.end(), patch, patch + size);
        faceKind_[std::size_t(f)] = std::uint8_t(kind);
        regular_.push_back(f);
        kinds_.push_back(std::uint8_t(kind));
    }
    cells_ = regular_;  // level 0's cells: the faces themselves
}

const KnownStencils& RegularPatches::descend() {
    const int l = ++level_;
    std::vector<int>& face = face_[l % 2];
    std::vector<int>& position = position_[l % 2];
    KnownStencils& known = known_[l % 2];
    face.assign(std::size_t(refiner_.faces(l).numVertices()), -1);
    position.resize(face.size());
    descendCells(refiner_, l - 1, cells_, kinds_, l < maxLevel_, [&](std::size_t r, int p, int v) {
        face[std::size_t(v)] = regular_[r];
        position[std::size_t(v)] = p;
    });
    known.patchStart = patchStart_.data();
    known.patchVerts = patchVerts_.data();
    known.faceKind = faceKind_.data();
    known.face = face.data();
    known.position = position.data();
    for (int kind = 0; kind < 2; ++kind) {
        const Templates& t = templates_[kind];
        if (int(t.offsets.size()) != maxLevel_) continue;  // none, or given up part of the way
        known.offsets[kind] = t.offsets[std::size_t(l) - 1].data();
        known.corners[kind] = t.corners[std::size_t(l) - 1].data();
        known.weights[kind] = t.weights[std::size_t(l) - 1].data();
        known.numTemplates[kind] = numPositions(kind, l);
    }
    return known;
}

std::size_t RegularPatches::bytes() const {
    std::size_t b = (patchStart_.capacity() + patchVerts_.capacity() + cells_.capacity() + regular_.capacity() +
                     face_[0].capacity() + face_[1].capacity() + position_[0].capacity() + position_[1].capacity()) *
                        sizeof(int) +
                    faceKind_.capacity() + kinds_.capacity();
    for (const Templates& t : templates_)
        for (std::size_t l = 0; l < t.offsets.size(); ++l)
            b += t.offsets[l].capacity() * sizeof(int) + t.corners[l].capacity() + t.weights[l].capacity() * sizeof(double);
    return b;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
