// CpuEvaluator against hand-computed sums, for any width, stride, offset and range.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "kernels/stencil_kernel.h"
#include <quadtri/osd/cpu_evaluator.h>
#include "tests/test_support.h"

namespace quadtri {
namespace {

using test::handCheckedTable;

float sourceValue(int vertex, int component) { return float(10 * vertex + component + 1); }

void checkWidth(int width, int srcStride, int dstStride, int srcOffset, int dstOffset) {
    const StencilTable t = handCheckedTable();
    std::vector<float> src(srcOffset + 4 * srcStride, -7.0f);
    for (int v = 0; v < 4; ++v)
        for (int c = 0; c < width; ++c) src[srcOffset + v * srcStride + c] = sourceValue(v, c);
    std::vector<float> dst(dstOffset + 3 * dstStride, -99.0f);
    CpuEvaluator::EvalStencils(src.data(), BufferDescriptor(srcOffset, width, srcStride), dst.data(),
                               BufferDescriptor(dstOffset, width, dstStride), t);
    for (int c = 0; c < width; ++c) {
        const float s0 = sourceValue(0, c), s1 = sourceValue(1, c), s2 = sourceValue(2, c), s3 = sourceValue(3, c);
        EXPECT_FLOAT_EQ(dst[dstOffset + 0 * dstStride + c], 0.5f * (s0 + s1)) << "width " << width;
        EXPECT_FLOAT_EQ(dst[dstOffset + 1 * dstStride + c], s3) << "width " << width;
        EXPECT_FLOAT_EQ(dst[dstOffset + 2 * dstStride + c], 0.25f * (s0 + s1 + s2 + s3)) << "width " << width;
    }
    // Padding between elements and before the first one is never written.
    for (int i = 0; i < 3; ++i)
        for (int c = width; c < dstStride; ++c) EXPECT_EQ(dst[dstOffset + i * dstStride + c], -99.0f);
    for (int i = 0; i < dstOffset; ++i) EXPECT_EQ(dst[i], -99.0f);
}

TEST(CpuEvaluator, EveryWidthStrideAndOffset) {
    for (int width : {1, 2, 3, 4, 5, 7, 16}) {
        checkWidth(width, width, width, 0, 0);
        checkWidth(width, width + 1, width + 3, 2, 5);
    }
}

TEST(CpuEvaluator, RangeWritesOnlyItsRows) {
    const StencilTable t = handCheckedTable();
    std::vector<float> src(12);
    for (int v = 0; v < 4; ++v)
        for (int c = 0; c < 3; ++c) src[3 * v + c] = sourceValue(v, c);
    std::vector<float> dst(9, -1.0f);
    CpuEvaluator::EvalStencils(src.data(), BufferDescriptor(0, 3, 3), dst.data(), BufferDescriptor(0, 3, 3), t, 1, 2);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(dst[c], -1.0f);
        EXPECT_FLOAT_EQ(dst[3 + c], sourceValue(3, c));
        EXPECT_EQ(dst[6 + c], -1.0f);
    }
    CpuEvaluator::EvalStencils(src.data(), BufferDescriptor(0, 3, 3), dst.data(), BufferDescriptor(0, 3, 3), t, 2, 2);
    EXPECT_EQ(dst[6], -1.0f);  // empty range: nothing written
}

TEST(CpuEvaluator, RejectsBadArguments) {
    const StencilTable t = handCheckedTable();
    std::vector<float> src(16), dst(16);
    auto eval = [&](BufferDescriptor s, BufferDescriptor d, int start, int end) {
        CpuEvaluator::EvalStencils(src.data(), s, dst.data(), d, t, start, end);
    };
    EXPECT_THROW(eval({0, 3, 2}, {0, 3, 3}, 0, -1), std::invalid_argument);  // stride < length
    EXPECT_THROW(eval({0, 3, 3}, {0, 4, 4}, 0, -1), std::invalid_argument);  // length mismatch
    EXPECT_THROW(eval({-1, 3, 3}, {0, 3, 3}, 0, -1), std::invalid_argument); // negative offset
    EXPECT_THROW(eval({0, 3, 3}, {0, 3, 3}, 2, 1), std::invalid_argument);   // start > end
    EXPECT_THROW(eval({0, 3, 3}, {0, 3, 3}, 0, 4), std::invalid_argument);   // past the table
}

// evalStencils (the AVX2 + FMA loop for widths 3 and 4 where the CPU has it) against the portable
// reference loop on real tables: within 1e-6 of the scale of each sum (sum of |w| |x|), 3 floats
// bitwise equal to the same positions padded to 4, and any split of the range into pieces (which
// cuts the runs of shared weights the fast loop takes) bitwise equal to the whole.
TEST(CpuEvaluator, FastLoopsAgreeWithThePortableLoop) {
    const test::RefinedMesh r = test::refineMesh("mixed/mixed_torus.obj", 3);
    for (int L = 1; L <= 3; ++L) {
        const StencilTable& t = r.refiner->levelStencils(L);
        const kernels::StencilArrays arrays{t.offsets.data(), t.indices.data(), t.weightOffsets.data(),
                                            t.weights.data()};
        const int n = t.numStencils();
        const std::size_t sources = std::size_t(t.numSourceVertices);
        std::vector<float> src3(3 * sources), src4(4 * sources, 0.5f);  // the padding's value is never read
        for (std::size_t k = 0; k < src3.size(); ++k) {
            src3[k] = std::sin(0.37f * float(k)) + 0.01f * float(k % 89);
            src4[k / 3 * 4 + k % 3] = src3[k];
        }
        std::vector<float> portable(3 * std::size_t(n)), fast(3 * std::size_t(n)), pieces(3 * std::size_t(n)),
            fast4(4 * std::size_t(n));
        kernels::evalStencilsPortable(src3.data(), 3, portable.data(), 3, 3, arrays, 0, n);
        kernels::evalStencils(src3.data(), 3, fast.data(), 3, 3, arrays, 0, n);
        kernels::evalStencils(src4.data(), 4, fast4.data(), 4, 4, arrays, 0, n);
        for (int b = 0; b < n; b += 1 + b % 7)
            kernels::evalStencils(src3.data(), 3, pieces.data(), 3, 3, arrays, b, std::min(n, b + 1 + b % 7));
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) {
                float scale = 0.0f;
                for (int k = t.offsets[i]; k < t.offsets[i + 1]; ++k)
                    scale += std::fabs(t.weights[t.weightOffsets[i] + k - t.offsets[i]] * src3[3 * t.indices[k] + c]);
                const std::size_t at = 3 * std::size_t(i) + c;
                ASSERT_NEAR(fast[at], portable[at], 1e-6f * scale) << "level " << L << " stencil " << i;
                ASSERT_EQ(std::memcmp(&fast4[4 * std::size_t(i) + c], &fast[at], sizeof(float)), 0)
                    << "level " << L << " stencil " << i << ": 4 floats differ from 3";
            }
        EXPECT_EQ(std::memcmp(pieces.data(), fast.data(), fast.size() * sizeof(float)), 0) << "level " << L;
    }
}

}  // namespace
}  // namespace quadtri
