#include "far/topology/face_loops.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

FaceLoops FaceLoopSplitter::split(const int* verts, int n, std::vector<int>& faceVerts, std::vector<int>& faceSizes,
                                  std::vector<int>* corners) {
    FaceLoops result;
    // Most faces are small and repeat no vertex: one loop, the face as given.
    bool simple = n >= 3 && n <= 8;
    for (int i = 1; simple && i < n; ++i)
        for (int j = 0; j < i; ++j) simple = simple && verts[i] != verts[j];
    if (simple) {
        faceVerts.insert(faceVerts.end(), verts, verts + n);
        if (corners)
            for (int i = 0; i < n; ++i) corners->push_back(i);
        faceSizes.push_back(n);
        result.loops = 1;
        return result;
    }
    auto emit = [&](std::size_t from) {  // walk_[from ..) is a closed loop
        const int size = int(walk_.size() - from);
        if (size < 3) {
            ++result.leftOut;
            return;
        }
        faceVerts.insert(faceVerts.end(), walk_.begin() + long(from), walk_.end());
        if (corners) corners->insert(corners->end(), walkCorner_.begin() + long(from), walkCorner_.end());
        faceSizes.push_back(size);
        ++result.loops;
    };
    walk_.clear();
    walkCorner_.clear();
    for (int i = 0; i < n; ++i) {
        const int v = verts[i];
        if (v == verts[i == 0 ? n - 1 : i - 1]) continue;  // collapsed edge: the first of its corners stays
        const int seen = position_[std::size_t(v)];
        if (seen < 0) {
            position_[std::size_t(v)] = int(walk_.size());
            walk_.push_back(v);
            walkCorner_.push_back(i);
            continue;
        }
        // Back at v: walk_[seen ..) went around a loop from v to v. Keep v on the walk, now
        // standing for this corner, where the walk leaves v again.
        if (result.repeated < 0) result.repeated = v;
        for (std::size_t k = std::size_t(seen) + 1; k < walk_.size(); ++k) position_[std::size_t(walk_[k])] = -1;
        emit(std::size_t(seen));
        walk_.resize(std::size_t(seen) + 1);
        walkCorner_.resize(std::size_t(seen) + 1);
        walkCorner_.back() = i;
    }
    // What is left closes back to the first corner.
    for (int v : walk_) position_[std::size_t(v)] = -1;
    if (!walk_.empty()) emit(0);
    if (result.loops + result.leftOut == 0) result.leftOut = 1;  // every corner the same vertex
    const bool onlyCollapsed = result.repeated < 0 && result.loops == 1 && faceSizes.back() < n;
    if (collapsed_ == CollapsedEdges::Keep && onlyCollapsed) {  // the one loop becomes the face as given
        faceVerts.resize(faceVerts.size() - std::size_t(faceSizes.back()));
        faceVerts.insert(faceVerts.end(), verts, verts + n);
        if (corners) {
            corners->resize(corners->size() - std::size_t(faceSizes.back()));
            for (int i = 0; i < n; ++i) corners->push_back(i);
        }
        faceSizes.back() = n;
    }
    return result;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
