// The composition of stencil tables (far/tables/compose_stencils.cpp) against a straightforward one
// kept here: each composed stencil a list of (source, sum) merged by linear search, sources in
// the order first reached, each sum added up in the order of the outer entries and then of the
// inner ones. The library's dense scatter row does the same arithmetic in the same order, so every
// table must come out bitwise equal: double tables, float tables with their weight pools, and
// the factorized tables of the Refiner for positions, face-varying values and varying data.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "bench/meshes/sphere.h"
#include "bench/meshes/torus.h"
#include "far/tables/regular_patches.h"
#include "far/schemes/scheme.h"
#include "far/internal/stencil_table_double.h"
#include "far/tables/varying_table.h"
#include "tests/limit/limit_support.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

StencilTableD referenceCompose(const StencilTableD& outer, const StencilTableD& inner) {
    StencilTableD out;
    out.numSourceVertices = inner.numSourceVertices;
    for (std::size_t i = 0; i < outer.sizes.size(); ++i) {
        std::vector<std::pair<int, double>> row;
        for (int k = outer.offsets[i]; k < outer.offsets[i] + outer.sizes[i]; ++k) {
            const int j = outer.indices[std::size_t(k)];
            for (int m = inner.offsets[std::size_t(j)]; m < inner.offsets[std::size_t(j)] + inner.sizes[std::size_t(j)]; ++m) {
                const int source = inner.indices[std::size_t(m)];
                const double term = outer.weights[std::size_t(k)] * inner.weights[std::size_t(m)];
                std::size_t at = 0;
                while (at < row.size() && row[at].first != source) ++at;
                if (at == row.size()) row.push_back({source, term});
                else row[at].second += term;
            }
        }
        out.offsets.push_back(int(out.indices.size()));
        out.sizes.push_back(int(row.size()));
        for (const auto& [source, sum] : row) {
            out.indices.push_back(source);
            out.weights.push_back(sum);
        }
    }
    return out;
}

// Bitwise: -0.0 and 0.0 apart.
bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}
bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

void expectSame(const StencilTableD& got, const StencilTableD& want, const std::string& where) {
    EXPECT_EQ(got.numSourceVertices, want.numSourceVertices) << where;
    EXPECT_EQ(got.sizes, want.sizes) << where;
    EXPECT_EQ(got.offsets, want.offsets) << where;
    EXPECT_EQ(got.indices, want.indices) << where;
    EXPECT_TRUE(sameBits(got.weights, want.weights)) << where << ": weights differ";
}

void expectSame(const StencilTable& got, const StencilTable& want, const std::string& where) {
    EXPECT_EQ(got.numSourceVertices, want.numSourceVertices) << where;
    EXPECT_EQ(got.offsets, want.offsets) << where;
    EXPECT_EQ(got.indices, want.indices) << where;
    EXPECT_EQ(got.weightOffsets, want.weightOffsets) << where;
    EXPECT_TRUE(sameBits(got.weights, want.weights)) << where << ": weight pools differ";
}

// A factorized table as the Refiner makes it: the children of regular control faces come from
// templates (far/tables/regular_patches.h), so their entries may come in another order and
// their weights may differ from the reference's by the rounding of a sum added up in another
// order (at most an ulp or two of float); every other stencil is the reference's bitwise.
void expectClose(const StencilTable& got, const StencilTable& want, const std::string& where) {
    ASSERT_EQ(got.numSourceVertices, want.numSourceVertices) << where;
    ASSERT_EQ(got.offsets, want.offsets) << where;
    for (int i = 0; i < want.numStencils(); ++i) {
        std::vector<std::pair<int, float>> a, b;
        for (int k = got.offsets[i]; k < got.offsets[i + 1]; ++k)
            a.emplace_back(got.indices[k], got.weights[std::size_t(got.weightOffsets[i] + k - got.offsets[i])]);
        for (int k = want.offsets[i]; k < want.offsets[i + 1]; ++k)
            b.emplace_back(want.indices[k], want.weights[std::size_t(want.weightOffsets[i] + k - want.offsets[i])]);
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        for (std::size_t k = 0; k < b.size(); ++k) {
            ASSERT_EQ(a[k].first, b[k].first) << where << ": stencil " << i << " reads other sources";
            ASSERT_LE(std::fabs(a[k].second - b[k].second), 2.4e-7 * std::fabs(b[k].second) + 1e-12)
                << where << ": stencil " << i << ", source " << b[k].first;
        }
    }
}

