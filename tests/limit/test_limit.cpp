// Limit stencils (far/limit_stencil_table.h, Refiner::limitStencils): the published closed forms
// of the limit position at every valence 3-12, unit sums, the orientation of dU × dV, a
// faces-only level, composition over the control vertices, errors, thread independence and the
// pooled weights.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "bench/meshes/torus.h"
#include "tests/limit/limit_support.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

// A fan of n faces around vertex 0 in the plane z = 0, listed counter-clockwise seen from +z:
// quads (0, 1 + k, n + 1 + k, 1 + (k + 1) % n), or triangles (0, 1 + k, 1 + (k + 1) % n).
struct Fan {
    std::vector<int> sizes, verts;
    std::vector<float> positions;
    int numVertices = 0;
    TopologyDescriptor descriptor() const { return descriptorOf(numVertices, sizes, verts); }
};

Fan fan(int n, bool quads, bool reversed = false) {
    Fan f;
    f.numVertices = quads ? 2 * n + 1 : n + 1;
    f.positions = {0, 0, 0};
    for (int k = 0; k < n; ++k) {
        const double a = 2 * M_PI * k / n;
        f.positions.insert(f.positions.end(), {float(std::cos(a)), float(std::sin(a)), 0.0f});
    }
    if (quads)
        for (int k = 0; k < n; ++k) {
            const double a = 2 * M_PI * (k + 0.5) / n;
            f.positions.insert(f.positions.end(), {float(1.4 * std::cos(a)), float(1.4 * std::sin(a)), 0.0f});
        }
    for (int k = 0; k < n; ++k) {
        std::vector<int> face = {0, 1 + k};
        if (quads) face.push_back(n + 1 + k);
        face.push_back(1 + (k + 1) % n);
        if (reversed) std::reverse(face.begin() + 1, face.end());  // clockwise, first corner kept
        f.sizes.push_back(int(face.size()));
        f.verts.insert(f.verts.end(), face.begin(), face.end());
    }
    return f;
}

// Stencil i's weights of `vertex` (position, dU, dV), zero where it does not read it.
Vec3 weightsOf(const LimitStencilTable& table, int i, int vertex) {
    Vec3 w{0, 0, 0};
    for (int k = 0; k < table.size(i); ++k)
        if (table.indices[table.offsets[i] + k] == vertex)
            for (int c = 0; c < 3; ++c) w[c] += table.weightsOf(i)[3 * k + c];
    return w;
}

LimitStencilTable limitOf(const Fan& f, Scheme scheme, bool leftHanded = false) {
    Options options;
    options.scheme = scheme;
    options.leftHanded = leftHanded;
    return Refiner(f.descriptor(), options).limitStencils(0);
}

// Catmull-Clark's limit position at a smooth vertex of valence n: (n² v + 4 Σ edge neighbours +
// Σ diagonal corners) / (n (n + 5)) (Halstead, Kass & DeRose 1993); at n = 4, 4/9, 1/9, 1/36.
TEST(LimitClosedForms, CatmullClarkPositionAtValences3To12) {
    for (Scheme scheme : {Scheme::CatmullClark, Scheme::StamLoop, Scheme::SchaeferWarren, Scheme::CatmarkButterfly})
        for (int n = 3; n <= 12; ++n) {
            const LimitStencilTable table = limitOf(fan(n, true), scheme);
            const double d = n * (n + 5.0);
            EXPECT_NEAR(weightsOf(table, 0, 0)[0], n * n / d, 1e-7) << toString(scheme) << " valence " << n;
            for (int k = 0; k < n; ++k) {
                EXPECT_NEAR(weightsOf(table, 0, 1 + k)[0], 4 / d, 1e-7) << toString(scheme) << " valence " << n;
                EXPECT_NEAR(weightsOf(table, 0, n + 1 + k)[0], 1 / d, 1e-7) << toString(scheme) << " valence " << n;
            }
        }
    const LimitStencilTable regular = limitOf(fan(4, true), Scheme::CatmullClark);
    EXPECT_FLOAT_EQ(weightsOf(regular, 0, 0)[0], 4.0f / 9);
    EXPECT_FLOAT_EQ(weightsOf(regular, 0, 1)[0], 1.0f / 9);
    EXPECT_FLOAT_EQ(weightsOf(regular, 0, 5)[0], 1.0f / 36);
}

