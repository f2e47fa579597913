// Factorized stencils of the children of regular control faces, without composing them
// (docs/factorized_templates.md). Around a control face whose corners' rings are regular (every
// vertex within them interior, smooth, of valence 4 with quads around it, or of valence 6 with
// triangles), each child of the face at every level has a factorized stencil over the face's
// patch (its corners' rings: 16 control vertices around a quad, 12 around a triangle) whose
// weights are the same for every such face. The weights are taken once per refinement from a
// small regular torus refined with the same options and composed as usual; every other stencil
// is still composed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace quadtri {
inline namespace v0 {

class Refiner;

namespace internal {

// Stencils of one level known without composing: stencil i, where face[i] >= 0, is template
// position[i] of that face's kind, its corners naming the face's patch vertices.
struct KnownStencils {
    const int* face = nullptr;      // per stencil: the regular control face it lies in, -1 if none
    const int* position = nullptr;  // per stencil: its template among that kind's
    const int* patchStart = nullptr;  // per control face: where its patch starts in patchVerts
    const int* patchVerts = nullptr;
    const std::uint8_t* faceKind = nullptr;  // per control face: which templates (0 quads, 1 triangles)
    // Per kind: template p's entries [offsets[p], offsets[p + 1]), each a patch corner and a weight.
    const int* offsets[2] = {nullptr, nullptr};
    const std::uint8_t* corners[2] = {nullptr, nullptr};
    const double* weights[2] = {nullptr, nullptr};
    int numTemplates[2] = {0, 0};

    bool has(int i) const { return face[i] >= 0; }
    int kind(int i) const { return faceKind[face[i]]; }
    int size(int i) const {
        const int k = faceKind[face[i]], p = position[i];
        return offsets[k][p + 1] - offsets[k][p];
    }

    // Stencil i as its template gives it: entry e reads patch[corners[e]] with weights[e].
    struct Entries {
        const int* patch;
        const std::uint8_t* corners;
        const double* weights;
        int size;
    };
    Entries entries(int i) const {
        const int f = face[i], k = faceKind[f], p = position[i], begin = offsets[k][p];
        return {patchVerts + patchStart[f], corners[k] + begin, weights[k] + begin, offsets[k][p + 1] - begin};
    }

    // Writes stencil i's entries, in its template's order: its indices, and its weights where
    // `out` is not null.
    template <class Weight>
    void write(int i, int* indices, Weight* out) const {
        const Entries t = entries(i);
        for (int e = 0; e < t.size; ++e) *indices++ = t.patch[t.corners[e]];
        if (out)
            for (int e = 0; e < t.size; ++e) *out++ = Weight(t.weights[e]);
    }
};

class RegularPatches {
public:
    // The regular faces of `refiner`'s level 0 and their templates for levels 1..maxLevel
    // (<= refiner.maxLevel()). None where the scheme's masks are not local (SchemeRules::
    // regularMasksApply()).
    RegularPatches(const Refiner& refiner, int maxLevel);

    // Moves to the next level (level 1 on the first call, up to maxLevel) and returns which of
    // its stencils are known; valid until the call after next, so that the level above can be
    // composed over it.
    const KnownStencils& descend();

    int numRegularFaces() const { return int(regular_.size()); }
    // Bytes held now: the patches, templates and the current level's arrays.
    std::size_t bytes() const;

private:
    struct Templates {
        std::vector<std::vector<int>> offsets;  // per level 1..maxLevel (index l - 1)
        std::vector<std::vector<std::uint8_t>> corners;
        std::vector<std::vector<double>> weights;
    };

    void findRegularFaces();
    void buildTemplates(int kind);

    const Refiner& refiner_;
    int maxLevel_, level_ = 0;
    std::vector<int> patchStart_, patchVerts_;
    std::vector<std::uint8_t> faceKind_;
    std::vector<int> regular_;  // the regular control faces
    std::vector<std::uint8_t> kinds_;  // and their kinds
    std::vector<int> cells_;  // per regular face, its 4^level cells (faces of the current level)
    // The last two levels' KnownStencils and their per-stencil arrays, by the level's parity.
    std::vector<int> face_[2], position_[2];
    Templates templates_[2];
    KnownStencils known_[2];
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
