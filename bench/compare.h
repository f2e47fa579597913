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
// (absolute), and the counts must be equal. partnerOfA, when given, receives each vertex of a's
// partner in b (-1 for none).
MatchResult matchPositions(const std::vector<float>& a, const std::vector<float>& b, double tolerance,
                           std::vector<int>* partnerOfA = nullptr);

// The largest angle in radians between the normal of a point of a and the normal of its partner
// in b (matched by position as matchPositions does); infinity if some point has no partner.
double maxNormalAngle(const std::vector<float>& aPositions, const std::vector<float>& aNormals,
                      const std::vector<float>& bPositions, const std::vector<float>& bNormals, double tolerance);

// normalize(du x dv) into n (zero where the cross product is).
void unitNormal(const float* du, const float* dv, float* n);

// The angle in radians between two directions (3 floats each).
double angleBetween(const float* n, const float* m);

// Same order on both sides (3 floats a point): the farthest pair of positions and the largest
// angle between the normals.
struct InOrderDifference {
    double position = 0;
    double normalAngle = 0;
};
InOrderDifference compareInOrder(const std::vector<float>& positions, const std::vector<float>& normals,
                                 const std::vector<float>& referencePositions,
                                 const std::vector<float>& referenceNormals);

// Same order on both sides: the largest coordinate difference.
double maxAbsDifference(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace quadtri::bench
