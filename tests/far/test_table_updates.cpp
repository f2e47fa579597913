// LimitTableUpdate and FactorizedTableUpdate against the Refiner's own tables after the same
// edits: limit tables over level L bit for bit, tables over the control vertices within rounding;
// for every mesh and scheme, and after a hundred edits in a row.
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include <quadtri/far/limit_table_update.h>
#include <quadtri/far/stencil_table_update.h>

#include "tests/far/edit_support.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

using Sources = LimitTableUpdate::Sources;

bool sameStencil(const LimitStencilTable& a, const LimitStencilTable& b, int i) {
    const int n = a.size(i);
    return n == b.size(i) && std::equal(a.sourcesOf(i), a.sourcesOf(i) + n, b.sourcesOf(i)) &&
           std::memcmp(a.weightsOf(i), b.weightsOf(i), sizeof(float) * 3 * std::size_t(n)) == 0;
}

// The largest difference of a weight between the tables' stencils (a source one lacks weighs 0
// there), over every stencil.
double largestDifference(const LimitStencilTable& a, const LimitStencilTable& b) {
    if (a.numStencils() != b.numStencils()) return INFINITY;
    double largest = 0.0;
    for (int i = 0; i < a.numStencils(); ++i) {
        std::map<int, std::array<double, 3>> sum;
        for (int k = 0; k < a.size(i); ++k)
            for (int c = 0; c < 3; ++c) sum[a.sourcesOf(i)[k]][std::size_t(c)] += a.weightsOf(i)[3 * k + c];
        for (int k = 0; k < b.size(i); ++k)
            for (int c = 0; c < 3; ++c) sum[b.sourcesOf(i)[k]][std::size_t(c)] -= b.weightsOf(i)[3 * k + c];
        for (const auto& [source, d] : sum)
            for (double x : d) largest = std::max(largest, std::abs(x));
    }
    return largest;
}

LimitStencilTable tableOf(const Refiner& refiner, int level, Sources sources) {
    return sources == Sources::Level ? refiner.limitStencils(level) : refiner.factorizedLimitStencils(level);
}

// The updated table against the Refiner's: bit for bit over level L, within 1e-6 over the
// control vertices; and every stencil that changed since `before` among those returned.
void expectUpToDate(const Refiner& refiner, int level, Sources sources, const LimitStencilTable& updated,
                    const LimitStencilTable& before, const std::vector<int>& written, const std::string& where) {
    const LimitStencilTable rebuilt = tableOf(refiner, level, sources);
    ASSERT_EQ(updated.numStencils(), rebuilt.numStencils()) << where;
    if (sources == Sources::Level) {
        for (int i = 0; i < rebuilt.numStencils(); ++i)
            ASSERT_TRUE(sameStencil(updated, rebuilt, i)) << where << ", stencil " << i;
    } else {
        EXPECT_LT(largestDifference(updated, rebuilt), 1e-6) << where;
    }
    for (int i = 0; i < rebuilt.numStencils(); ++i) {
        const bool reported = std::binary_search(written.begin(), written.end(), i);
        ASSERT_TRUE(reported || sameStencil(before, updated, i)) << where << ", stencil " << i << " changed, not reported";
    }
}

TEST(LimitTableUpdate, EqualsTheRefinersTablesOnEveryMeshAndScheme) {
    std::mt19937 random(5);
    for (const std::string& name : allMeshes()) {
        const io::ObjMesh mesh = io::readObj(meshPath(name));
        const int levels = mesh.numFaces() > 300 ? 1 : 2;  // the pawn and the rook at level 1: time
        for (Scheme scheme : allSchemes()) {
            const std::unique_ptr<Refiner> refiner = buildIfTaken(mesh, scheme, levels);
            if (!refiner) continue;
            const bool holes = refiner->faces(0).numFaces() == mesh.numFaces();
            for (Sources sources : {Sources::Level, Sources::Control}) {
                LimitTableUpdate update(*refiner, levels, sources);
                LimitStencilTable table = tableOf(*refiner, levels, sources);
                const LimitStencilTable before = table;
                const EditReport report = refiner->applyEdits(randomEdits(refiner->level(0), random, holes));
                const std::vector<int> written = update.update(report, table).stencils;
                expectUpToDate(*refiner, levels, sources, table, before, written,
                               name + ", " + toString(scheme) + (sources == Sources::Level ? ", level" : ", control"));
                if (HasFailure()) return;
            }
        }
    }
}