// Levels 1..L of `levels` (double tables, level l's over level l-1's) composed by the reference.
StencilTableD referenceChain(const std::vector<StencilTableD>& levels, int L) {
    StencilTableD composed = levels[0];
    for (int l = 2; l <= L; ++l) composed = referenceCompose(levels[std::size_t(l) - 1], composed);
    return composed;
}

// A table by hand: stencil i reads sources[i] with weights[i].
StencilTableD tableOf(int numSources, const std::vector<std::vector<int>>& sources,
                      const std::vector<std::vector<double>>& weights) {
    StencilTableD t;
    t.numSourceVertices = numSources;
    for (std::size_t i = 0; i < sources.size(); ++i) {
        t.offsets.push_back(int(t.indices.size()));
        t.sizes.push_back(int(sources[i].size()));
        t.indices.insert(t.indices.end(), sources[i].begin(), sources[i].end());
        t.weights.insert(t.weights.end(), weights[i].begin(), weights[i].end());
    }
    return t;
}

TEST(Composition, HandMadeTablesAsTheReference) {
    // Inner stencil 0 starts a sum at -0.0 (which must stay -0.0), stencil 1 adds +0.0 to a source
    // stencil 0 left at -0.0, stencil 2 reads one source twice, stencil 3 is empty, and stencil 4
    // reaches 300 sources, past every initial capacity.
    std::vector<int> wide(300);
    std::vector<double> wideWeights(300);
    for (int s = 0; s < 300; ++s) {
        wide[std::size_t(s)] = (s * 37) % 300;
        wideWeights[std::size_t(s)] = 1.0 / (1 + s);
    }
    const StencilTableD inner = tableOf(300, {{5, 7}, {5, 9}, {2, 2, 3}, {}, wide},
                                        {{-0.0, 0.5}, {0.0, 0.25}, {0.125, 0.375, 0.5}, {}, wideWeights});
    const StencilTableD outer = tableOf(5, {{0}, {0, 1}, {2, 3, 0}, {}, {4, 2, 4, 1}, {3}},
                                        {{1.0}, {1.0, 1.0}, {0.75, 0.5, -0.25}, {}, {0.5, 0.25, 0.5, 1e-300}, {1.0}});
    const StencilTableD want = referenceCompose(outer, inner);
    ASSERT_TRUE(std::signbit(want.weights[0])) << "the reference keeps -0.0";
    expectSame(composeStencils(outer, inner), want, "double");
    expectSame(composeStencilsToFloat(outer, inner), toFloatTable(want), "float");
}

// Stencils that look alike (the same pooled outer mask over inner stencils of equal weights, what
// a composition that reused its work by shape would key on) but whose inner stencils share
// sources differently: A and B share a
// source, A and C share none, A and A' read the same two sources in the other order (a pattern
// with no collapse fits their products, but would give one source two entries). Every one must
// come out as the reference composes it, and so must a second level over the first.
TEST(Composition, LookAlikeStencilsAsTheReference) {
    const std::vector<double> half = {0.5, 0.25};
    const StencilTableD inner = tableOf(5, {{0, 1}, {1, 2}, {3, 4}, {1, 0}}, {half, half, half, half});
    const int A = 0, B = 1, C = 2, A2 = 3;
    const std::vector<double> mask = {0.75, -0.5};
    const StencilTable outer = toFloatTable(
        tableOf(4, {{A, C}, {A, B}, {A, C}, {A, A2}, {C, A}, {A, B}, {B, A}, {A2, A}}, std::vector<std::vector<double>>(8, mask)));
    const StencilTableD want = referenceCompose(toDoubleTable(outer), inner);
    expectSame(composeStencils(outer, inner), want, "double");
    expectSame(composeStencilsToFloat(outer, inner), toFloatTable(want), "float");
    const StencilTable second = toFloatTable(
        tableOf(8, {{0, 1}, {2, 5}, {0, 2}, {3, 3}, {7, 3}, {1, 5}, {4, 6}}, std::vector<std::vector<double>>(7, {0.5, 0.125})));
    const StencilTableD want2 = referenceCompose(toDoubleTable(second), want);
    expectSame(composeStencils(second, composeStencils(outer, inner)), want2, "second level, double");
    expectSame(composeStencilsToFloat(second, composeStencils(outer, inner)), toFloatTable(want2), "second level, float");
}