// Loop's limit position at a smooth vertex of valence n: (1 − n w) v + w Σ neighbours with
// w = 1 / (n + 3 / (8 β)), β Loop's vertex weight (5/8 − (3/8 + ¼ cos 2π/n)²) / n (Loop 1987;
// Hoppe et al. 1994); at n = 6, ½ and 1/12.
TEST(LimitClosedForms, LoopPositionAtValences3To12) {
    for (Scheme scheme : {Scheme::Loop, Scheme::StamLoop, Scheme::SchaeferWarren})
        for (int n = 3; n <= 12; ++n) {
            const LimitStencilTable table = limitOf(fan(n, false), scheme);
            const double c = 3.0 / 8 + std::cos(2 * M_PI / n) / 4, beta = (5.0 / 8 - c * c) / n;
            const double w = 1 / (n + 3 / (8 * beta));
            EXPECT_NEAR(weightsOf(table, 0, 0)[0], 1 - n * w, 1e-7) << toString(scheme) << " valence " << n;
            for (int k = 1; k <= n; ++k) EXPECT_NEAR(weightsOf(table, 0, k)[0], w, 1e-7) << toString(scheme) << " valence " << n;
        }
    const LimitStencilTable regular = limitOf(fan(6, false), Scheme::Loop);
    EXPECT_FLOAT_EQ(weightsOf(regular, 0, 0)[0], 0.5f);
    EXPECT_FLOAT_EQ(weightsOf(regular, 0, 1)[0], 1.0f / 12);
}

// The boundary of a fan is a crease curve (a uniform cubic B-spline): a boundary vertex with two
// boundary neighbours a, b lands on (a + 4 v + b) / 6; a vertex fixed by the corner rule stays.
TEST(LimitClosedForms, CreaseAndCornerPositions) {
    const Fan f = fan(6, false);
    const LimitStencilTable table = limitOf(f, Scheme::Loop);
    EXPECT_FLOAT_EQ(weightsOf(table, 1, 1)[0], 4.0f / 6);
    EXPECT_FLOAT_EQ(weightsOf(table, 1, 2)[0], 1.0f / 6);
    EXPECT_FLOAT_EQ(weightsOf(table, 1, 6)[0], 1.0f / 6);
    EXPECT_FLOAT_EQ(weightsOf(table, 1, 0)[0], 0.0f);
    Options options;
    options.scheme = Scheme::CatmullClark;
    options.boundary = BoundaryInterpolation::EdgeAndCorner;
    const Fan quads = fan(4, true);
    const LimitStencilTable corners = Refiner(quads.descriptor(), options).limitStencils(0);
    EXPECT_FLOAT_EQ(weightsOf(corners, 5, 5)[0], 1.0f);  // a diagonal corner: one face, two edges
    EXPECT_EQ(corners.size(5), 3);                         // itself and its two edge neighbours
}

// Position weights sum to 1 and tangent weights to 0, on every catmark_* shape under
// catmull-clark, loop_* under loop and bilinear_cube under bilinear, levels 0-2, per-level and
// factorized.
TEST(LimitStencils, PositionWeightsSumToOneTangentsToZero) {
    for (const std::string& mesh : allMeshes()) {
        Options options;
        const std::string name = mesh.substr(mesh.find('/') + 1);
        if (name.rfind("catmark_", 0) == 0)
            options.scheme = Scheme::CatmullClark;
        else if (name.rfind("loop_", 0) == 0)
            options.scheme = Scheme::Loop;
        else if (name.rfind("bilinear_", 0) == 0)
            options.scheme = Scheme::Bilinear;
        else
            continue;
        const RefinedMesh r = refineMesh(mesh, 2, options);
        for (int L = 0; L <= 2; ++L)
            for (const LimitStencilTable& table : {r.refiner->limitStencils(L), r.refiner->factorizedLimitStencils(L)})
                for (int i = 0; i < table.numStencils(); ++i) {
                    double sum[3] = {0, 0, 0}, scale[3] = {0, 0, 0};
                    for (int k = 0; k < table.size(i); ++k)
                        for (int c = 0; c < 3; ++c) {
                            sum[c] += table.weightsOf(i)[3 * k + c];
                            scale[c] += std::abs(table.weightsOf(i)[3 * k + c]);
                        }
                    ASSERT_NEAR(sum[0], 1.0, 1e-5) << mesh << " level " << L << " stencil " << i;
                    ASSERT_NEAR(sum[1], 0.0, 1e-6 * scale[1]) << mesh << " level " << L << " stencil " << i;
                    ASSERT_NEAR(sum[2], 0.0, 1e-6 * scale[2]) << mesh << " level " << L << " stencil " << i;
                }
    }
}