TEST(LimitTableUpdate, AHundredEditsInARowKeepTheTablesUpToDate) {
    for (const char* name : {"mixed/cylinder_capped_creased.obj", "osd/catmark_pawn.obj"}) {
        const io::ObjMesh mesh = io::readObj(meshPath(name));
        Options options;
        options.scheme = std::string(name).find("osd/") == 0 ? Scheme::CatmullClark : Scheme::SchaeferWarren;
        options = mesh.applyTags(options);
        std::unique_ptr<Refiner> refiner = build(mesh, options, 2);
        LimitTableUpdate level(*refiner, 2, Sources::Level), control(*refiner, 2, Sources::Control);
        LimitStencilTable overLevel = refiner->limitStencils(2), overControl = refiner->factorizedLimitStencils(2);
        std::mt19937 random(13);
        for (int k = 1; k <= 100; ++k) {
            const EditReport report = refiner->applyEdits(randomEdits(refiner->level(0), random, true));
            const LimitStencilTable beforeLevel = overLevel, beforeControl = overControl;
            const std::vector<int> a = level.update(report, overLevel).stencils, b = control.update(report, overControl).stencils;
            if (k % 20 != 0) continue;
            const std::string where = std::string(name) + ", edit " + std::to_string(k);
            expectUpToDate(*refiner, 2, Sources::Level, overLevel, beforeLevel, a, where);
            expectUpToDate(*refiner, 2, Sources::Control, overControl, beforeControl, b, where);
            if (HasFailure()) return;
        }
    }
}

// The largest difference of a weight between two CSR tables' stencils (a source one lacks weighs
// 0 there).
double largestDifference(const StencilTable& a, const StencilTable& b) {
    if (a.numStencils() != b.numStencils()) return INFINITY;
    double largest = 0.0;
    for (int i = 0; i < a.numStencils(); ++i) {
        std::map<int, double> sum;
        for (int k = 0; k < a.size(i); ++k) sum[a.indices[std::size_t(a.offsets[i] + k)]] += a.weightsOf(i)[k];
        for (int k = 0; k < b.size(i); ++k) sum[b.indices[std::size_t(b.offsets[i] + k)]] -= b.weightsOf(i)[k];
        for (const auto& [source, d] : sum) largest = std::max(largest, std::abs(d));
    }
    return largest;
}

bool sameStencil(const StencilTable& a, const StencilTable& b, int i) {
    const int n = a.size(i);
    return n == b.size(i) &&
           std::equal(a.indices.begin() + a.offsets[i], a.indices.begin() + a.offsets[i + 1], b.indices.begin() + b.offsets[i]) &&
           std::memcmp(a.weightsOf(i), b.weightsOf(i), sizeof(float) * std::size_t(n)) == 0;
}

// FactorizedTableUpdate: factorizedStencils(L) within 1e-6 after every edit, every stencil that
// changed among those reported, on every mesh and scheme and after a hundred edits in a row.
TEST(FactorizedTableUpdate, EqualsTheRefinersTableAfterEveryEdit) {
    std::mt19937 random(23);
    auto check = [&](const std::string& name, Scheme scheme, int levels, int edits) {
        const io::ObjMesh mesh = io::readObj(meshPath(name));
        const std::unique_ptr<Refiner> refiner = buildIfTaken(mesh, scheme, levels);
        if (!refiner) return;
        const bool holes = refiner->faces(0).numFaces() == mesh.numFaces();
        FactorizedTableUpdate update(*refiner, levels);
        StencilTable table = refiner->factorizedStencils(levels);
        for (int k = 1; k <= edits; ++k) {
            const StencilTable before = table;
            const StencilTableChange change = update.update(refiner->applyEdits(randomEdits(refiner->level(0), random, holes)), table);
            if (edits > 10 && k % 25 != 0) continue;
            const std::string where = name + ", " + toString(scheme) + ", edit " + std::to_string(k);
            EXPECT_LT(largestDifference(table, refiner->factorizedStencils(levels)), 1e-6) << where;
            bool resized = false;
            for (int i = 0; i < table.numStencils(); ++i) {
                const bool reported = std::binary_search(change.stencils.begin(), change.stencils.end(), i);
                ASSERT_TRUE(reported || sameStencil(before, table, i)) << where << ", stencil " << i;
                resized = resized || (reported && before.size(i) != table.size(i));
            }
            EXPECT_EQ(change.resized, resized) << where;
        }
    };
    for (const std::string& name : allMeshes())
        for (Scheme scheme : allSchemes()) check(name, scheme, 2, 2);
    check("mixed/cylinder_capped_creased.obj", Scheme::SchaeferWarren, 3, 100);
    check("osd/catmark_pawn.obj", Scheme::CatmullClark, 2, 100);
}

TEST(LimitTableUpdate, RefusesALevelWithoutWhatItReads) {
    const io::ObjMesh mesh = io::readObj(meshPath("mixed/mixed_torus.obj"));
    Refiner facesOnly(mesh.descriptor(), Options());
    facesOnly.refineUniform(2);  // level 2 holds its faces only
    EXPECT_THROW(LimitTableUpdate(facesOnly, 2, Sources::Level), std::logic_error);
    Refiner noTables(mesh.descriptor(), Options());
    noTables.refineUniform(2, TopologyDetail::Full, LevelTables::None);
    EXPECT_THROW(LimitTableUpdate(noTables, 2, Sources::Control), std::logic_error);
    EXPECT_NO_THROW(LimitTableUpdate(noTables, 2, Sources::Level));
    EXPECT_THROW(LimitTableUpdate(noTables, 3, Sources::Level), std::logic_error);
    EXPECT_THROW(FactorizedTableUpdate(noTables, 2), std::logic_error);
    EXPECT_THROW(FactorizedTableUpdate(facesOnly, 0), std::logic_error);
}

}  // namespace
}  // namespace quadtri::test