TEST(Composition, RefusesAtTheSameBytes) {
    const StencilTableD inner = tableOf(4, {{0, 1}, {2, 3}}, {{0.5, 0.5}, {0.5, 0.5}});
    const StencilTableD outer = tableOf(2, {{0, 1}, {0, 1}, {1}}, {{0.5, 0.5}, {0.5, 0.5}, {1.0}});
    const StencilTableD want = referenceCompose(outer, inner);
    const std::size_t exact = bytesOf(want);
    EXPECT_NO_THROW(composeStencils(outer, inner, exact));
    EXPECT_NO_THROW(composeStencilsToFloat(outer, inner, exact));
    EXPECT_THROW(composeStencils(outer, inner, exact - 1), std::length_error);
    EXPECT_THROW(composeStencilsToFloat(outer, inner, exact - 1), std::length_error);
}

// Double tables of levels 1..L built by the analyzer, as the Refiner composes them.
std::vector<StencilTableD> doubleLevels(const Refiner& refiner, int L) {
    std::vector<StencilTableD> levels;
    for (int l = 1; l <= L; ++l) levels.push_back(toDoubleTable(refiner.levelStencils(l)));
    return levels;
}

void checkRefiner(const Refiner& refiner, int maxLevel, const std::string& name) {
    const std::vector<StencilTableD> levels = doubleLevels(refiner, maxLevel);
    for (int L = 1; L <= maxLevel; ++L) {
        const std::string where = name + " level " + std::to_string(L);
        const StencilTableD want = referenceChain(levels, L);
        if (L >= 2) {
            const StencilTableD inner = referenceChain(levels, L - 1);
            expectSame(composeStencils(levels[std::size_t(L) - 1], inner), want, where);
            expectSame(composeStencils(refiner.levelStencils(L), inner), want, where + " from the float table");
            expectSame(composeStencilsToFloat(refiner.levelStencils(L), inner), toFloatTable(want), where + " to float");
            if (L == 2) {  // over level 1's float table itself: its weights widen exactly
                expectSame(composeStencils(refiner.levelStencils(2), refiner.levelStencils(1)), want,
                           where + " over the float table");
                expectSame(composeStencilsToFloat(refiner.levelStencils(2), refiner.levelStencils(1)), toFloatTable(want),
                           where + " over the float table, to float");
            }
        }
        expectClose(refiner.factorizedStencils(L), toFloatTable(want), where + " factorized");
        // Level 1 over the control vertices is level 1's own table, pool and all.
        if (L == 1) expectSame(refiner.factorizedStencils(1), refiner.levelStencils(1), where + " factorized, its own table");
    }
}

TEST(Composition, FactorizedTablesAsTheReference) {
    for (const char* name : {"mixed/mixed_torus.obj", "mixed/cylinder_capped_creased.obj", "osd/catmark_pole8.obj",
                             "osd/loop_xord_interior.obj", "osd/catmark_fan.obj"}) {
        const RefinedMesh r = refineMesh(name, 3);
        checkRefiner(*r.refiner, 3, name);
    }
}

