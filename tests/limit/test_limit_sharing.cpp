// The float limit table's layout (far/limit_stencil_table.h): every stencil's run of sources is
// strictly ascending, in range and stored once however many stencils read it; on a regular torus
// there is one run per control face, edge and vertex; and the shared table evaluates as the
// unshared double table it was made from.
#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "bench/meshes/torus.h"
#include "far/limit/limit_ring.h"
#include "far/limit/limit_table.h"
#include "far/topology/refine_topology.h"
#include "far/schemes/scheme.h"
#include "far/internal/stencil_table_double.h"
#include "tests/limit/limit_support.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

// Layout invariants, and that no two runs in the pool are equal (every run stored once).
void expectSharedLayout(const LimitStencilTable& t, const std::string& where) {
    const int n = t.numStencils();
    ASSERT_EQ(t.offsets.size(), std::size_t(n)) << where;
    ASSERT_EQ(t.weightOffsets.size(), std::size_t(n)) << where;
    std::map<std::vector<int>, int> runs;  // run -> its offset
    std::size_t entries = 0;
    for (int i = 0; i < n; ++i) {
        const int size = t.size(i), first = t.offsets[i];
        ASSERT_TRUE(size > 0 && first >= 0 && std::size_t(first) + size <= t.indices.size()) << where << " stencil " << i;
        ASSERT_LE(std::size_t(t.weightOffsets[i]) + 3 * std::size_t(size), t.weights.size()) << where << " stencil " << i;
        const int* s = t.sourcesOf(i);
        ASSERT_TRUE(s[0] >= 0 && s[size - 1] < t.numSourceVertices) << where << " stencil " << i;
        for (int k = 1; k < size; ++k) ASSERT_LT(s[k - 1], s[k]) << where << " stencil " << i << " entry " << k;
        const auto [at, fresh] = runs.emplace(std::vector<int>(s, s + size), first);
        EXPECT_TRUE(fresh || at->second == first) << where << ": stencils " << i << " and another read equal runs at "
                                                  << first << " and " << at->second;
        entries += std::size_t(size);
    }
    EXPECT_EQ(t.numEntries(), entries) << where;
    std::size_t pooled = 0;
    for (const auto& [run, offset] : runs) pooled += run.size();
    EXPECT_EQ(t.indices.size(), pooled) << where << ": the pool holds runs no stencil reads";
}

TEST(LimitSharing, RunsAscendInRangeAndAreStoredOnce) {
    for (const auto& [mesh, scheme] : {std::pair{"osd/catmark_pawn.obj", Scheme::CatmullClark},
                                       std::pair{"osd/catmark_nonquads.obj", Scheme::CatmullClark},
                                       std::pair{"osd/loop_icos_infsharp.obj", Scheme::Loop},
                                       std::pair{"osd/catmark_torus_creases0.obj", Scheme::CatmullClark}}) {
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineMesh(mesh, 2, options);
        for (int L = 0; L <= 2; ++L) {
            const std::string where = std::string(mesh) + " level " + std::to_string(L);
            expectSharedLayout(r.refiner->limitStencils(L), where);
            expectSharedLayout(r.refiner->factorizedLimitStencils(L), where + " factorized");
        }
    }
}

// On a regular closed mesh every limit point inside one control face reads that face's
// neighbourhood, the control vertices whose basis functions do not vanish on it: its 4x4 block
// of 16 under Catmull-Clark, 12 under Loop (the three-direction box spline); every point on one
// control edge the 12 or 10 of its two faces that do not vanish on it, and a control vertex its 9
// or 7 (its 1-ring). So the factorized table holds exactly one run per control face, edge and
// vertex, and at level 3 stores far fewer indices than it evaluates.
TEST(LimitSharing, RegularTorusHasOneRunPerControlFaceEdgeAndVertex) {
    struct Case {
        bench::TorusFaces faces;
        Scheme scheme;
        int facesPerVertex, faceRun, edgeRun, vertexRun;
    };
    for (const Case& c : {Case{bench::TorusFaces::Quads, Scheme::CatmullClark, 1, 16, 12, 9},
                          Case{bench::TorusFaces::Triangles, Scheme::Loop, 2, 12, 10, 7}}) {
        const bench::ControlMesh m = bench::makeTorus(16, c.faces);
        Options options;
        options.scheme = c.scheme;
        Refiner refiner(descriptorOf(m.numVertices, m.faceSizes, m.faceVerts), options);
        refiner.refineUniform(3);
        const LimitStencilTable t = refiner.factorizedLimitStencils(3);
        expectSharedLayout(t, m.name);
        std::map<int, int> runs;  // offset -> size, one per distinct run
        for (int i = 0; i < t.numStencils(); ++i) runs[t.offsets[i]] = t.size(i);
        std::map<int, int> runsOfSize;
        for (const auto& [offset, size] : runs) ++runsOfSize[size];
        const int V = m.numVertices, F = c.facesPerVertex * V, E = V + F;  // Euler: V - E + F = 0
        EXPECT_EQ(runsOfSize, (std::map<int, int>{{c.faceRun, F}, {c.edgeRun, E}, {c.vertexRun, V}})) << m.name;
        EXPECT_LT(4 * t.indices.size(), t.numEntries()) << m.name;
    }
}

