// Limit stencils of a face-varying channel (docs/face_varying.md, "Limit UVs"): the value mesh's
// own limit masks, with the sharpness OpenSubdiv's LimitFaceVarying reads from the value tags.
#include <cstddef>

#include "far/fvar/fvar_channel.h"
#include "far/limit/limit_ring.h"
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// A value that matches its vertex keeps the value mesh's sharpness, which is the mesh's there, so
// it takes its vertex's mask. Every other value is a corner or a crease of the value mesh:
// semi-sharp and dependent values are corners until their tag relaxes (they are refined as
// blends, but their limit is taken as OpenSubdiv takes it, from the tag alone).
Topology FVarChannelRefinement::limitMesh(int L, const Options& options) const {
    const Level& level = levels_.at(std::size_t(L));
    Topology mesh = level.values;
    if (options.fvarLinearInterpolation == FVarLinearInterpolation::All) return mesh;  // sharp throughout already
    for (int p = 0; p < mesh.numVertices; ++p) {
        switch (level.kind[std::size_t(p)]) {
            case FVarKind::Match: break;
            case FVarKind::Corner:
            case FVarKind::SemiSharp:
            case FVarKind::Dependent: mesh.vertSharpness[std::size_t(p)] = kInfiniteSharpness; break;
            case FVarKind::Crease:
            case FVarKind::Released: mesh.vertSharpness[std::size_t(p)] = 0.0f; break;
        }
    }
    return mesh;
}

Topology FVarChannelRefinement::surfaceMesh() const {
    const Level& level = levels_[0];
    Topology mesh = level.values;
    for (int p = 0; p < mesh.numVertices; ++p)
        if (level.kind[std::size_t(p)] == FVarKind::Dependent) mesh.vertSharpness[std::size_t(p)] = kInfiniteSharpness;
    return mesh;
}

LimitStencilTableD FVarChannelRefinement::limitStencils(int L, const Topology& limitMesh, const Options& options) const {
    // Rings start where the value mesh's start, level by level, as the mesh's do (its faces are
    // the mesh's): a matched value's tangents are its vertex's.
    const TriangleSplit split = rulesOf(options.scheme).triangleSplit();
    RingStarts starts(levels_[0].values);
    for (int l = 1; l <= L; ++l) {
        const Topology& parent = levels_[std::size_t(l) - 1].values;
        starts.descend(parent, numberChildren(parent, split), levels_[std::size_t(l)].values.numVertices);
    }
    LimitStencilTableD table = buildLimitStencils(limitMesh, options, &starts);
    if (L > 0) return table;

    // Level 0: one stencil per value of the channel, over its values. A value several
    // value-vertices carry (a vertex whose faces alternate A B A B, or one index given at two
    // vertices) takes the last one's, as OpenSubdiv's last write; a value no corner names stays.
    std::vector<int> stencilOf(std::size_t(numControlValues_), -1);
    for (int p = 0; p < limitMesh.numVertices; ++p) stencilOf[std::size_t(controlValueOf_[std::size_t(p)])] = p;
    LimitStencilTableD out;
    out.numSourceVertices = numControlValues_;
    for (int value = 0; value < numControlValues_; ++value) {
        out.offsets.push_back(int(out.indices.size()));
        const int p = stencilOf[std::size_t(value)];
        if (p < 0) {
            out.sizes.push_back(1);
            out.indices.push_back(value);
            out.weights.insert(out.weights.end(), {1.0, 0.0, 0.0});
            continue;
        }
        const int first = table.offsets[std::size_t(p)], size = table.sizes[std::size_t(p)];
        out.sizes.push_back(size);
        for (int k = first; k < first + size; ++k)
            out.indices.push_back(controlValueOf_[std::size_t(table.indices[std::size_t(k)])]);
        out.weights.insert(out.weights.end(), table.weights.begin() + 3 * std::ptrdiff_t(first),
                           table.weights.begin() + 3 * std::ptrdiff_t(first + size));
    }
    return out;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