// Regular control faces, whose children's stencils come from templates: every face of a torus of
// quads or triangles, under each scheme that has templates, and fewer where a crease, a pole or
// the tri/quad seam breaks the rings around a face; the tables agree with the reference either way.
TEST(Composition, RegularFacesAsTheReference) {
    for (const bench::TorusFaces faces : {bench::TorusFaces::Quads, bench::TorusFaces::Triangles, bench::TorusFaces::Mixed})
        for (const Scheme scheme : {Scheme::StamLoop, Scheme::SchaeferWarren, Scheme::CatmullClark, Scheme::Loop}) {
            if (scheme == Scheme::Loop && faces != bench::TorusFaces::Triangles) continue;
            const bench::ControlMesh torus = bench::makeTorus(14, faces);
            const TopologyDescriptor desc = torus.descriptor();
            Options options;
            options.scheme = scheme;
            Refiner refiner(desc, options);
            refiner.refineUniform(3);
            const int numFaces = refiner.level(0).numFaces();
            const bool triangleTemplates = scheme != Scheme::CatmullClark;  // it splits triangles into quads
            const RegularPatches patches(refiner, 3);
            const std::string where = torus.name + " under " + toString(scheme);
            const int want = faces == bench::TorusFaces::Quads ? numFaces
                             : faces == bench::TorusFaces::Triangles ? (triangleTemplates ? numFaces : 0)
                                                                     : 0;  // mixed: every face is near the seam
            EXPECT_EQ(patches.numRegularFaces(), want) << where;
            checkRefiner(refiner, 3, where);
        }
    // A crease through a quad torus: the faces whose patches hold one of its vertices are composed.
    const bench::ControlMesh torus = bench::makeTorus(14, bench::TorusFaces::Quads);
    Refiner refiner(withOneCrease(torus.descriptor()), Options());
    refiner.refineUniform(4);  // levels 2 and 3 hold only the composed stencils, level 4 reads both kinds
    const RegularPatches patches(refiner, 4);
    EXPECT_EQ(patches.numRegularFaces(), refiner.level(0).numFaces() - 20) << "a crease edge's two vertices are in 20 patches";
    checkRefiner(refiner, 4, torus.name + " with a crease");
}

// Poles of valence 64: composed stencils near them pass a hundred sources.
TEST(Composition, HighValenceAsTheReference) {
    const bench::ControlMesh sphere = bench::makeUvSphere(64, 6, bench::SpherePoles::TriangleFans);
    const TopologyDescriptor desc = sphere.descriptor();
    Refiner refiner(desc, Options());
    refiner.refineUniform(3);
    checkRefiner(refiner, 3, sphere.name);
}

// Many waves of parts (far/tables/compose_stencils.cpp): one thread and four give the same tables, on a
// mixed torus (everything composed) and on a creased quad torus (templated stencils written
// beside composed ones, the composed reading templated ones).
TEST(Composition, SameTablesOnAnyNumberOfThreads) {
    for (const bench::TorusFaces faces : {bench::TorusFaces::Mixed, bench::TorusFaces::Quads}) {
        const bench::ControlMesh torus = bench::makeTorus(40, faces);
        const bool quads = faces == bench::TorusFaces::Quads;
        const TopologyDescriptor desc = quads ? withOneCrease(torus.descriptor()) : torus.descriptor();
        Options options;
        options.scheme = quads ? Scheme::CatmullClark : Scheme::SchaeferWarren;
        Refiner refiner(desc, options);
        refiner.refineUniform(3);
        StencilTable serial;
        {
            const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
            serial = refiner.factorizedStencils(3);
        }
        StencilTable threaded;
        tbb::task_arena(4).execute([&] { threaded = refiner.factorizedStencils(3); });
        ASSERT_GT(serial.numStencils(), 4 * 4 * 2048) << "fewer stencils than a wave of parts";
        expectSame(threaded, serial, torus.name + " level 3, 4 threads against 1");
        checkRefiner(refiner, 3, torus.name);
    }
}

