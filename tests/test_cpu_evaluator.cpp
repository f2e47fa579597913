// CpuEvaluator against hand-computed sums, for any width, stride, offset and range.
#include <gtest/gtest.h>

#include <stdexcept>

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

}  // namespace
}  // namespace quadtri
