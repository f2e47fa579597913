// The faces of one refinement level, read only: what a renderer or an exporter needs (its index
// buffer). Every level has them, including a last level that Refiner::refineUniform built with
// its faces only (TopologyDetail::FacesOnly), whose edges and incidences do not exist.
#pragma once

#include <cstddef>
#include <cstdint>

#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {

class LevelFaces {
public:
    // A view of `topology`'s faces; valid as long as it is.
    explicit LevelFaces(const Topology& topology) : t_(&topology) {}

    int numVertices() const { return t_->numVertices; }
    int numFaces() const { return t_->numFaces(); }
    int faceSize(int f) const { return t_->faceSize(f); }
    // Face f's corners, counter-clockwise seen from outside (the Refiner stores clockwise input,
    // Options::leftHanded, reversed).
    IndexSpan verticesOfFace(int f) const {
        const int* all = t_->faceVerts.data();
        return {all + t_->faceOffsets[f], all + t_->faceOffsets[f + 1]};
    }
    // A hole is kept in the numbering (its children are holes too) but is not drawn.
    bool isHole(int f) const { return std::size_t(f) < t_->faceHole.size() && t_->faceHole[f] != 0; }
    int numHoles() const;

    // The flat arrays, e.g. to upload: face f's corners are vertices()[offsets()[f] ..
    // offsets()[f + 1]); holes() has one byte per face, non-zero for a hole.
    const int* offsets() const { return t_->faceOffsets.data(); }
    const int* vertices() const { return t_->faceVerts.data(); }
    const std::uint8_t* holes() const { return t_->faceHole.data(); }
    int numCorners() const { return int(t_->faceVerts.size()); }

private:
    const Topology* t_;
};

inline int LevelFaces::numHoles() const {
    int holes = 0;
    for (int f = 0; f < numFaces(); ++f) holes += isHole(f) ? 1 : 0;
    return holes;
}

}  // namespace v0
}  // namespace quadtri