// Level L's limit stencils over the control vertices in double, unshared and unsorted: the
// level's masks composed over the factorized stencils of level L.
LimitStencilTableD unsharedLimit(const Refiner& refiner, int L) {
    const TriangleSplit split = rulesOf(refiner.options().scheme).triangleSplit();
    RingStarts starts(refiner.level(0));
    for (int l = 1; l <= L; ++l) {
        const Topology& parent = refiner.level(l - 1);
        starts.descend(parent, numberChildren(parent, split), refiner.level(l).numVertices);
    }
    LimitStencilTableD limit = buildLimitStencils(refiner.level(L), refiner.options(), &starts);
    if (L == 0) return limit;
    return composeLimitStencils(limit, toDoubleTable(refiner.factorizedStencils(L)));
}

// The double table applied in double, entry by entry in its own order.
LimitData applyDouble(const LimitStencilTableD& t, const std::vector<float>& xyz) {
    LimitData out;
    for (int i = 0; i < t.numStencils(); ++i) {
        Vec3 p{0, 0, 0}, u{0, 0, 0}, v{0, 0, 0};
        for (int k = t.offsets[i]; k < t.offsets[i] + t.sizes[i]; ++k) {
            const double* w = t.weights.data() + 3 * std::size_t(k);
            const float* x = xyz.data() + 3 * std::size_t(t.indices[k]);
            for (int c = 0; c < 3; ++c) p[c] += w[0] * x[c], u[c] += w[1] * x[c], v[c] += w[2] * x[c];
        }
        out.position.push_back(p);
        out.du.push_back(u);
        out.dv.push_back(v);
    }
    return out;
}

TEST(LimitSharing, SharedTableEvaluatesAsTheUnsharedDoubleTable) {
    for (const auto& [mesh, scheme] : {std::pair{"osd/catmark_torus_creases0.obj", Scheme::CatmullClark},
                                       std::pair{"osd/loop_icos_infsharp.obj", Scheme::Loop},
                                       std::pair{"osd/catmark_nonquads.obj", Scheme::CatmullClark}}) {
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineMesh(mesh, 3, options);
        const double diagonal = boundingBoxDiagonal(r.mesh.positions);
        for (int L = 0; L <= 3; ++L) {
            const LimitStencilTableD unshared = unsharedLimit(*r.refiner, L);
            const LimitStencilTable shared = toFloatTable(unshared);
            expectSharedLayout(shared, std::string(mesh) + " level " + std::to_string(L));
            const LimitData a = applyLimit(shared, r.mesh.positions), b = applyDouble(unshared, r.mesh.positions);
            ASSERT_EQ(a.position.size(), b.position.size());
            for (std::size_t v = 0; v < a.position.size(); ++v) {
                EXPECT_LE(distance(a.position[v], b.position[v]), 1e-6 * diagonal) << mesh << " level " << L;
                EXPECT_LE(distance(a.du[v], b.du[v]), 1e-6 * diagonal + 1e-5 * norm(b.du[v])) << mesh << " level " << L;
                EXPECT_LE(distance(a.dv[v], b.dv[v]), 1e-6 * diagonal + 1e-5 * norm(b.dv[v])) << mesh << " level " << L;
            }
        }
    }
}

