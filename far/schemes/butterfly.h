// Catmull-Clark on quads, Butterfly on triangles (Boumzaid, Lanquetin, Neveu and Destelle 2011;
// derivation and choices in docs/catmark_butterfly/README.md). The quad side is Catmull-Clark and
// comes from the Stam-Loop masks (the base class), which equal it wherever no triangle is
// involved; this class builds every mask that touches a triangle:
//   - vertices with triangles only never move (interpolation), whatever their rule;
//   - edges between two triangles: Butterfly (½, ½, ⅛, ⅛, −1/16 × 4), Zorin's modified rule at
//     interior extraordinary endpoints, the seam rules of eqs. 11/12 (seam → column 1) and the
//     half Butterfly (column 1 → column 2) where the plain rule would read the seam;
//   - seam edges (a triangle and a quad): eq. 14 (missing wings reflected); smooth seam vertices
//     of the regular seam (2 quads, 3 triangles): eq. 13. Irregular smooth seam vertices keep
//     Stam-Loop's mixed vertex rule (stam_loop.cpp), the one of the choices measured in the docs whose
//     normal jumps shrink fastest;
//   - sharp edges and creases whose faces are triangles, and crease vertices on the seam: curve
//     rules reproducing cubics under the curve quasi-interpolant (4-point on the triangle side,
//     cubic B-spline on the quad side, solved in between; butterfly_curve.cpp). The surface
//     masks do not read across a crease: a wing there is reflected, as a missing one is.
#pragma once

#include <cstdint>
#include <vector>

#include "far/schemes/stam_loop.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

class CatmarkButterflyMasks : public StamLoopMasks {
public:
    CatmarkButterflyMasks(const Topology& topology, SparseAccumulator& accumulator);

    void smoothEdgePoint(int edge, double scale) override;
    void sharpEdgePoint(int edge, double scale) override;
    void vertexPoint(int vertex, VertexRule rule, const float* edgeSharpness, double scale) override;

private:
    // Whether this class builds the child's mask; otherwise the base class's (Catmull-Clark, and
    // at irregular seam vertices Stam-Loop, and the shared sharp rules) applies.
    bool touchesEdge(int edge) const;        // smooth rule: a triangle on the edge
    bool touchesSharpEdge(int edge) const;   // sharp rule: triangles only on the edge
    bool touchesVertex(int vertex, VertexRule rule) const;

    // RegularSeam: a closed fan of two quads and three triangles with two seam edges, the seam of
    // split_plane and the only configuration eqs. 11-14 were derived for.
    enum class Kind : uint8_t { QuadOnly, Seam, RegularSeam, TriangleOnly };
    bool interpolated(int v) const { return kind_[v] == Kind::TriangleOnly; }
    Kind classify(int v) const;
    void seamVertex(int v, double scale);
    void seamEdge(int e, double scale);
    void butterflyEdge(int e, double scale);
    void butterfly(int a, int b, int f0, int f1, double scale);
    void halfButterfly(int a, int b, int f, double scale);
    void seamDiagonal(int s, int t, int towardsSeam, int away, double scale);
    void zorinEdge(int centre, int edge, double scale);
    void walkRing(int centre, int other, int face, std::vector<int>& ring) const;
    const std::vector<double>& zorinWeights(int valence);

    // Curve rules (butterfly_curve.cpp).
    void creaseVertex(int v, const float* edgeSharpness, double scale);
    int curveContinuation(int vertex, int previous) const;

    int thirdVertex(int triangle, int a, int b) const;
    // The edge of `face` joining its corners x and y, or -1: O(face size), where findEdge would
    // scan a vertex's edges (thousands at a pole).
    int edgeOfFace(int face, int x, int y) const;
    int otherFace(int edge, int face) const;
    // Vertex across edge (x, y) from `triangle`, or -1 when that face is missing or no triangle.
    int wing(int triangle, int x, int y) const;
    // Adds the wing across (x, y) from the triangle (x, y, z); a missing wing, and one across a
    // crease (by the crease's sharpness, up to 1), is replaced by the reflection x + y − z, which
    // keeps the mask affine invariant and exact on linear data.
    void addWing(int triangle, int x, int y, int z, double weight);
    // A Butterfly side (the triangle's opposite corner and its two wings) with no seam vertex.
    bool cleanSide(int triangle, int a, int b) const;
    double seamWeightOfSide(int triangle, int a, int b) const;

    std::vector<Kind> kind_;
    std::vector<uint8_t> sharpEdges_;  // per vertex: its sharp edges, counted up to 3
    // Zorin's rule: a centre's neighbours in fan order (a long ring kept for the next edge of
    // its centre) and the weights per valence, computed at its first use (their total size is at
    // most the level's edge ends: each valence seen is a vertex's edge count).
    static constexpr int kShortRing = 16;
    std::vector<int> shortRing_;
    int longRingCentre_ = -1;
    std::vector<int> longRing_;
    std::vector<std::vector<double>> weightsByValence_;
};

const SchemeRules& catmarkButterflyRules();

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
