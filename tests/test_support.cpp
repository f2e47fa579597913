#include "tests/test_support.h"

#include <stdexcept>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include <quadtri/osd/cpu_evaluator.h>
#include "far/topology/refine_topology.h"
#include "far/tables/level_stencils.h"
#include "far/schemes/scheme.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri::test {

std::string meshPath(const std::string& relative) { return std::string(QUADTRI_TEST_MESHES) + "/" + relative; }

RefinedMesh refineMesh(const std::string& relative, int maxLevel, Options options) {
    RefinedMesh r;
    r.mesh = io::readObj(meshPath(relative));
    r.options = r.mesh.applyTags(options);
    r.refiner = std::make_unique<Refiner>(r.mesh.descriptor(), r.options);
    r.refiner->refineUniform(maxLevel, TopologyDetail::Full);  // tests read every level's connectivity
    r.positions = evaluateLevels(*r.refiner, r.mesh.positions, 3);
    return r;
}

namespace {

// `control` carried through tableOf(1 .. maxLevel()) with CpuEvaluator, every level kept.
template <class TableOf>
std::vector<std::vector<float>> evaluateThrough(const Refiner& refiner, const std::vector<float>& control, int width,
                                                const TableOf& tableOf) {
    std::vector<std::vector<float>> levels{control};
    for (int L = 1; L <= refiner.maxLevel(); ++L) {
        const StencilTable& table = tableOf(L);
        std::vector<float> out(size_t(table.numStencils()) * width);
        CpuEvaluator::EvalStencils(levels.back().data(), BufferDescriptor(0, width, width), out.data(),
                                   BufferDescriptor(0, width, width), table);
        levels.push_back(std::move(out));
    }
    return levels;
}

}  // namespace

std::vector<std::vector<float>> evaluateLevels(const Refiner& refiner, const std::vector<float>& control, int width) {
    return evaluateThrough(refiner, control, width, [&](int L) -> const StencilTable& { return refiner.levelStencils(L); });
}

std::vector<std::vector<float>> evaluateChannelLevels(const Refiner& refiner, int channel,
                                                      const std::vector<float>& control, int width) {
    return evaluateThrough(refiner, control, width,
                           [&](int L) -> const StencilTable& { return refiner.fvarLevelStencils(channel, L); });
}

double boundingBoxDiagonal(const std::vector<float>& xyz) {
    double lo[3], hi[3];
    for (int c = 0; c < 3; ++c) {
        lo[c] = std::numeric_limits<double>::max();
        hi[c] = -std::numeric_limits<double>::max();
    }
    for (size_t i = 0; i + 2 < xyz.size(); i += 3)
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], double(xyz[i + c]));
            hi[c] = std::max(hi[c], double(xyz[i + c]));
        }
    double d2 = 0;
    for (int c = 0; c < 3; ++c) d2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    return std::sqrt(d2);
}

double stencilWeightSum(const StencilTable& table, int i) {
    double sum = 0;
    for (int k = 0; k < table.size(i); ++k) sum += table.weightsOf(i)[k];
    return sum;
}

std::vector<std::string> allMeshes() {
    std::vector<std::string> names;
    for (const char* dir : {"osd", "mixed"})
        for (const auto& entry : std::filesystem::directory_iterator(meshPath(dir)))
            if (entry.path().extension() == ".obj") names.push_back(std::string(dir) + "/" + entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string testNameOf(std::string text) {
    for (char& c : text)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return text;
}

StencilTable handCheckedTable() {
    StencilTable t;
    t.numSourceVertices = 4;
    t.offsets = {0, 2, 3, 7};
    t.indices = {0, 1, 3, 0, 1, 2, 3};
    // Pool order differs from stencil order, so evaluators must follow weightOffsets.
    t.weightOffsets = {4, 6, 0};
    t.weights = {0.25f, 0.25f, 0.25f, 0.25f, 0.5f, 0.5f, 1.0f};
    return t;
}

TopologyDescriptor descriptorOf(int numVertices, const std::vector<int>& sizes, const std::vector<int>& verts) {
    TopologyDescriptor d;
    d.numVertices = numVertices;
    d.numFaces = int(sizes.size());
    d.numVertsPerFace = sizes.data();
    d.faceVertIndices = verts.data();
    return d;
}

TopologyDescriptor withOneCrease(TopologyDescriptor desc) {
    static const int pair[2] = {0, 1};
    static const float sharpness = 2.0f;
    desc.numCreases = 1;
    desc.creaseVertexPairs = pair;
    desc.creaseWeights = &sharpness;
    return desc;
}

void expectShortCutEqualsTheRules(const std::string& mesh, const Options& options) {
    const io::ObjMesh m = io::readObj(meshPath(mesh));
    Refiner refiner(m.descriptor(), m.applyTags(options));
    refiner.refineUniform(3, TopologyDetail::Full);
    for (int L = 1; L <= 3; ++L) {
        const std::string where = mesh + " " + toString(options.scheme) + " level " + std::to_string(L);
        const Topology& parent = refiner.level(L - 1);
        const ChildNumbering numbering = numberChildren(parent, rulesOf(options.scheme).triangleSplit());
        const StencilTable rules = toFloatTable(buildLevelStencils<StencilTableD>(parent, numbering, refiner.options()));
        const StencilTable& built = refiner.levelStencils(L);
        EXPECT_EQ(built.offsets, rules.offsets) << where;
        EXPECT_EQ(built.indices, rules.indices) << where;
        EXPECT_EQ(built.weightOffsets, rules.weightOffsets) << where;
        EXPECT_EQ(built.weights, rules.weights) << where;
    }
}

std::string messageOf(const std::function<void()>& call) {
    try {
        call();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no exception)";
}

}  // namespace quadtri::test