// dU × dV points to the side from which the faces run counter-clockwise: +z on a flat fan, at
// the smooth centre, the crease points of its rim and its corners, under every closed-form
// scheme; the same with the faces listed clockwise and Options::leftHanded.
TEST(LimitStencils, NormalsPointOutside) {
    for (Scheme scheme : {Scheme::CatmullClark, Scheme::Loop, Scheme::Bilinear, Scheme::StamLoop})
        for (bool quads : {true, false})
            for (bool leftHanded : {false, true})
                for (int n : {3, 4, 5, 6, 7}) {
                    if (scheme == Scheme::Loop && quads) continue;
                    const Fan f = fan(n, quads, leftHanded);
                    for (BoundaryInterpolation boundary : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
                        Options options;
                        options.scheme = scheme;
                        options.leftHanded = leftHanded;
                        options.boundary = boundary;
                        const LimitData d = applyLimit(Refiner(f.descriptor(), options).limitStencils(0), f.positions);
                        for (int v = 0; v < f.numVertices; ++v) {
                            const Vec3 normal = cross(d.du[v], d.dv[v]);
                            EXPECT_GT(normal[2], 1e-3 * norm(d.du[v]) * norm(d.dv[v]))
                                << toString(scheme) << (quads ? " quads" : " triangles") << " valence " << n
                                << (leftHanded ? " left-handed" : "") << " " << toString(boundary) << " vertex " << v;
                        }
                    }
                }
}

// On a closed shape every limit normal points away from the centre: the cube under
// catmull-clark and loop, levels 0-3.
TEST(LimitStencils, ClosedShapesNormalsPointAway) {
    for (const auto& [mesh, scheme] : {std::pair{"osd/catmark_cube.obj", Scheme::CatmullClark},
                                       std::pair{"osd/loop_cube.obj", Scheme::Loop},
                                       std::pair{"osd/catmark_cube.obj", Scheme::SchaeferWarren}}) {
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineMesh(mesh, 3, options);
        Vec3 centre{0, 0, 0};
        const int n0 = r.mesh.numVertices();
        for (int v = 0; v < n0; ++v)
            for (int c = 0; c < 3; ++c) centre[c] += r.mesh.positions[3 * v + c] / n0;
        for (int L = 0; L <= 3; ++L) {
            const LimitData d = applyLimit(r.refiner->limitStencils(L), r.positions[L]);
            for (std::size_t v = 0; v < d.position.size(); ++v) {
                const Vec3 out{d.position[v][0] - centre[0], d.position[v][1] - centre[1], d.position[v][2] - centre[2]};
                EXPECT_GT(dot(cross(d.du[v], d.dv[v]), out), 0) << mesh << " level " << L << " vertex " << v;
            }
        }
    }
}

