// EvalLimitStencils on CpuEvaluator and TbbEvaluator: against the plain reference loop over the
// table (the portable kernel bitwise in float; every path within float rounding of the double
// loop; the 3-float AVX2 + FMA loop, where the CPU runs it, bitwise its documented order of fused
// multiply-adds), any subset of outputs with padded layouts and widths 1-7, unit normals equal to
// normalize(dU x dV), the degenerate fallback (the level's area-weighted face normal, or (0, 0, 0)
// without a MeshNormalTable), TBB bitwise equal to CPU in arenas of 1 and 2 threads, and the same
// argument checks on both.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#include <quadtri/far/refiner.h>
#include "bench/meshes/torus.h"
#include "kernels/limit_kernel.h"
#include "osd/internal/eval_arguments.h"
#include "tests/limit/limit_test_tables.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

constexpr float kUntouched = -4321.25f;
const BufferDescriptor kPacked(0, 3, 3);

std::size_t floatsFor(const BufferDescriptor& d, int count) { return std::size_t(d.offset) + std::size_t(count) * d.stride; }

std::vector<float> randomSource(const BufferDescriptor& d, int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(-3.0f, 3.0f);
    std::vector<float> src(floatsFor(d, count), kUntouched);
    for (int v = 0; v < count; ++v)
        for (int c = 0; c < d.length; ++c) src[d.offset + std::size_t(v) * d.stride + c] = value(rng);
    return src;
}

// The four outputs of one call, each with its own padded layout.
struct Outputs {
    BufferDescriptor desc[4];
    std::vector<float> data[4];
    float* ptr(int k, bool wanted) { return wanted ? data[k].data() : nullptr; }
};

Outputs makeOutputs(int width, int count) {
    Outputs o{{BufferDescriptor(1, width, width + 1), BufferDescriptor(0, width, width + 2),
               BufferDescriptor(3, width, width), BufferDescriptor(2, 3, 5)},
              {}};
    for (int k = 0; k < 4; ++k) o.data[k].assign(floatsFor(o.desc[k], count), kUntouched);
    return o;
}

enum class Host { Cpu, Tbb };

void evalOn(Host host, const std::vector<float>& src, const BufferDescriptor& srcDesc, Outputs& o, const bool want[4],
            const LimitStencilTable& t, const MeshNormalTable* fallback, int start = 0, int end = -1) {
    auto eval = host == Host::Cpu ? &CpuEvaluator::EvalLimitStencils : &TbbEvaluator::EvalLimitStencils;
    eval(src.data(), srcDesc, o.ptr(0, want[0]), o.desc[0], o.ptr(1, want[1]), o.desc[1], o.ptr(2, want[2]), o.desc[2],
         o.ptr(3, want[3]), o.desc[3], t, fallback, start, end);
}

// The call through kernels::evalLimitPortable, the loop every width but 3 takes (and 3 where the
// CPU has no AVX2 + FMA), with the evaluators' own argument handling.
void evalPortable(const std::vector<float>& src, const BufferDescriptor& srcDesc, Outputs& o, const bool want[4],
                  const LimitStencilTable& t) {
    detail::HostLimitCall c;
    int end = -1;
    if (!detail::hostLimitCall(c, src.data(), srcDesc, o.ptr(0, want[0]), o.desc[0], o.ptr(1, want[1]), o.desc[1],
                               o.ptr(2, want[2]), o.desc[2], o.ptr(3, want[3]), o.desc[3], t, nullptr, 0, end))
        return;
    kernels::evalLimitPortable(c.src, srcDesc.stride, srcDesc.length, c.arrays, c.outputs, 0, end);
}

// Whether the evaluators' width-`width` results are the portable loop's bits.
bool portableBits(int width) { return width != 3 || !kernels::limitKernelUsesAvx2(); }

const float* element(const Outputs& o, int k, int i) { return &o.data[k][o.desc[k].offset + std::size_t(i) * o.desc[k].stride]; }

