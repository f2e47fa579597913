// Working space of the generic limit masks (docs/limit_eigen.md, "Build time"): the marks and
// lists that reading a vertex's neighbourhood and cutting its patch need, kept from one vertex to
// the next so that a vertex costs what it touches, not the level's size or an allocation per set.
// One per builder of a limit table: LimitMaskCache holds it (far/internal/limit_eigen.h).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace quadtri {
inline namespace v0 {

// Per index below some bound (a level's vertices or faces): whether it was marked since the last
// clear(), with an int beside the mark. clear() is a new stamp, not a pass over the array.
class StampedMarks {
public:
    // Forgets every mark and makes room for indices below n.
    void clear(int n) {
        if (marks_.size() < std::size_t(n)) marks_.resize(n);
        if (++stamp_ == 0) {  // the stamp wrapped: old marks could read as current
            std::fill(marks_.begin(), marks_.end(), Mark{});
            stamp_ = 1;
        }
    }
    bool marked(int i) const { return marks_[i].stamp == stamp_; }
    // Marks i with `value`; false, and nothing changed, if i was marked already.
    bool mark(int i, int value = 0) {
        if (marks_[i].stamp == stamp_) return false;
        marks_[i] = {stamp_, value};
        return true;
    }
    int value(int i) const { return marks_[i].value; }  // of a marked i
    void setValue(int i, int value) { marks_[i].value = value; }  // of a marked i

private:
    struct Mark {
        std::uint32_t stamp = 0;  // marked while it equals stamp_
        int value = 0;
    };
    std::vector<Mark> marks_;
    std::uint32_t stamp_ = 0;
};

// gatherNeighbourhood's (far/vertex_configuration.cpp).
struct NeighbourhoodScratch {
    StampedMarks reached;  // vertices of the region; value 1: within the inner rings
    StampedMarks region;   // faces of the region; value 1: queued by the walk
    StampedMarks labels;   // vertices labelled so far; value: the label
    std::vector<int> vertices, faces;
    std::vector<std::pair<int, int>> queue;  // (face, entry corner)
};

// cutPatch's (far/limit_deeper.cpp).
struct PatchScratch {
    StampedMarks local;   // vertices in the patch; value: the patch's number for it
    StampedMarks inside;  // faces in the patch
    std::vector<int> faces, sharpEdges;
};

}  // namespace v0
}  // namespace quadtri
