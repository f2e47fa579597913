// The analyzer and the evaluators from several std::threads at once: each thread's results must
// be bitwise those of the same work done serially. Refiners share no state, and a const Refiner
// is safe to read from any number of threads (its accessors and factorizedStencils build nothing
// shared). Checked by results rather than under ThreadSanitizer, which reports only false
// positives over an uninstrumented oneTBB.
#include <gtest/gtest.h>

#include <cstring>
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

}  // namespace
}  // namespace quadtri