TEST(LimitEvaluator, MatchesTheReferenceLoopForEveryWidthAndOutputSubset) {
    const int numSources = 500, numStencils = 3000;
    const LimitStencilTable t = randomLimitTable(numStencils, numSources, 7);
    for (int width : {1, 2, 3, 4, 7}) {
        const BufferDescriptor srcDesc(2, width, width + 3);
        const std::vector<float> src = randomSource(srcDesc, numSources, 11 + width);
        std::vector<float> p, u, v;
        std::vector<double> pd, ud, vd;
        referenceLimit(t, src, srcDesc, p, u, v);
        referenceLimit(t, src, srcDesc, pd, ud, vd);
        const std::vector<float>* reference[3] = {&p, &u, &v};
        const std::vector<double>* exact[3] = {&pd, &ud, &vd};
        for (int subset = 1; subset < 8; ++subset) {
            const bool want[4] = {(subset & 1) != 0, (subset & 2) != 0, (subset & 4) != 0, false};
            for (bool portable : {false, true}) {
                Outputs o = makeOutputs(width, numStencils);
                if (portable)
                    evalPortable(src, srcDesc, o, want, t);
                else
                    evalOn(Host::Cpu, src, srcDesc, o, want, t, nullptr);
                for (int k = 0; k < 3; ++k) {
                    for (std::size_t f = 0; f < o.data[k].size(); ++f) {
                        const BufferDescriptor& d = o.desc[k];
                        const bool inElement = f >= std::size_t(d.offset) && int((f - d.offset) % d.stride) < width;
                        if (!want[k] || !inElement) {
                            ASSERT_EQ(o.data[k][f], kUntouched)
                                << "width " << width << " output " << k << " float " << f;
                            continue;
                        }
                        const std::size_t i = (f - d.offset) / d.stride, c = (f - d.offset) % d.stride;
                        const float expected = (*reference[k])[i * width + c];
                        if (portable || portableBits(width)) {
                            ASSERT_EQ(std::memcmp(&o.data[k][f], &expected, sizeof(float)), 0)
                                << "width " << width << " output " << k << " stencil " << i;
                        }
                        // Float rounding only: sums of up to 24 terms of magnitude <= 3 * |w|.
                        ASSERT_NEAR(o.data[k][f], (*exact[k])[i * width + c], 1e-4);
                    }
                }
            }
        }
    }
}

// The 3-float AVX2 + FMA loop's position and tangents, rebuilt in its documented order
// (kernels/limit_kernel_avx2.cpp): per output two sums, the even entries' and the odd ones', one fused multiply-add per entry, the tangents over the source
// minus the stencil's first source, the even sum plus the odd one at the end. Bit for bit: the
// loop takes an entry and the next together in one register, and each half must still do these
// operations. Skipped where the CPU does not run that loop.
TEST(LimitEvaluator, TheAvx2LoopAddsInItsDocumentedOrder) {
    if (!kernels::limitKernelUsesAvx2()) GTEST_SKIP() << "the CPU runs the portable loop";
    const int numSources = 400, numStencils = 2500;
    const LimitStencilTable t = randomLimitTable(numStencils, numSources, 17);
    const std::vector<float> src = randomSource(kPacked, numSources, 19);
    Outputs o = makeOutputs(3, numStencils);
    const bool want[4] = {true, true, true, false};
    evalOn(Host::Cpu, src, kPacked, o, want, t, nullptr);
    for (int i = 0; i < numStencils; ++i) {
        const int n = t.sizes[i];
        const int* idx = t.indices.data() + t.offsets[i];
        const float* w = t.weights.data() + t.weightOffsets[i];
        for (int c = 0; c < 3; ++c) {
            const float first = n > 0 ? src[3 * std::size_t(idx[0]) + c] : 0.0f;
            float sums[3][2] = {{0.0f, 0.0f}, {0.0f, 0.0f}, {0.0f, 0.0f}};  // [output][even, odd]
            for (int k = 0; k < n; ++k) {
                const float x = src[3 * std::size_t(idx[k]) + c], d = x - first;
                const int half = k % 2;  // an odd count's last entry is even: with the even ones
                sums[0][half] = std::fma(w[3 * k + 0], x, sums[0][half]);
                sums[1][half] = std::fma(w[3 * k + 1], d, sums[1][half]);
                sums[2][half] = std::fma(w[3 * k + 2], d, sums[2][half]);
            }
            for (int out = 0; out < 3; ++out) {
                const float expected = sums[out][0] + sums[out][1];
                ASSERT_EQ(std::memcmp(element(o, out, i) + c, &expected, sizeof(float)), 0)
                    << "stencil " << i << " (" << n << " entries) output " << out << " component " << c;
            }
        }
    }
}

