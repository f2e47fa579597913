#include "tests/fuzz/fuzz_oracles.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>

namespace quadtri::fuzz {

namespace {

// An output whose bound (sum_k |w_k| |x_k|) is below this cannot overflow in float: the margin
// covers the rounding of the partial sums and of the levels before it.
constexpr double kFiniteBound = FLT_MAX / 4.0;

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", x);
    return text;
}

std::string tableName(const char* kind, int level) { return std::string(kind) + " table of level " + std::to_string(level); }

void checkFaces(const LevelFaces& faces, int level) {
    std::string name = "level " + std::to_string(level);
    if (faces.offsets()[0] != 0 || faces.offsets()[faces.numFaces()] != faces.numCorners())
        fail(name + ": face offsets do not span the face vertices");
    if (faces.numFaces() > 0 && faces.holes() == nullptr) fail(name + ": no hole flags");
    for (int f = 0; f < faces.numFaces(); ++f)
        if (faces.faceSize(f) < 3)
            fail(name + ": face " + std::to_string(f) + " has " + std::to_string(faces.faceSize(f)) + " corners");
    for (int i = 0; i < faces.numCorners(); ++i)
        if (faces.vertices()[i] < 0 || faces.vertices()[i] >= faces.numVertices())
            fail(name + ": face vertex " + std::to_string(faces.vertices()[i]) + " out of range");
}

void checkTable(const StencilTable& t, int numSources, int numStencils, const std::string& name) {
    if (t.numSourceVertices != numSources)
        fail(name + ": numSourceVertices " + std::to_string(t.numSourceVertices) + ", expected " + std::to_string(numSources));
    if (t.numStencils() != numStencils)
        fail(name + ": " + std::to_string(t.numStencils()) + " stencils, expected " + std::to_string(numStencils));
    if (t.offsets.size() != size_t(numStencils) + 1 || t.offsets[0] != 0 || t.offsets.back() != int(t.indices.size()))
        fail(name + ": offsets do not span the indices");
    for (int i = 0; i < numStencils; ++i) {
        std::string at = name + ", stencil " + std::to_string(i);
        if (t.size(i) < 0) fail(at + ": offsets decrease");
        if (t.weightOffsets[i] < 0 || size_t(t.weightOffsets[i]) + size_t(t.size(i)) > t.weights.size())
            fail(at + ": weights outside the pool");
        double sum = 0;
        for (int k = 0; k < t.size(i); ++k) {
            int source = t.indices[t.offsets[i] + k];
            if (source < 0 || source >= numSources) fail(at + ": source " + std::to_string(source) + " out of range");
            float w = t.weightsOf(i)[k];
            if (!std::isfinite(w)) fail(at + ": weight " + number(w));
            sum += w;
        }
        if (!(std::abs(sum - 1.0) <= 1e-5)) fail(at + ": weights sum to " + number(sum));
    }
}

// Stencil outputs over `src` (3 floats per source) from CpuEvaluator; TbbEvaluator must agree bitwise.
std::vector<float> evaluate(const StencilTable& t, const std::vector<float>& src, const std::string& name) {
    BufferDescriptor desc(0, 3, 3);
    std::vector<float> cpu(3 * size_t(t.numStencils())), tbb(cpu.size());
    CpuEvaluator::EvalStencils(src.data(), desc, cpu.data(), desc, t);
    TbbEvaluator::EvalStencils(src.data(), desc, tbb.data(), desc, t);
    if (!cpu.empty() && std::memcmp(cpu.data(), tbb.data(), cpu.size() * sizeof(float)) != 0)
        fail(name + ": TbbEvaluator's result differs from CpuEvaluator's");
    return cpu;
}

// Per vertex, the largest |coordinate|: where a bound on the outputs starts.
std::vector<double> magnitudes(const std::vector<float>& xyz) {
    std::vector<double> m(xyz.size() / 3);
    for (size_t v = 0; v < m.size(); ++v)
        m[v] = std::max({std::abs(double(xyz[3 * v])), std::abs(double(xyz[3 * v + 1])), std::abs(double(xyz[3 * v + 2]))});
    return m;
}

// Per stencil, sum_k |w_k| bound[source_k]: no coordinate of its exact output is larger.
std::vector<double> propagate(const StencilTable& t, const std::vector<double>& bound) {
    std::vector<double> out(t.numStencils());
    for (int i = 0; i < t.numStencils(); ++i)
        for (int k = 0; k < t.size(i); ++k) out[i] += std::abs(double(t.weightsOf(i)[k])) * bound[t.indices[t.offsets[i] + k]];
    return out;
}

// Float rounding of a stencil sum of `size` terms (and of the levels or weights before it),
// relative to its bound, with room for subnormal results.
double tolerance(double bound, int size) { return (1e-5 + 4.0 * FLT_EPSILON * size) * bound + size * 1e-44; }

void checkFinite(const std::vector<float>& out, const std::vector<double>& bound, const std::string& name) {
    for (size_t i = 0; i < bound.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (bound[i] < kFiniteBound && !std::isfinite(out[3 * i + c]))
                fail(name + ", stencil " + std::to_string(i) + ": output " + number(out[3 * i + c]) + " although its bound is " +
                     number(bound[i]));
}

// Affine invariance: moving every control vertex by t moves every output by t.
void checkTranslation(const StencilTable& t, const std::vector<float>& control, const std::vector<float>& out,
                      const std::vector<double>& bound, const std::string& name) {
    std::vector<double> m = magnitudes(control);
    double largest = m.empty() ? 0.0 : *std::max_element(m.begin(), m.end());
    // A power of two of the data's size, so that t itself is exact in float.
    double scale = std::exp2(std::ceil(std::log2(std::max(1.0, largest))));
    const double shift[3] = {0.5 * scale, -0.25 * scale, 0.75 * scale};
    std::vector<float> moved(control.size());
    for (size_t i = 0; i < control.size(); ++i) moved[i] = float(double(control[i]) + shift[i % 3]);
    std::vector<float> movedOut = evaluate(t, moved, name + " (translated)");
    std::vector<double> movedBound = propagate(t, magnitudes(moved));
    for (int i = 0; i < t.numStencils(); ++i) {
        if (!(bound[i] < kFiniteBound && movedBound[i] < kFiniteBound)) continue;
        for (int c = 0; c < 3; ++c) {
            double expected = double(out[3 * i + c]) + shift[c];
            if (!(std::abs(movedOut[3 * i + c] - expected) <= tolerance(bound[i] + movedBound[i], t.size(i))))
                fail(name + ", stencil " + std::to_string(i) + ": translating the control by " + number(shift[c]) +
                     " moves coordinate " + std::to_string(c) + " from " + number(out[3 * i + c]) + " to " +
                     number(movedOut[3 * i + c]));
        }
    }
}

}  // namespace

void fail(const std::string& what) {
    std::fprintf(stderr, "fuzz oracle failed: %s\n", what.c_str());
    std::abort();
}

void expectMessage(const std::exception& error) {
    if (std::strlen(error.what()) == 0) fail("an error without a message");
}

void checkRefinement(const Refiner& refiner, const std::vector<float>& control) {
    for (const TopologyDiagnostic& w : refiner.warnings())
        if (w.message().empty()) fail("a warning without a message");
    const int numControl = refiner.faces(0).numVertices();
    if (control.size() != 3 * size_t(numControl)) fail("level 0 does not have one vertex per control position");
    checkFaces(refiner.faces(0), 0);
    const std::vector<double> controlBound = magnitudes(control);
    std::vector<float> positions = control;  // of level L, evaluated level by level
    std::vector<double> bound = controlBound;
    for (int L = 1; L <= refiner.maxLevel(); ++L) {
        const LevelFaces child = refiner.faces(L);
        checkFaces(child, L);

        std::string perLevel = tableName("per-level", L);
        const StencilTable& table = refiner.levelStencils(L);
        checkTable(table, refiner.faces(L - 1).numVertices(), child.numVertices(), perLevel);
        positions = evaluate(table, positions, perLevel);
        bound = propagate(table, bound);
        checkFinite(positions, bound, perLevel);

        std::string factorized = tableName("factorized", L);
        StencilTable direct;
        try {
            direct = refiner.factorizedStencils(L);
        } catch (const MemoryBudgetError& e) {  // a clear refusal; deeper levels need more
            expectMessage(e);
            return;
        }
        checkTable(direct, numControl, child.numVertices(), factorized);
        std::vector<float> out = evaluate(direct, control, factorized);
        std::vector<double> directBound = propagate(direct, controlBound);
        checkFinite(out, directBound, factorized);
        checkTranslation(direct, control, out, directBound, factorized);

        // Level by level and factorized are the same linear map, rounded differently.
        for (int i = 0; i < direct.numStencils(); ++i) {
            if (!(bound[i] < kFiniteBound)) continue;
            for (int c = 0; c < 3; ++c)
                if (!(std::abs(double(out[3 * i + c]) - positions[3 * i + c]) <= tolerance(bound[i], direct.size(i))))
                    fail(factorized + ", stencil " + std::to_string(i) + ": coordinate " + std::to_string(c) + " is " +
                         number(out[3 * i + c]) + ", level by level " + number(positions[3 * i + c]));
        }
    }
}

}  // namespace quadtri::fuzz