TEST(Composition, ChannelAndVaryingTablesAsTheReference) {
    const io::ObjMesh mesh = io::readObj(meshPath("osd/catmark_torus.obj"));
    ASSERT_TRUE(mesh.hasUVs());
    FVarChannel uvs;
    Refiner refiner(mesh.descriptor(uvs), mesh.applyTags(Options()));
    refiner.refineUniform(3);
    std::vector<StencilTableD> channel, varying;
    for (int l = 1; l <= 3; ++l) {
        channel.push_back(toDoubleTable(refiner.fvarLevelStencils(0, l)));
        const Topology& parent = refiner.level(l - 1);
        varying.push_back(
            buildVaryingStencils(parent, numberChildren(parent, rulesOf(refiner.options().scheme).triangleSplit())));
    }
    for (int L = 1; L <= 3; ++L) {
        const std::string where = "catmark_torus level " + std::to_string(L);
        expectSame(refiner.fvarFactorizedStencils(0, L), toFloatTable(referenceChain(channel, L)), where + " channel");
        expectSame(refiner.factorizedVaryingStencils(L), toFloatTable(referenceChain(varying, L)), where + " varying");
    }
}

// A Refiner refined without its per-level tables (LevelTables::None) makes the factorized tables
// of one that keeps them, bit for bit: on regular tori (every stencil templated: no per-level
// table read), with a crease (templated and composed stencils side by side: the tables of the
// levels that need them made for the call), on a mixed torus and a high-valence sphere
// (everything composed). Asked again with Build, it gets the per-level tables the other kept.
TEST(Composition, FactorizedTablesWithoutLevelTables) {
    struct Case {
        bench::ControlMesh mesh;
        Scheme scheme;
        bool crease;
    };
    const Case cases[] = {
        {bench::makeTorus(14, bench::TorusFaces::Quads), Scheme::CatmullClark, false},
        {bench::makeTorus(14, bench::TorusFaces::Triangles), Scheme::Loop, false},
        {bench::makeTorus(14, bench::TorusFaces::Quads), Scheme::CatmullClark, true},
        {bench::makeTorus(14, bench::TorusFaces::Mixed), Scheme::SchaeferWarren, false},
        {bench::makeUvSphere(32, 6, bench::SpherePoles::TriangleFans), Scheme::StamLoop, false},
    };
    for (const Case& c : cases) {
        const TopologyDescriptor desc = c.crease ? withOneCrease(c.mesh.descriptor()) : c.mesh.descriptor();
        Options options;
        options.scheme = c.scheme;
        Refiner kept(desc, options), none(desc, options);
        kept.refineUniform(3);
        none.refineUniform(3, TopologyDetail::FacesOnly, LevelTables::None);
        const std::string where = c.mesh.name + (c.crease ? " with a crease" : "") + " under " + toString(c.scheme);
        EXPECT_LT(none.bytes(), kept.bytes()) << where;
        for (int L = 1; L <= 3; ++L) {
            const std::string at = where + " level " + std::to_string(L);
            EXPECT_FALSE(none.hasLevelStencils(L)) << at;
            EXPECT_THROW(none.levelStencils(L), std::logic_error) << at;
            expectSame(none.factorizedStencils(L), kept.factorizedStencils(L), at + " factorized");
            expectSameLimitTable(none.factorizedLimitStencils(L), kept.factorizedLimitStencils(L), at + " factorized limit");
        }
        EXPECT_THROW(none.levelStencils(4), std::out_of_range) << where;
        none.refineUniform(2);  // levels 1 and 2 get their tables, level 3 none yet
        EXPECT_TRUE(none.hasLevelStencils(2) && !none.hasLevelStencils(3)) << where;
        none.refineUniform(3);
        for (int L = 1; L <= 3; ++L) expectSame(none.levelStencils(L), kept.levelStencils(L), where + " level table");
        EXPECT_EQ(none.bytes(), kept.bytes()) << where;
    }
}

}  // namespace
}  // namespace quadtri::test
