// Working space of the generic limit masks (docs/limit_eigen.md, "Build time"): the marks and
// lists that reading a vertex's neighbourhood and cutting its patch need, kept from one vertex to
// the next so that a vertex costs what it touches, not the level's size or an allocation per set.
// One per builder of a limit table: LimitMaskCache holds it (far/limit/limit_eigen.h).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace quadtri {
inline namespace v0 {
namespace internal {

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

// What gatherNeighbourhood (far/limit/vertex_configuration.cpp) and cutPatch (far/limit/limit_deeper.cpp)
// mark and list. One walk at a time: each clears what it uses as it starts and neither calls the
// other, so they share it, and it costs 8 bytes per vertex twice and per face once of the largest
// level walked.
struct WalkScratch {
    StampedMarks vertices;  // reached; value: 1 within the neighbourhood's inner rings, or the patch's number
    StampedMarks labels;    // the neighbourhood's vertices labelled so far; value: the label
    StampedMarks faces;     // reached; value (the neighbourhood's): 1 once queued by the walk
    std::vector<int> vertexList, faceList, sharpEdges;
    std::vector<std::pair<int, int>> queue;  // (face, entry corner)
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
