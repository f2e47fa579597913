// matchPositions (tests/position_match.h): a uniform hash grid over the reference points.
#include "tests/position_match.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace quadtri::test {

namespace {

struct CellKey {
    int64_t x, y, z;
    bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
};

struct CellKeyHash {
    size_t operator()(const CellKey& k) const {
        uint64_t h = uint64_t(k.x) * 0x9E3779B97F4A7C15ull;
        h ^= uint64_t(k.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
        h ^= uint64_t(k.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
        return size_t(h);
    }
};

// Nearest-neighbour queries over a fixed point set, optionally skipping points marked as used.
class PointGrid {
public:
    explicit PointGrid(const std::vector<float>& xyz) : xyz_(xyz), n_(int(xyz.size() / 3)) {
        double lo[3], hi[3];
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::numeric_limits<double>::max();
            hi[c] = -std::numeric_limits<double>::max();
        }
        for (int i = 0; i < n_; ++i)
            for (int c = 0; c < 3; ++c) {
                lo[c] = std::min(lo[c], double(xyz_[3 * size_t(i) + c]));
                hi[c] = std::max(hi[c], double(xyz_[3 * size_t(i) + c]));
            }
        double d2 = 0;
        for (int c = 0; c < 3; ++c) {
            origin_[c] = n_ > 0 ? lo[c] : 0.0;
            d2 += n_ > 0 ? (hi[c] - lo[c]) * (hi[c] - lo[c]) : 0.0;
        }
        // Points of a refined surface are spaced about diag / sqrt(n): a few points per cell.
        const double diag = std::sqrt(d2);
        cell_ = n_ > 1 && diag > 0 ? 2.0 * diag / std::sqrt(double(n_)) : 1.0;
        for (int c = 0; c < 3; ++c) {
            cmin_[c] = std::numeric_limits<int64_t>::max();
            cmax_[c] = std::numeric_limits<int64_t>::min();
        }
        for (int i = 0; i < n_; ++i) {
            CellKey k = keyOf(&xyz_[3 * size_t(i)]);
            cells_[k].push_back(i);
            const int64_t kk[3] = {k.x, k.y, k.z};
            for (int c = 0; c < 3; ++c) {
                cmin_[c] = std::min(cmin_[c], kk[c]);
                cmax_[c] = std::max(cmax_[c], kk[c]);
            }
        }
    }

    // The nearest point to q (skipping used[i] != 0 when `used` is given), or -1 if none is left.
    int nearest(const float* q, const std::vector<char>* used, double* distance) const {
        const CellKey center = keyOf(q);
        int best = -1;
        double bestD2 = std::numeric_limits<double>::max();
        const int64_t cc[3] = {center.x, center.y, center.z};
        // Largest shell radius needed to cover every occupied cell.
        int64_t rCover = 0;
        for (int c = 0; c < 3; ++c) rCover = std::max({rCover, cc[c] - cmin_[c], cmax_[c] - cc[c]});
        const int64_t kMaxShell = 4;
        for (int64_t r = 0; r <= std::min(rCover, kMaxShell); ++r) {
            for (int64_t dx = -r; dx <= r; ++dx)
                for (int64_t dy = -r; dy <= r; ++dy)
                    for (int64_t dz = -r; dz <= r; ++dz) {
                        if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != r) continue;
                        auto it = cells_.find(CellKey{center.x + dx, center.y + dy, center.z + dz});
                        if (it == cells_.end()) continue;
                        for (int i : it->second) consider(q, i, used, best, bestD2);
                    }
            // Points in shells beyond r are farther than r * cell from q.
            const double bound = double(r) * cell_;
            if ((best >= 0 && bestD2 <= bound * bound) || r == rCover) {
                *distance = best >= 0 ? std::sqrt(bestD2) : std::numeric_limits<double>::infinity();
                return best;
            }
        }
        if (rCover > kMaxShell) {
            // Far from every remaining point: search them all.
            for (int i = 0; i < n_; ++i) consider(q, i, used, best, bestD2);
        }
        *distance = best >= 0 ? std::sqrt(bestD2) : std::numeric_limits<double>::infinity();
        return best;
    }

private:
    CellKey keyOf(const float* p) const {
        return CellKey{int64_t(std::floor((p[0] - origin_[0]) / cell_)), int64_t(std::floor((p[1] - origin_[1]) / cell_)),
                       int64_t(std::floor((p[2] - origin_[2]) / cell_))};
    }

    void consider(const float* q, int i, const std::vector<char>* used, int& best, double& bestD2) const {
        if (used && (*used)[i]) return;
        double d2 = 0;
        for (int c = 0; c < 3; ++c) {
            const double d = double(q[c]) - double(xyz_[3 * size_t(i) + c]);
            d2 += d * d;
        }
        if (d2 < bestD2) {
            bestD2 = d2;
            best = i;
        }
    }

    const std::vector<float>& xyz_;
    int n_;
    double origin_[3];
    double cell_;
    int64_t cmin_[3], cmax_[3];
    std::unordered_map<CellKey, std::vector<int>, CellKeyHash> cells_;
};

}  // namespace

PositionMatch matchPositions(const std::vector<float>& ours, const std::vector<float>& reference, double diagonal,
                             double tolerance) {
    PositionMatch m;
    m.numOurs = int(ours.size() / 3);
    m.numReference = int(reference.size() / 3);
    m.countsEqual = m.numOurs == m.numReference;
    m.diagonal = diagonal;
    m.ourToReference.assign(m.numOurs, -1);

    PointGrid grid(reference);
    std::vector<char> used(m.numReference, 0);
    for (int i = 0; i < m.numOurs; ++i) {
        const float* q = &ours[3 * size_t(i)];
        double d = 0;
        int j = grid.nearest(q, nullptr, &d);
        if (j >= 0 && used[j]) {
            ++m.numCollisions;
            j = grid.nearest(q, &used, &d);
        }
        if (j < 0) {
            // More of our vertices than reference vertices: nothing left to match.
            m.maxDistance = std::numeric_limits<double>::infinity();
            m.worstOurs = i;
            m.worstReference = -1;
            m.outliers.push_back(i);
            continue;
        }
        used[j] = 1;
        m.ourToReference[i] = j;
        if (m.worstOurs < 0 || d > m.maxDistance) {
            m.maxDistance = d;
            m.worstOurs = i;
            m.worstReference = j;
        }
        if (d > tolerance * diagonal) m.outliers.push_back(i);
    }
    return m;
}

}  // namespace quadtri::test