// normalize(dU x dV) in float, operation by operation as kernels/limit_kernel.h documents it (the
// portable loop gives these bits), and on every path within float rounding of the double normal,
// (0, 0, 0) where the tangents are parallel.
TEST(LimitEvaluator, NormalsAreTheUnitCrossProductOfTheTangents) {
    const LimitStencilTable t = randomLimitTable(2000, 300, 3);
    const std::vector<float> src = randomSource(kPacked, 300, 5);
    std::vector<float> pf, uf, vf;
    std::vector<double> p, u, v;
    referenceLimit(t, src, kPacked, pf, uf, vf);
    referenceLimit(t, src, kPacked, p, u, v);
    for (bool portable : {false, true}) {
        Outputs o = makeOutputs(3, t.numStencils());
        const bool want[4] = {false, false, false, true};
        if (portable)
            evalPortable(src, kPacked, o, want, t);
        else
            evalOn(Host::Cpu, src, kPacked, o, want, t, nullptr);
        const bool bitwise = portable || portableBits(3);
        int checked = 0;
        for (int i = 0; i < t.numStencils(); ++i) {
            const float* q = element(o, 3, i);
            const double* a = &u[3 * i];
            const double* b = &v[3 * i];
            const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
            const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            const double size =
                std::sqrt((a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
            if (bitwise) {
                const float* x = &uf[3 * i];
                const float* y = &vf[3 * i];
                const float nf[3] = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
                const float n2 = nf[0] * nf[0] + nf[1] * nf[1] + nf[2] * nf[2];
                const float x2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2], y2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
                if (!(n2 > 1e-4f * 1e-4f * x2 * y2)) {
                    for (int c = 0; c < 3; ++c) ASSERT_EQ(q[c], 0.0f) << "degenerate stencil " << i;
                    continue;
                }
                const float scale = 1.0f / std::sqrt(n2);
                for (int c = 0; c < 3; ++c) ASSERT_EQ(q[c], nf[c] * scale) << "stencil " << i << " component " << c;
            } else if (len <= 0.5e-4 * size) {  // parallel beyond doubt: the degenerate case
                for (int c = 0; c < 3; ++c) ASSERT_EQ(q[c], 0.0f) << "degenerate stencil " << i;
                continue;
            }
            if (len <= 1e-3 * size) continue;  // nearly parallel: float rounding moves the direction
            const double qlen = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2]);
            ASSERT_NEAR(qlen, 1.0, 1e-6) << i;
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(q[c], n[c] / len, 1e-4) << i;
            ++checked;
        }
        EXPECT_GT(checked, 1800);  // all but the one-source stencils (no tangent) and near-parallel pairs
    }
}

void expectSameBits(const Outputs& a, const Outputs& b, const std::string& what) {
    for (int k = 0; k < 4; ++k)
        EXPECT_EQ(std::memcmp(a.data[k].data(), b.data[k].data(), a.data[k].size() * sizeof(float)), 0)
            << what << " output " << k;
}