// A vertex and its vertex point one level down are the same point of the limit surface, with the
// same tangent plane (on the same side of a crease): the masks agree with the refinement rules,
// independently of OpenSubdiv. Not where OpenSubdiv's closed forms are themselves approximate
// (docs/limit.md, "Where the closed forms are not the exact limit"): semi-sharp features, darts,
// and the cross-crease tangent at irregular Catmull-Clark crease vertices.
TEST(LimitStencils, VertexPointsKeepTheirLimit) {
    for (const auto& [mesh, scheme] : {std::pair{"osd/catmark_cube.obj", Scheme::CatmullClark},
                                       std::pair{"osd/catmark_nonquads.obj", Scheme::CatmullClark},
                                       std::pair{"osd/catmark_edgecorner.obj", Scheme::CatmullClark},
                                       std::pair{"osd/catmark_inf_crease0.obj", Scheme::CatmullClark},
                                       std::pair{"osd/loop_icos_infsharp.obj", Scheme::Loop},
                                       std::pair{"osd/loop_xord_interior.obj", Scheme::Loop},
                                       std::pair{"osd/loop_triangle_edgeonly.obj", Scheme::Loop},
                                       std::pair{"osd/catmark_xord_boundary.obj", Scheme::SchaeferWarren}}) {
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineMesh(mesh, 3, options);
        const double diagonal = boundingBoxDiagonal(r.mesh.positions);
        for (int L = 1; L < 3; ++L) {
            const LimitData parent = applyLimit(r.refiner->limitStencils(L), r.positions[L]);
            const LimitData child = applyLimit(r.refiner->limitStencils(L + 1), r.positions[L + 1]);
            const Topology& t = r.refiner->level(L);
            const int firstVertexPoint = r.refiner->level(L + 1).numVertices - t.numVertices;
            for (int v = 0; v < t.numVertices; ++v) {
                const int c = firstVertexPoint + v;
                int sharpEdges = 0;
                bool semiSharp = t.vertSharpness[v] > 0 && t.vertSharpness[v] < kInfiniteSharpness;
                for (int e : t.edgesOfVertex(v)) {
                    sharpEdges += t.edgeSharpness[e] > 0 ? 1 : 0;
                    semiSharp = semiSharp || (t.edgeSharpness[e] > 0 && t.edgeSharpness[e] < kInfiniteSharpness);
                }
                if (semiSharp || sharpEdges == 1) continue;
                EXPECT_LE(distance(parent.position[v], child.position[c]), 1e-6 * diagonal) << mesh << " level " << L << " vertex " << v;
                if (t.vertSharpness[v] > 0 || sharpEdges > 2 || (t.vertFlags[v] & kVertexNonManifold)) continue;  // corners
                const bool regularCrease = t.vertexEdgeCount(v) == ((t.vertFlags[v] & kVertexBoundary) ? 3 : 4);
                if (sharpEdges == 2 && scheme != Scheme::Loop && !regularCrease) continue;
                EXPECT_LE(angleBetween(cross(parent.du[v], parent.dv[v]), cross(child.du[c], child.dv[c])), 1e-3)
                    << mesh << " level " << L << " vertex " << v;
            }
        }
    }
}

// A last level built with its faces only is completed for the call: the same table as from a
// full level, and the Refiner is left as it was.
TEST(LimitStencils, FacesOnlyLevelGivesTheSameTable) {
    for (const auto& [mesh, scheme] : {std::pair{"osd/catmark_pawn.obj", Scheme::CatmullClark},
                                       std::pair{"osd/loop_cubes_semisharp.obj", Scheme::Loop}}) {
        Options options;
        options.scheme = scheme;
        const io::ObjMesh obj = io::readObj(meshPath(mesh));
        options = obj.applyTags(options);
        Refiner facesOnly(obj.descriptor(), options), full(obj.descriptor(), options);
        facesOnly.refineUniform(2);
        full.refineUniform(2, TopologyDetail::Full);
        const LimitStencilTable a = facesOnly.limitStencils(2), b = full.limitStencils(2);
        EXPECT_EQ(facesOnly.detail(2), TopologyDetail::FacesOnly) << mesh;
        EXPECT_EQ(a.sizes, b.sizes) << mesh;
        EXPECT_EQ(a.offsets, b.offsets) << mesh;
        EXPECT_EQ(a.indices, b.indices) << mesh;
        EXPECT_EQ(a.weightOffsets, b.weightOffsets) << mesh;
        EXPECT_EQ(a.weights, b.weights) << mesh;
        EXPECT_EQ(a.numSourceVertices, b.numSourceVertices) << mesh;
    }
}

