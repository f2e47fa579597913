// The two walks LevelPatchTable's builder needs (far/surface/level_patch_table.cpp): the level-L
// vertices of a level-K face with their grid cells, and limit stencils of chosen level-L
// vertices over level K's vertices.
#pragma once

#include <vector>

#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/refiner.h>

namespace quadtri {
inline namespace v0 {

struct LevelPatchTable;

namespace internal {

// The corners of every level-L descendant of a level-K face, as (vertex, i, j): (i, j) / 2^(L-K)
// is the corner's (s, t) in the level-K face (corner 0 at (0, 0), corner 1 at (1, 0); a quad's
// corner 3 at (0, 1), a triangle's corner 2 at (0, 1)). A child's corners are its parent's
// corner, edge midpoints and centre, as refinement numbers children (refine_topology.cpp). A
// face that is neither a quad nor a triangle split in four reports its vertices with i = j = -1.
class DescendantCorners {
public:
    DescendantCorners(const Refiner& refiner, int K, int L);
    template <class Visit>
    void forEach(int face, const Visit& visit) const;

private:
    struct Corner {
        int x, y;
    };
    template <class Visit>
    void walk(int level, int face, const Corner* corners, int n, const Visit& visit) const;

    const Refiner& refiner_;
    int K_, L_;
    bool splitsTrianglesInFour_;
    std::vector<std::vector<int>> firstChild_;  // per level K .. L-1, per face
};

// Limit stencils of level L's `vertices` over level K's vertices: Refiner::limitStencils(L)'s
// rows composed with the per-level tables L .. K+1, in double, rounded once.
LimitStencilTable composeLimitRowsDown(const Refiner& refiner, int L, int K, const std::vector<int>& vertices);

LevelPatchTable buildLevelPatchTable(const Refiner& refiner, int L, int K);

template <class Visit>
void DescendantCorners::forEach(int face, const Visit& visit) const {
    const int n = 1 << (L_ - K_);
    const LevelFaces faces = refiner_.faces(K_);
    const int size = faces.faceSize(face);
    const bool patchShaped = size == 4 || (size == 3 && splitsTrianglesInFour_);
    if (!patchShaped) {  // its descendants, without cells
        std::vector<int> stack{face}, levels{K_};
        while (!stack.empty()) {
            const int f = stack.back(), l = levels.back();
            stack.pop_back();
            levels.pop_back();
            if (l == L_) {
                for (int v : refiner_.faces(L_).verticesOfFace(f)) visit(v, -1, -1);
                continue;
            }
            const int s = refiner_.faces(l).faceSize(f);
            const int children = (s == 4 || (s == 3 && splitsTrianglesInFour_)) ? 4 : s;
            for (int c = 0; c < children; ++c) {
                stack.push_back(firstChild_[std::size_t(l - K_)][std::size_t(f)] + c);
                levels.push_back(l + 1);
            }
        }
        return;
    }
    const Corner quad[4] = {{0, 0}, {n, 0}, {n, n}, {0, n}}, triangle[3] = {{0, 0}, {n, 0}, {0, n}};
    walk(K_, face, size == 4 ? quad : triangle, size, visit);
}

template <class Visit>
void DescendantCorners::walk(int level, int face, const Corner* c, int n, const Visit& visit) const {
    if (level == L_) {
        const IndexSpan verts = refiner_.faces(L_).verticesOfFace(face);
        for (int i = 0; i < n; ++i) visit(verts[i], c[i].x, c[i].y);
        return;
    }
    auto mid = [](Corner a, Corner b) { return Corner{(a.x + b.x) / 2, (a.y + b.y) / 2}; };
    const int first = firstChild_[std::size_t(level - K_)][std::size_t(face)];
    if (n == 4) {
        const Corner centre = mid(c[0], c[2]);
        for (int i = 0; i < 4; ++i) {
            const Corner child[4] = {c[i], mid(c[i], c[(i + 1) % 4]), centre, mid(c[(i + 3) % 4], c[i])};
            walk(level + 1, first + i, child, 4, visit);
        }
        return;
    }
    for (int i = 0; i < 3; ++i) {
        const Corner child[3] = {c[i], mid(c[i], c[(i + 1) % 3]), mid(c[(i + 2) % 3], c[i])};
        walk(level + 1, first + i, child, 3, visit);
    }
    const Corner middle[3] = {mid(c[0], c[1]), mid(c[1], c[2]), mid(c[2], c[0])};
    walk(level + 1, first + 3, middle, 3, visit);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