// The 3-float AVX2 loop takes normals eight stencils at a time (kernels/limit_kernel_avx2.cpp);
// a range shorter than eight takes the per-stencil normal. Every stencil evaluated alone, and
// ranges that start and end off the batches, give the whole call's bits, degenerate tangents
// (zero without a fallback, the mesh normal with one) included.
TEST(LimitEvaluator, BatchedNormalsAreThePerStencilOnesBitwise) {
    const bool all[4] = {true, true, true, true};
    const LimitStencilTable random = randomLimitTable(3000, 400, 29);
    const std::vector<float> src = randomSource(kPacked, 400, 31);
    const CornerLevel L = cornerLevel(2);
    struct Case {
        const LimitStencilTable& table;
        const std::vector<float>& src;
        const MeshNormalTable* fallback;
        const char* name;
    };
    for (const Case& c : {Case{random, src, nullptr, "random"}, Case{L.table, L.positions, &L.meshNormals, "corners"}}) {
        const int n = c.table.numStencils();
        Outputs whole = makeOutputs(3, n), single = makeOutputs(3, n), ranges = makeOutputs(3, n);
        evalOn(Host::Cpu, c.src, kPacked, whole, all, c.table, c.fallback);
        for (int i = 0; i < n; ++i) evalOn(Host::Cpu, c.src, kPacked, single, all, c.table, c.fallback, i, i + 1);
        for (int i = 0; i < n; i += 13) evalOn(Host::Cpu, c.src, kPacked, ranges, all, c.table, c.fallback, i, std::min(n, i + 13));
        expectSameBits(whole, single, std::string(c.name) + ", one stencil at a time");
        expectSameBits(whole, ranges, std::string(c.name) + ", ranges of 13");
    }
}

// Parallel or zero tangents: the level's mesh normal at that vertex with a fallback table,
// (0, 0, 0) without; elsewhere the normal of the vertex's first face's corner.
TEST(LimitEvaluator, DegenerateTangentsFallBackToTheMeshNormal) {
    const CornerLevel L = cornerLevel(2);
    const int n = L.meshNormals.numVertices;
    std::vector<float> mesh(3 * std::size_t(n));
    CpuEvaluator::EvalMeshNormals(L.positions.data(), kPacked, mesh.data(), kPacked, L.meshNormals);
    Outputs with = makeOutputs(3, n), without = makeOutputs(3, n);
    const bool want[4] = {true, false, false, true};
    evalOn(Host::Cpu, L.positions, kPacked, with, want, L.table, &L.meshNormals);
    evalOn(Host::Cpu, L.positions, kPacked, without, want, L.table, nullptr);
    int degenerate = 0;
    for (int v = 0; v < n; ++v) {
        const float* a = element(with, 3, v);
        const float* b = element(without, 3, v);
        for (int c = 0; c < 3; ++c) ASSERT_EQ(element(with, 0, v)[c], L.positions[3 * v + c]);
        if (isDegenerateCorner(v)) {
            ++degenerate;
            for (int c = 0; c < 3; ++c) {
                ASSERT_EQ(a[c], mesh[3 * v + c]) << v;
                ASSERT_EQ(b[c], 0.0f) << v;
            }
        } else {
            const double len = std::sqrt(double(a[0]) * a[0] + double(a[1]) * a[1] + double(a[2]) * a[2]);
            ASSERT_NEAR(len, 1.0, 1e-6) << v;
            // A corner's normal leans the same way as the vertex's mesh normal.
            ASSERT_GT(a[0] * mesh[3 * v] + a[1] * mesh[3 * v + 1] + a[2] * mesh[3 * v + 2], 0.2f) << v;
            for (int c = 0; c < 3; ++c) ASSERT_EQ(a[c], b[c]) << v;
        }
    }
    EXPECT_GT(degenerate, n / 8);
}