// The float tables made in parts (composed or masked, sorted and rounded on the threads, interned
// in stencil order) are the double tables rounded by toFloatTable, bit for bit, pools and all, on
// one thread and on four (several waves of parts): the composition, the masks of a level, and
// toFloatTable itself.
TEST(LimitSharing, FloatTablesInPartsAreTheDoubleOnesRounded) {
    for (const auto& [mesh, scheme, L] : {std::tuple{"osd/catmark_pawn.obj", Scheme::CatmullClark, 3},
                                          std::tuple{"osd/loop_icos_infsharp.obj", Scheme::Loop, 3},
                                          std::tuple{"mixed/mixed_torus.obj", Scheme::SchaeferWarren, 2}}) {
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineMesh(mesh, L, options);
        const TriangleSplit split = rulesOf(scheme).triangleSplit();
        RingStarts starts(r.refiner->level(0));
        for (int l = 1; l <= L; ++l) {
            const Topology& parent = r.refiner->level(l - 1);
            starts.descend(parent, numberChildren(parent, split), r.refiner->level(l).numVertices);
        }
        const Topology last = refineTopology(r.refiner->level(L - 1),
                                             numberChildren(r.refiner->level(L - 1), split), options.creaseMethod,
                                             TopologyDetail::Full);
        const LimitStencilTableD limit = buildLimitStencils(last, options, &starts);
        const StencilTableD inner = toDoubleTable(r.refiner->factorizedStencils(L));
        const LimitStencilTable want = toFloatTable(composeLimitStencils(limit, inner));
        const std::string where = std::string(mesh) + " level " + std::to_string(L);
        LimitStencilTable serial, threaded;
        tbb::task_arena(1).execute([&] { serial = composeLimitStencilsToFloat(limit, inner); });
        tbb::task_arena(4).execute([&] { threaded = composeLimitStencilsToFloat(limit, inner); });
        expectSameLimitTable(serial, want, where + ", one thread");
        expectSameLimitTable(threaded, want, where + ", four threads");
        const LimitStencilTable wantMasks = toFloatTable(limit);
        LimitStencilTable masksSerial, masksThreaded, roundedSerial;
        tbb::task_arena(1).execute([&] {
            masksSerial = buildLimitStencilsToFloat(last, options, &starts);
            roundedSerial = toFloatTable(limit);
        });
        tbb::task_arena(4).execute([&] { masksThreaded = buildLimitStencilsToFloat(last, options, &starts); });
        expectSameLimitTable(masksSerial, wantMasks, where + " masks, one thread");
        expectSameLimitTable(masksThreaded, wantMasks, where + " masks, four threads");
        expectSameLimitTable(roundedSerial, wantMasks, where + " rounded on one thread");
        if (std::string(mesh) == "osd/catmark_pawn.obj") {
            EXPECT_GT(limit.numStencils(), 4 * 4 * 2048) << "one wave only";
        }
        EXPECT_THROW(composeLimitStencilsToFloat(limit, inner, 3 * sizeof(int) * std::size_t(limit.numStencils()) + 64),
                     std::length_error)
            << where;
    }
}

// Stencils listing the same sources in another order, or one source twice, read one run; a
// source listed twice becomes one entry whose weights are the sum (in double, then rounded).
TEST(LimitSharing, PermutedAndRepeatedSourcesShareOneRun) {
    LimitStencilTableD d;
    d.numSourceVertices = 10;
    const std::vector<std::vector<int>> sources = {{5, 2, 9}, {9, 5, 2}, {2, 5, 9, 5}, {2, 5}};
    for (const std::vector<int>& s : sources) {
        d.offsets.push_back(int(d.indices.size()));
        d.sizes.push_back(int(s.size()));
        for (int source : s) {
            d.indices.push_back(source);
            const double w = 0.1 * double(d.indices.size());  // distinct per entry
            d.weights.insert(d.weights.end(), {w, -w, 1 + w});
        }
    }
    const LimitStencilTable t = toFloatTable(d);
    EXPECT_EQ(t.indices, (std::vector<int>{2, 5, 9, 2, 5}));
    EXPECT_EQ(t.offsets, (std::vector<int>{0, 0, 0, 3}));
    EXPECT_EQ(t.sizes, (std::vector<int>{3, 3, 3, 2}));
    for (int i = 0; i < t.numStencils(); ++i)
        for (int k = 0; k < t.size(i); ++k)
            for (int c = 0; c < 3; ++c) {
                double expected = 0;
                for (int e = d.offsets[i]; e < d.offsets[i] + d.sizes[i]; ++e)
                    if (d.indices[e] == t.sourcesOf(i)[k]) expected += d.weights[3 * std::size_t(e) + c];
                EXPECT_EQ(t.weightsOf(i)[3 * k + c], float(expected)) << "stencil " << i << " entry " << k;
            }
}

}  // namespace
}  // namespace quadtri::test
