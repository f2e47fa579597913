// Test helpers for limit stencils: the plain loop that applies a LimitStencilTable's three weight
// runs (in double, so that tests see the table's own error only), vector geometry, and the
// comparison of two tables bit for bit.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <quadtri/far/limit_stencil_table.h>

namespace quadtri::test {

using Vec3 = std::array<double, 3>;

// got is want, bit for bit: arrays and pools (weights compared as bytes, -0.0 and 0.0 apart).
inline void expectSameLimitTable(const LimitStencilTable& got, const LimitStencilTable& want, const std::string& where) {
    EXPECT_EQ(got.numSourceVertices, want.numSourceVertices) << where;
    EXPECT_EQ(got.sizes, want.sizes) << where;
    EXPECT_EQ(got.offsets, want.offsets) << where;
    EXPECT_EQ(got.indices, want.indices) << where;
    EXPECT_EQ(got.weightOffsets, want.weightOffsets) << where;
    ASSERT_EQ(got.weights.size(), want.weights.size()) << where;
    EXPECT_TRUE(got.weights.empty() ||
                std::memcmp(got.weights.data(), want.weights.data(), got.weights.size() * sizeof(float)) == 0)
        << where << ": weight pools differ";
}

struct LimitData {
    std::vector<Vec3> position, du, dv;
};

// Tangents are accumulated relative to the stencil's first source, Σ w_k (s_k − s_0), which their
// weights summing to 0 allows: the data's magnitude then no longer multiplies the weights'
// rounding (docs/limit.md, "Precision").
inline LimitData applyLimit(const LimitStencilTable& table, const std::vector<float>& xyz) {
    LimitData out;
    for (int i = 0; i < table.numStencils(); ++i) {
        Vec3 p{0, 0, 0}, u{0, 0, 0}, v{0, 0, 0};
        const float* w = table.weightsOf(i);
        const float* s0 = xyz.data() + 3 * std::size_t(table.indices[table.offsets[i]]);
        for (int k = 0; k < table.size(i); ++k) {
            const float* s = xyz.data() + 3 * std::size_t(table.indices[table.offsets[i] + k]);
            for (int c = 0; c < 3; ++c) {
                p[c] += double(w[3 * k]) * s[c];
                u[c] += double(w[3 * k + 1]) * (double(s[c]) - s0[c]);
                v[c] += double(w[3 * k + 2]) * (double(s[c]) - s0[c]);
            }
        }
        out.position.push_back(p);
        out.du.push_back(u);
        out.dv.push_back(v);
    }
    return out;
}

inline Vec3 vec3(const float* p) { return {p[0], p[1], p[2]}; }
inline Vec3 vec3(const double* p) { return {p[0], p[1], p[2]}; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline double distance(const Vec3& a, const Vec3& b) { return norm({a[0] - b[0], a[1] - b[1], a[2] - b[2]}); }
// The angle between two vectors, in radians (robust near 0).
inline double angleBetween(const Vec3& a, const Vec3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

}  // namespace quadtri::test