TEST(LimitEvaluator, TbbEqualsCpuBitwise) {
    const bool all[4] = {true, true, true, true};
    // Random tables (several blocks), widths 3 and 5, and the corner level with its fallback.
    for (int width : {3, 5}) {
        const LimitStencilTable t = randomLimitTable(20000, 4000, 19);
        const BufferDescriptor srcDesc(1, width, width + 1);
        const std::vector<float> src = randomSource(srcDesc, 4000, 23);
        const bool want[4] = {true, true, true, width == 3};
        Outputs cpu = makeOutputs(width, t.numStencils());
        evalOn(Host::Cpu, src, srcDesc, cpu, want, t, nullptr);
        for (int threads : {1, 2}) {
            Outputs tbb = makeOutputs(width, t.numStencils());
            tbb::task_arena(threads).execute([&] { evalOn(Host::Tbb, src, srcDesc, tbb, want, t, nullptr); });
            expectSameBits(cpu, tbb, "width " + std::to_string(width) + ", " + std::to_string(threads) + " threads");
        }
        // Ranges write their rows only.
        Outputs cpuPart = makeOutputs(width, t.numStencils()), tbbPart = makeOutputs(width, t.numStencils());
        evalOn(Host::Cpu, src, srcDesc, cpuPart, want, t, nullptr, 1234, 17000);
        evalOn(Host::Tbb, src, srcDesc, tbbPart, want, t, nullptr, 1234, 17000);
        expectSameBits(cpuPart, tbbPart, "range");
        for (int i : {0, 1233, 17000, 19999}) EXPECT_EQ(element(cpuPart, 0, i)[0], kUntouched) << i;
        EXPECT_EQ(element(cpuPart, 0, 1234)[0], element(cpu, 0, 1234)[0]);
    }
    const CornerLevel L = cornerLevel(3);
    Outputs cpu = makeOutputs(3, L.table.numStencils()), tbb = makeOutputs(3, L.table.numStencils());
    evalOn(Host::Cpu, L.positions, kPacked, cpu, all, L.table, &L.meshNormals);
    tbb::task_arena(2).execute([&] { evalOn(Host::Tbb, L.positions, kPacked, tbb, all, L.table, &L.meshNormals); });
    expectSameBits(cpu, tbb, "corner level with fallback");
}

// The Refiner's own tables. A flat grid's limit surface is its plane: every normal is +z, the
// corners' too (their tangents are the first face's edges), and the limit points keep z = 0.
// On a torus the limit normals point outward and near the refined mesh's normals.
TEST(LimitEvaluator, RefinerTablesGiveFlatAndOutwardNormals) {
    const int nx = 5, ny = 4;
    std::vector<int> sizes, verts;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const int a = j * (nx + 1) + i;
            sizes.push_back(4);
            verts.insert(verts.end(), {a, a + 1, a + nx + 2, a + nx + 1});
        }
    std::vector<float> grid;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) grid.insert(grid.end(), {float(i) + 0.2f * float(j % 2), 0.8f * float(j), 0.0f});
    for (Scheme scheme : {Scheme::CatmullClark, Scheme::StamLoop}) {
        Options options;
        options.scheme = scheme;
        Refiner refiner(descriptorOf((nx + 1) * (ny + 1), sizes, verts), options);
        refiner.refineUniform(2);
        const LimitStencilTable t = refiner.factorizedLimitStencils(2);
        Outputs o = makeOutputs(3, t.numStencils());
        const bool want[4] = {true, false, false, true};
        evalOn(Host::Cpu, grid, kPacked, o, want, t, nullptr);
        for (int i = 0; i < t.numStencils(); ++i) {
            ASSERT_EQ(element(o, 0, i)[2], 0.0f) << toString(scheme) << " point " << i;
            ASSERT_EQ(element(o, 3, i)[0], 0.0f) << toString(scheme) << " point " << i;
            ASSERT_EQ(element(o, 3, i)[1], 0.0f) << toString(scheme) << " point " << i;
            ASSERT_FLOAT_EQ(element(o, 3, i)[2], 1.0f) << toString(scheme) << " point " << i;
        }
    }
    const bench::ControlMesh m = bench::makeTorus(12, bench::TorusFaces::Quads);
    Options options;
    options.scheme = Scheme::CatmullClark;
    Refiner refiner(descriptorOf(m.numVertices, m.faceSizes, m.faceVerts), options);
    refiner.refineUniform(3);
    const LimitStencilTable t = refiner.factorizedLimitStencils(3);
    const MeshNormalTable mesh = buildMeshNormalTable(refiner.faces(3));
    const std::vector<float> level3 = evaluateLevels(refiner, m.positions, 3)[3];
    std::vector<float> meshNormals(level3.size());
    CpuEvaluator::EvalMeshNormals(level3.data(), kPacked, meshNormals.data(), kPacked, mesh);
    Outputs o = makeOutputs(3, t.numStencils());
    const bool want[4] = {true, false, false, true};
    evalOn(Host::Cpu, m.positions, kPacked, o, want, t, nullptr);
    for (int i = 0; i < t.numStencils(); ++i) {
        const float* n = element(o, 3, i);
        const float* q = &meshNormals[3 * i];
        ASSERT_GT(n[0] * q[0] + n[1] * q[1] + n[2] * q[2], std::cos(0.1)) << "point " << i;  // within ~6 degrees
    }
}

