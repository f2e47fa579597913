// The analyzer and the evaluators from several std::threads at once: each thread's results must
// be bitwise those of the same work done serially. Refiners share no state, and a const Refiner
// is safe to read from any number of threads (its accessors and factorizedStencils build nothing
// shared). Checked by results rather than under ThreadSanitizer, which reports only false
// positives over an uninstrumented oneTBB.
#include <gtest/gtest.h>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#include "tests/test_support.h"

namespace quadtri {
namespace {

constexpr int kLevels = 4;
constexpr int kThreadsPerJob = 3;

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

bool sameTable(const StencilTable& a, const StencilTable& b) {
    return a.numSourceVertices == b.numSourceVertices && a.offsets == b.offsets && a.indices == b.indices &&
           a.weightOffsets == b.weightOffsets && sameBits(a.weights, b.weights);
}

std::vector<float> evaluate(const StencilTable& table, const std::vector<float>& control) {
    std::vector<float> out(3 * size_t(table.numStencils()));
    TbbEvaluator::EvalStencils(control.data(), BufferDescriptor(0, 3, 3), out.data(), BufferDescriptor(0, 3, 3), table);
    return out;
}

// Everything a refinement produces that a caller reads: tables, positions and face lists.
struct Result {
    std::vector<StencilTable> levelTables, factorizedTables;
    std::vector<std::vector<float>> positions;  // factorized evaluation of each level
    std::vector<std::vector<int>> faceVerts;
};

Result readAll(const Refiner& refiner, const std::vector<float>& control) {
    Result r;
    for (int L = 1; L <= refiner.maxLevel(); ++L) {
        r.levelTables.push_back(refiner.levelStencils(L));
        r.factorizedTables.push_back(refiner.factorizedStencils(L));
        r.positions.push_back(evaluate(r.factorizedTables.back(), control));
        r.faceVerts.push_back(test::cornersOf(refiner.faces(L)));
    }
    return r;
}

void expectSame(const Result& serial, const Result& threaded, const std::string& what) {
    ASSERT_EQ(serial.levelTables.size(), threaded.levelTables.size()) << what;
    for (size_t L = 0; L < serial.levelTables.size(); ++L) {
        EXPECT_TRUE(sameTable(serial.levelTables[L], threaded.levelTables[L])) << what << ", per-level table " << L + 1;
        EXPECT_TRUE(sameTable(serial.factorizedTables[L], threaded.factorizedTables[L])) << what << ", factorized table " << L + 1;
        EXPECT_TRUE(sameBits(serial.positions[L], threaded.positions[L])) << what << ", positions of level " << L + 1;
        EXPECT_EQ(serial.faceVerts[L], threaded.faceVerts[L]) << what << ", faces of level " << L + 1;
    }
}

struct Job {
    std::string mesh;
    Scheme scheme;
};

Result refineAndRead(const Job& job, const io::ObjMesh& mesh) {
    Options options = mesh.applyTags(Options());
    options.scheme = job.scheme;
    Refiner refiner(mesh.descriptor(), options);
    refiner.refineUniform(kLevels);
    return readAll(refiner, mesh.positions);
}

TEST(Concurrency, RefinersOnSeveralThreadsGiveTheSerialResults) {
    const std::vector<Job> jobs = {{"mixed/mixed_torus.obj", Scheme::SchaeferWarren},
                                   {"mixed/checker_cube.obj", Scheme::StamLoop},
                                   {"mixed/cylinder_capped_creased.obj", Scheme::CatmarkButterfly},
                                   {"osd/catmark_pyramid.obj", Scheme::Bilinear},
                                   {"osd/loop_cubes_semisharp.obj", Scheme::SchaeferWarren},
                                   {"osd/catmark_chaikin0.obj", Scheme::StamLoop}};
    std::vector<io::ObjMesh> meshes;
    std::vector<Result> serial;
    for (const Job& job : jobs) {
        meshes.push_back(io::readObj(test::meshPath(job.mesh)));
        serial.push_back(refineAndRead(job, meshes.back()));
    }
    // Every job on several threads at once, so that equal and different work overlap.
    std::vector<Result> threaded(jobs.size() * kThreadsPerJob);
    std::vector<std::thread> threads;
    for (size_t t = 0; t < threaded.size(); ++t)
        threads.emplace_back([&, t] { threaded[t] = refineAndRead(jobs[t % jobs.size()], meshes[t % jobs.size()]); });
    for (std::thread& thread : threads) thread.join();
    for (size_t t = 0; t < threaded.size(); ++t)
        expectSame(serial[t % jobs.size()], threaded[t], jobs[t % jobs.size()].mesh + " under " + toString(jobs[t % jobs.size()].scheme));
}

TEST(Concurrency, OneConstRefinerReadFromSeveralThreadsGivesTheSerialResults) {
    io::ObjMesh mesh = io::readObj(test::meshPath("mixed/mixed_torus.obj"));
    Refiner built(mesh.descriptor(), mesh.applyTags(Options()));
    built.refineUniform(kLevels);
    const Refiner& refiner = built;
    const Result serial = readAll(refiner, mesh.positions);

    std::vector<Result> threaded(8);
    std::vector<std::thread> threads;
    for (Result& result : threaded) threads.emplace_back([&] { result = readAll(refiner, mesh.positions); });
    for (std::thread& thread : threads) thread.join();
    for (size_t t = 0; t < threaded.size(); ++t) expectSame(serial, threaded[t], "thread " + std::to_string(t));
}

// Level 0's per-edge and per-vertex passes (flags, fans, boundary tags) run on oneTBB's threads:
// one thread and four give the same arrays, on a grid large enough for many tasks that has every
// kind of edge and vertex they tag (boundary, corners, a hole, a fin on a non-manifold edge, a
// bow tie's pinched vertex, triangles beside quads, creases, an isolated vertex).
TEST(Concurrency, LevelZeroIsTheSameOnAnyNumberOfThreads) {
    constexpr int n = 120;  // n x n quads: 14 641 vertices, 28 800 edges
    auto at = [](int i, int j) { return i * (n + 1) + j; };
    std::vector<int> sizes, verts;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            if ((i + j) % 7 == 0) {  // some quads split: seams
                sizes.insert(sizes.end(), {3, 3});
                verts.insert(verts.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            } else {
                sizes.push_back(4);
                verts.insert(verts.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    const int fin = (n + 1) * (n + 1), tie = fin + 1, isolated = fin + 5;
    sizes.push_back(3);  // a fin on the edge (60, 60)-(61, 60): three faces there
    verts.insert(verts.end(), {at(60, 60), at(61, 60), fin});
    sizes.push_back(6);  // a bow tie hanging off a corner of the grid
    verts.insert(verts.end(), {at(0, 0), tie, tie + 1, at(0, 0), tie + 2, tie + 3});
    const std::vector<int> creases = {at(10, 10), at(10, 11), at(10, 11), at(10, 12)};
    const std::vector<float> creaseWeights = {2.0f, 10.0f}, cornerWeights = {3.0f};
    const std::vector<int> corners = {at(30, 30)}, holes = {500, 501, 9000};
    TopologyDescriptor desc;
    desc.numVertices = isolated + 1;
    desc.numFaces = int(sizes.size());
    desc.numVertsPerFace = sizes.data();
    desc.faceVertIndices = verts.data();
    desc.numCreases = 2;
    desc.creaseVertexPairs = creases.data();
    desc.creaseWeights = creaseWeights.data();
    desc.numCorners = 1;
    desc.cornerVertexIndices = corners.data();
    desc.cornerWeights = cornerWeights.data();
    desc.numHoles = int(holes.size());
    desc.holeIndices = holes.data();
    for (const BoundaryInterpolation boundary :
         {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner, BoundaryInterpolation::None}) {
        Options options;
        options.scheme = Scheme::CatmullClark;
        options.boundary = boundary;
        std::unique_ptr<Refiner> serial, threaded;
        {
            const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
            serial = std::make_unique<Refiner>(desc, options);
        }
        tbb::task_arena(4).execute([&] { threaded = std::make_unique<Refiner>(desc, options); });
        const Topology &a = serial->level(0), &b = threaded->level(0);
        const std::string where = std::string("boundary ") + toString(boundary);
        EXPECT_EQ(a.numVertices, b.numVertices) << where;
        EXPECT_EQ(a.faceOffsets, b.faceOffsets) << where;
        EXPECT_EQ(a.faceVerts, b.faceVerts) << where;
        EXPECT_EQ(a.faceEdges, b.faceEdges) << where;
        EXPECT_EQ(a.faceHole, b.faceHole) << where;
        EXPECT_EQ(a.edgeVerts, b.edgeVerts) << where;
        EXPECT_EQ(a.edgeFaceOffsets, b.edgeFaceOffsets) << where;
        EXPECT_EQ(a.edgeFaces, b.edgeFaces) << where;
        EXPECT_EQ(a.edgeSharpness, b.edgeSharpness) << where;
        EXPECT_EQ(a.edgeFlags, b.edgeFlags) << where;
        EXPECT_EQ(a.vertFaceOffsets, b.vertFaceOffsets) << where;
        EXPECT_EQ(a.vertFaces, b.vertFaces) << where;
        EXPECT_EQ(a.vertEdgeOffsets, b.vertEdgeOffsets) << where;
        EXPECT_EQ(a.vertEdges, b.vertEdges) << where;
        EXPECT_EQ(a.vertSharpness, b.vertSharpness) << where;
        EXPECT_EQ(a.vertFlags, b.vertFlags) << where;
        // The grid has what the passes tag: a test that could pass on an untagged level says so.
        auto count = [](const std::vector<uint8_t>& flags, uint8_t bit) {
            return std::count_if(flags.begin(), flags.end(), [bit](uint8_t f) { return (f & bit) != 0; });
        };
        EXPECT_GT(count(a.edgeFlags, kEdgeBoundary), 4 * n) << where;
        EXPECT_GE(count(a.edgeFlags, kEdgeNonManifold), 1) << where;
        EXPECT_GT(count(a.edgeFlags, kEdgeSeam), n) << where;
        EXPECT_GE(count(a.vertFlags, kVertexCorner), 3) << where;
        EXPECT_GE(count(a.vertFlags, kVertexNonManifold), 1) << where;
        EXPECT_EQ(a.vertSharpness[std::size_t(isolated)], kInfiniteSharpness) << where;
    }
}

}  // namespace
}  // namespace quadtri
