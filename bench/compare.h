// Agreement of two vertex sets given in different orders: each vertex of one set is matched to a
// distinct vertex of the other within a tolerance, through a uniform hash grid.
#pragma once

#include <string>
#include <vector>

namespace quadtri::bench {

struct MatchResult {
    bool ok = false;
    int numA = 0, numB = 0;
    int unmatched = 0;         // vertices of A with no unused vertex of B within the tolerance
    double maxDistance = 0;    // over the matched pairs
    std::string describe() const;
};

// a, b: xyz triples. Every vertex of a must find a distinct vertex of b within `tolerance`
// (absolute), and the counts must be equal.
MatchResult matchPositions(const std::vector<float>& a, const std::vector<float>& b, double tolerance);

// Same order on both sides: the largest coordinate difference.
double maxAbsDifference(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace quadtri::bench