TEST(LimitEvaluator, BadArgumentsGiveTheSameMessageOnBothEvaluators) {
    const LimitStencilTable t = randomLimitTable(10, 8, 1);
    LimitStencilTable shortOffsets = t;
    shortOffsets.offsets.pop_back();
    const CornerLevel L = cornerLevel(1);
    std::vector<float> src(64, 1.0f), out(256);
    const BufferDescriptor bad(0, 3, 2), four(0, 4, 4);
    float* o = out.data();
    struct Case {
        std::function<void(decltype(&CpuEvaluator::EvalLimitStencils))> call;
        const char* expected;
    };
    const float* s = src.data();
    const Case cases[] = {
        {[&](auto e) { e(s, bad, o, kPacked, o, kPacked, nullptr, kPacked, nullptr, kPacked, t, nullptr, 0, -1); },
         "EvalLimitStencils: source invalid BufferDescriptor"},
        {[&](auto e) { e(s, kPacked, o, kPacked, o, bad, nullptr, kPacked, nullptr, kPacked, t, nullptr, 0, -1); },
         "EvalLimitStencils: dU invalid BufferDescriptor"},
        {[&](auto e) { e(s, kPacked, o, kPacked, nullptr, kPacked, o, four, nullptr, kPacked, t, nullptr, 0, -1); },
         "EvalLimitStencils: source length 3 differs from dV length 4"},
        {[&](auto e) { e(s, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, t, nullptr, 0, -1); },
         "EvalLimitStencils: no output (position, dU, dV and normal all null)"},
        {[&](auto e) { e(s, four, o, four, nullptr, kPacked, nullptr, kPacked, o, kPacked, t, nullptr, 0, -1); },
         "EvalLimitStencils: normals need 3-float positions and normals (source length 4, normal length 3)"},
        {[&](auto e) { e(s, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, o, kPacked, t, &L.meshNormals, 0, -1); },
         "EvalLimitStencils: the fallback MeshNormalTable has"},
        {[&](auto e) { e(s, kPacked, o, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, t, nullptr, 4, 11); },
         "EvalLimitStencils: range [4, 11) outside the table's 10 stencils"},
        {[&](auto e) { e(nullptr, kPacked, o, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, t, nullptr, 0, -1); },
         "EvalLimitStencils: null source buffer"},
        {[&](auto e) { e(s, kPacked, o, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, shortOffsets, nullptr, 0, -1); },
         "EvalLimitStencils: inconsistent LimitStencilTable arrays (10 sizes, 9 offsets, 10 weight offsets)"},
    };
    for (const Case& c : cases) {
        const std::string cpu = messageOf([&] { c.call(&CpuEvaluator::EvalLimitStencils); });
        const std::string tbb = messageOf([&] { c.call(&TbbEvaluator::EvalLimitStencils); });
        EXPECT_EQ(cpu.rfind(c.expected, 0), 0u) << cpu;
        EXPECT_EQ(cpu, tbb);
    }
    // An empty range needs no source; an omitted output's descriptor is not read.
    EXPECT_NO_THROW(CpuEvaluator::EvalLimitStencils(nullptr, kPacked, o, kPacked, nullptr, bad, nullptr, bad, nullptr,
                                                    bad, t, nullptr, 5, 5));
}

}  // namespace
}  // namespace quadtri::test