// factorizedLimitStencils(L) on `control` lands where limitStencils(L) on level L's refined
// vertices (`level`) does.
void expectFactorizedAsPerLevel(const Refiner& refiner, const std::vector<float>& control, const std::vector<float>& level,
                                int L, const std::string& where) {
    const double diagonal = boundingBoxDiagonal(control);
    const int maxLevel = refiner.maxLevel();
    const LimitStencilTable factorized = refiner.factorizedLimitStencils(L);
    EXPECT_EQ(factorized.numSourceVertices, int(control.size() / 3)) << where;
    const LimitData a = applyLimit(factorized, control);
    const LimitData b = applyLimit(refiner.limitStencils(L), level);
    ASSERT_EQ(a.position.size(), b.position.size()) << where;
    for (std::size_t v = 0; v < a.position.size(); ++v) {
        EXPECT_LE(distance(a.position[v], b.position[v]), 1e-6 * diagonal) << where << " level " << L;
        EXPECT_LE(distance(a.du[v], b.du[v]), 1e-6 * diagonal * (1 << (maxLevel - L)) + 1e-5 * norm(b.du[v])) << where;
        EXPECT_LE(distance(a.dv[v], b.dv[v]), 1e-6 * diagonal * (1 << (maxLevel - L)) + 1e-5 * norm(b.dv[v])) << where;
    }
}

TEST(LimitStencils, FactorizedEqualsPerLevel) {
    for (const auto& [mesh, scheme] : {std::pair{"osd/catmark_torus_creases0.obj", Scheme::CatmullClark},
                                       std::pair{"osd/loop_icos_infsharp.obj", Scheme::Loop},
                                       std::pair{"osd/catmark_nonquads.obj", Scheme::CatmullClark}}) {
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineMesh(mesh, 3, options);
        for (int L = 0; L <= 3; ++L) expectFactorizedAsPerLevel(*r.refiner, r.mesh.positions, r.positions[L], L, mesh);
    }
}

// The same on tori big enough for the factorized tables' templates (docs/factorized_templates.md):
// the level chain below the limit table leaves the templated stencils out of its intermediate
// levels and keeps its last level whole. A crease keeps some faces composed beside them.
TEST(LimitStencils, FactorizedEqualsPerLevelWithTemplates) {
    for (const bench::TorusFaces faces : {bench::TorusFaces::Quads, bench::TorusFaces::Triangles}) {
        const bench::ControlMesh torus = bench::makeTorus(14, faces);
        const TopologyDescriptor desc = withOneCrease(torus.descriptor());
        Options options;
        options.scheme = faces == bench::TorusFaces::Quads ? Scheme::CatmullClark : Scheme::Loop;
        Refiner refiner(desc, options);
        refiner.refineUniform(3);
        const std::vector<std::vector<float>> levels = evaluateLevels(refiner, torus.positions, 3);
        for (int L = 1; L <= 3; ++L) expectFactorizedAsPerLevel(refiner, torus.positions, levels[std::size_t(L)], L, torus.name);
    }
}

TEST(LimitStencils, RefusesLevelsOutOfRangeAndPastTheBudget) {
    Options options;
    options.scheme = Scheme::CatmullClark;
    const RefinedMesh r = refineMesh("osd/catmark_cube.obj", 2, options);
    EXPECT_THROW(r.refiner->limitStencils(3), TopologyError);
    EXPECT_THROW(r.refiner->limitStencils(-1), TopologyError);
    EXPECT_THROW(r.refiner->factorizedLimitStencils(3), TopologyError);

    // The smallest budget level 4 is refined under leaves too little for its factorized limit.
    const io::ObjMesh obj = io::readObj(meshPath("osd/catmark_cube.obj"));
    Options tight = options;
    std::size_t lo = 0, hi = std::size_t(1) << 26;
    while (hi - lo > 1) {
        tight.memoryBudgetBytes = (lo + hi) / 2;
        try {
            Refiner(obj.descriptor(), tight).refineUniform(4);
            hi = tight.memoryBudgetBytes;
        } catch (const MemoryBudgetError&) {
            lo = tight.memoryBudgetBytes;
        }
    }
    tight.memoryBudgetBytes = hi;
    Refiner small(obj.descriptor(), tight);
    small.refineUniform(4);
    try {
        small.factorizedLimitStencils(4);
        FAIL() << "the factorized limit stencils of level 4 fit in " << tight.memoryBudgetBytes << " bytes";
    } catch (const MemoryBudgetError& e) {
        EXPECT_EQ(e.subject(), "the factorized limit stencils of level 4");
        EXPECT_GT(e.needed(), e.budget());
    }
}

