#include "bench/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <utility>

namespace quadtri::bench {

namespace {

// The points of b bucketed into cubic cells, sorted by cell key: a cell's points are one range.
class CellGrid {
public:
    CellGrid(const std::vector<float>& xyz, double minCell) : xyz_(xyz) {
        const size_t n = xyz.size() / 3;
        double hi[3];
        for (int c = 0; c < 3; ++c) {
            origin_[c] = std::numeric_limits<double>::max();
            hi[c] = -std::numeric_limits<double>::max();
        }
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) {
                origin_[c] = std::min(origin_[c], double(xyz[3 * i + c]));
                hi[c] = std::max(hi[c], double(xyz[3 * i + c]));
            }
        double d2 = 0;
        for (int c = 0; c < 3; ++c) d2 += n ? (hi[c] - origin_[c]) * (hi[c] - origin_[c]) : 0.0;
        // Points of a surface lie about diagonal / sqrt(n) apart: a few per cell.
        cell_ = std::max(minCell, n > 1 ? std::sqrt(d2) / std::sqrt(double(n)) : 1.0);
        for (int c = 0; c < 3; ++c) cells_[c] = n ? std::int64_t((hi[c] - origin_[c]) / cell_) + 1 : 0;
        entries_.reserve(n);
        for (size_t i = 0; i < n; ++i) {
            std::int64_t k[3];
            for (int c = 0; c < 3; ++c) k[c] = cellOf(xyz[3 * i + c], c);
            entries_.emplace_back(key(k), int(i));
        }
        std::sort(entries_.begin(), entries_.end());
    }

    // The nearest point within `tolerance` of p that is not used, or -1.
    int nearestUnused(const float* p, double tolerance, const std::vector<char>& used, double* distance) const {
        std::int64_t lo[3], hi[3];
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::max<std::int64_t>(0, cellOf(p[c] - tolerance, c));
            hi[c] = std::min<std::int64_t>(cells_[c] - 1, cellOf(p[c] + tolerance, c));
            if (lo[c] > hi[c]) return -1;
        }
        int best = -1;
        double bestD2 = tolerance * tolerance;
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
            for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
                for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
                    const std::int64_t k[3] = {x, y, z};
                    auto first = std::lower_bound(entries_.begin(), entries_.end(), std::make_pair(key(k), -1));
                    for (auto it = first; it != entries_.end() && it->first == key(k); ++it) {
                        if (used[it->second]) continue;
                        double d2 = 0;
                        for (int c = 0; c < 3; ++c) {
                            const double d = double(p[c]) - double(xyz_[3 * size_t(it->second) + c]);
                            d2 += d * d;
                        }
                        if (d2 <= bestD2) {
                            bestD2 = d2;
                            best = it->second;
                        }
                    }
                }
        *distance = std::sqrt(bestD2);
        return best;
    }

private:
    std::int64_t cellOf(double x, int axis) const { return std::int64_t(std::floor((x - origin_[axis]) / cell_)); }
    std::uint64_t key(const std::int64_t k[3]) const {
        return (std::uint64_t(k[0]) * std::uint64_t(cells_[1]) + std::uint64_t(k[1])) * std::uint64_t(cells_[2]) +
               std::uint64_t(k[2]);
    }

    const std::vector<float>& xyz_;
    double origin_[3];
    double cell_ = 1.0;
    std::int64_t cells_[3];
    std::vector<std::pair<std::uint64_t, int>> entries_;
};

}  // namespace

std::string MatchResult::describe() const {
    std::ostringstream s;
    s << numA << " vs " << numB << " vertices, " << unmatched << " without a partner, max distance " << maxDistance;
    return s.str();
}

MatchResult matchPositions(const std::vector<float>& a, const std::vector<float>& b, double tolerance,
                           std::vector<int>* partnerOfA) {
    MatchResult m;
    m.numA = int(a.size() / 3);
    m.numB = int(b.size() / 3);
    CellGrid grid(b, 2.0 * tolerance);
    std::vector<char> used(m.numB, 0);
    if (partnerOfA) partnerOfA->assign(std::size_t(m.numA), -1);
    for (int i = 0; i < m.numA; ++i) {
        double d = 0;
        const int j = grid.nearestUnused(&a[3 * size_t(i)], tolerance, used, &d);
        if (partnerOfA) (*partnerOfA)[std::size_t(i)] = j;
        if (j < 0) {
            ++m.unmatched;
            continue;
        }
        used[j] = 1;
        m.maxDistance = std::max(m.maxDistance, d);
    }
    m.ok = m.numA == m.numB && m.unmatched == 0;
    return m;
}

double maxNormalAngle(const std::vector<float>& aPositions, const std::vector<float>& aNormals,
                      const std::vector<float>& bPositions, const std::vector<float>& bNormals, double tolerance) {
    std::vector<int> partner;
    if (!matchPositions(aPositions, bPositions, tolerance, &partner).ok) return std::numeric_limits<double>::infinity();
    double worst = 0;
    for (std::size_t i = 0; i < partner.size(); ++i)
        worst = std::max(worst, angleBetween(&aNormals[3 * i], &bNormals[3 * std::size_t(partner[i])]));
    return worst;
}

void unitNormal(const float* du, const float* dv, float* n) {
    const float x = du[1] * dv[2] - du[2] * dv[1], y = du[2] * dv[0] - du[0] * dv[2], z = du[0] * dv[1] - du[1] * dv[0];
    const float length = std::sqrt(x * x + y * y + z * z);
    const float scale = length > 0 ? 1 / length : 0;
    n[0] = x * scale;
    n[1] = y * scale;
    n[2] = z * scale;
}

double angleBetween(const float* n, const float* m) {
    double dot = 0, cross2 = 0;
    for (int c = 0; c < 3; ++c) dot += double(n[c]) * m[c];
    for (int c = 0; c < 3; ++c) {
        const double x = double(n[(c + 1) % 3]) * m[(c + 2) % 3] - double(n[(c + 2) % 3]) * m[(c + 1) % 3];
        cross2 += x * x;
    }
    return std::atan2(std::sqrt(cross2), dot);
}

InOrderDifference compareInOrder(const std::vector<float>& positions, const std::vector<float>& normals,
                                 const std::vector<float>& referencePositions,
                                 const std::vector<float>& referenceNormals) {
    if (positions.size() != referencePositions.size() || normals.size() != referenceNormals.size())
        return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    InOrderDifference d;
    for (std::size_t i = 0; i + 2 < positions.size(); i += 3) {
        double squared = 0;
        for (int c = 0; c < 3; ++c) squared += std::pow(double(positions[i + c]) - referencePositions[i + c], 2);
        d.position = std::max(d.position, std::sqrt(squared));
        d.normalAngle = std::max(d.normalAngle, angleBetween(&normals[i], &referenceNormals[i]));
    }
    return d;
}

double maxAbsDifference(const std::vector<float>& a, const std::vector<float>& b) {
    if (a.size() != b.size()) return std::numeric_limits<double>::infinity();
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(double(a[i]) - double(b[i])));
    return worst;
}

}  // namespace quadtri::bench
