// Matching two sets of positions vertex to vertex, for comparing refined levels whose vertex
// orders differ (OpenSubdiv's and quadtri's).
#pragma once

#include <vector>

namespace quadtri::test {

// Result of matching each vertex of `ours` to a distinct vertex of `reference` by position.
struct PositionMatch {
    int numOurs = 0;
    int numReference = 0;
    bool countsEqual = false;
    // ourToReference[i]: the reference vertex matched to our vertex i. The matching is one-to-one
    // by construction: our vertices are taken in order, each gets the nearest reference vertex not
    // yet taken. When the two sets agree up to the tolerance this is the nearest-neighbour matching.
    std::vector<int> ourToReference;
    // Our vertices whose unrestricted nearest reference vertex was already taken by another of our
    // vertices (0 unless the sets contain (near) duplicates or disagree).
    int numCollisions = 0;
    double maxDistance = 0;        // over matched pairs
    int worstOurs = -1;            // our vertex with the largest distance
    int worstReference = -1;       // its reference partner
    double diagonal = 0;           // bounding-box diagonal used to normalize
    double maxRelative() const { return diagonal > 0 ? maxDistance / diagonal : maxDistance; }
    // Our vertices whose matched distance exceeds `tolerance * diagonal`, in index order.
    std::vector<int> outliers;
};

// Matches positions (xyz triples) with a uniform hash grid (expected O(n) for well spread points).
// `diagonal` normalizes the distances (pass the bounding-box diagonal of the control mesh);
// `tolerance` (relative) only decides which vertices are listed as outliers.
PositionMatch matchPositions(const std::vector<float>& ours, const std::vector<float>& reference, double diagonal,
                             double tolerance);

}  // namespace quadtri::test