// The table does not depend on the number of threads that build it (a level large enough to be
// split into parts).
TEST(LimitStencils, SameTableOnAnyNumberOfThreads) {
    Options options;
    options.scheme = Scheme::CatmullClark;
    const RefinedMesh r = refineMesh("osd/catmark_pawn.obj", 3, options);
    LimitStencilTable serial, parallel;
    tbb::task_arena(1).execute([&] { serial = r.refiner->limitStencils(3); });
    tbb::task_arena(4).execute([&] { parallel = r.refiner->limitStencils(3); });
    ASSERT_GT(serial.numStencils(), 32768);
    EXPECT_EQ(serial.sizes, parallel.sizes);
    EXPECT_EQ(serial.offsets, parallel.offsets);
    EXPECT_EQ(serial.indices, parallel.indices);
    EXPECT_EQ(serial.weightOffsets, parallel.weightOffsets);
    EXPECT_EQ(serial.weights, parallel.weights);
}

// Several threads may ask one Refiner for limit tables at once, a faces-only level included.
TEST(LimitStencils, ConcurrentReadersGetTheSameTable) {
    Options options;
    options.scheme = Scheme::CatmullClark;
    const io::ObjMesh obj = io::readObj(meshPath("osd/catmark_torus_creases0.obj"));
    Refiner refiner(obj.descriptor(), obj.applyTags(options));
    refiner.refineUniform(3);
    const LimitStencilTable reference = refiner.limitStencils(3);
    std::vector<LimitStencilTable> tables(4);
    std::vector<std::thread> threads;
    for (auto& table : tables) threads.emplace_back([&] { table = refiner.limitStencils(3); });
    for (auto& thread : threads) thread.join();
    for (const LimitStencilTable& table : tables) {
        EXPECT_EQ(table.sizes, reference.sizes);
        EXPECT_EQ(table.offsets, reference.offsets);
        EXPECT_EQ(table.indices, reference.indices);
        EXPECT_EQ(table.weightOffsets, reference.weightOffsets);
        EXPECT_EQ(table.weights, reference.weights);
    }
}

// Identical masks share their weights: on the torus, where every vertex is regular, every
// stencil's 9 weight triples are one mask's, in the order of its ring's vertex numbers (the
// runs of sources ascend), so the pool holds that mask once per ordering that occurs, far fewer
// than the stencils.
TEST(LimitStencils, RegularMasksArePooled) {
    Options options;
    options.scheme = Scheme::CatmullClark;
    const RefinedMesh r = refineMesh("osd/catmark_torus.obj", 2, options);
    const LimitStencilTable table = r.refiner->limitStencils(2);
    EXPECT_EQ(table.numEntries(), 9u * table.numStencils());
    auto sortedTriples = [&](int i) {
        std::vector<std::array<float, 3>> triples;
        for (int k = 0; k < 9; ++k) triples.push_back({table.weightsOf(i)[3 * k], table.weightsOf(i)[3 * k + 1], table.weightsOf(i)[3 * k + 2]});
        std::sort(triples.begin(), triples.end());
        return triples;
    };
    for (int i = 0; i < table.numStencils(); ++i) ASSERT_EQ(sortedTriples(i), sortedTriples(0)) << "stencil " << i;
    EXPECT_EQ(table.weights.size() % 27, 0u);
    EXPECT_LT(10 * table.weights.size(), 27u * table.numStencils());
    EXPECT_EQ(table.bytes(), (table.sizes.size() + table.offsets.size() + table.indices.size() +
                              table.weightOffsets.size()) * sizeof(int) +
                                 table.weights.size() * sizeof(float));
}

// Bilinear: every vertex is its own limit.
TEST(LimitStencils, BilinearVerticesAreTheirOwnLimit) {
    Options options;
    options.scheme = Scheme::Bilinear;
    const RefinedMesh r = refineMesh("osd/bilinear_cube.obj", 2, options);
    for (int L = 0; L <= 2; ++L) {
        const LimitStencilTable table = r.refiner->limitStencils(L);
        for (int i = 0; i < table.numStencils(); ++i) EXPECT_EQ(weightsOf(table, i, i)[0], 1.0f) << "level " << L;
    }
}

}  // namespace
}  // namespace quadtri::test
