// Face-varying channels: invariants of their tables under every scheme and option (a linear map
// of the positions reproduced where the channel has no seam, partition of unity, factorized
// tables equal to the per-level ones), a UV seam across the tri/quad seam of a mixed mesh, the
// API's refusals of bad channels, faces that repeat a vertex (read as their loops, values too),
// and UVs read from OBJ files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <quadtri/osd/cpu_evaluator.h>

#include "tests/test_support.h"

namespace quadtri::test {
namespace {


std::vector<Scheme> schemesFor(const io::ObjMesh& mesh) {
    const bool triangles = std::all_of(mesh.faceSizes.begin(), mesh.faceSizes.end(), [](int n) { return n == 3; });
    std::vector<Scheme> schemes;
    for (Scheme s : allSchemes())
        if (s != Scheme::Loop || triangles) schemes.push_back(s);
    return schemes;
}

// A linear map of the positions, 2 floats per vertex.
std::vector<float> linearUVs(const std::vector<float>& xyz) {
    std::vector<float> uv;
    for (std::size_t v = 0; v < xyz.size(); v += 3) {
        uv.push_back(0.5f * xyz[v] - 0.25f * xyz[v + 1] + 0.125f * xyz[v + 2] + 2.0f);
        uv.push_back(-0.375f * xyz[v] + 0.75f * xyz[v + 2] - 1.0f);
    }
    return uv;
}

// A channel with one value per vertex has no seam: wherever its values' rules are the vertices'
// (every option but All on a closed mesh, and None anywhere), the refined values are the same
// linear map of the refined positions, corner by corner.
TEST(FVar, LinearMapOfThePositionsIsReproducedWithoutSeams) {
    for (const std::string name : {"mixed/mixed_torus.obj", "mixed/checker_cube.obj", "mixed/cylinder_capped.obj",
                                   "osd/loop_icosahedron.obj", "mixed/split_plane.obj", "osd/catmark_tent.obj"}) {
        const io::ObjMesh mesh = io::readObj(meshPath(name));
        bool closed = true;
        {
            Refiner probe(mesh.descriptor(), mesh.applyTags(Options()));
            for (uint8_t flags : probe.level(0).vertFlags) closed = closed && !(flags & kVertexBoundary);
        }
        const FVarChannel channel{mesh.numVertices(), mesh.faceVerts.data()};
        const std::vector<float> control = linearUVs(mesh.positions);
        for (Scheme scheme : schemesFor(mesh))
            for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
                if (fvar == FVarLinearInterpolation::All || (!closed && fvar != FVarLinearInterpolation::None)) continue;
                SCOPED_TRACE(name + " " + toString(scheme) + " " + toString(fvar));
                Options options;
                options.scheme = scheme;
                options.fvarLinearInterpolation = fvar;
                options = mesh.applyTags(options);
                TopologyDescriptor desc = mesh.descriptor();
                desc.numFVarChannels = 1;
                desc.fvarChannels = &channel;
                Refiner refiner(desc, options);
                refiner.refineUniform(3);
                const auto positions = evaluateLevels(refiner, mesh.positions, 3);
                const auto uvs = evaluateChannelLevels(refiner, 0, control, 2);
                double worst = 0, scale = 1;
                for (float x : control) scale = std::max(scale, double(std::fabs(x)));
                for (int L = 1; L <= 3; ++L) {
                    const std::vector<float> expected = linearUVs(positions[L]);
                    const LevelFaces faces = refiner.faces(L);
                    for (int f = 0; f < faces.numFaces(); ++f) {
                        const IndexSpan verts = faces.verticesOfFace(f), values = refiner.fvarValuesOfFace(0, L, f);
                        for (int k = 0; k < verts.size(); ++k)
                            for (int a = 0; a < 2; ++a)
                                worst = std::max(worst, std::fabs(double(uvs[L][2 * std::size_t(values[k]) + a]) -
                                                                  double(expected[2 * std::size_t(verts[k]) + a])));
                    }
                }
                EXPECT_LE(worst, 1e-5 * scale);
            }
    }
}

// Seams everywhere (OpenSubdiv's shapes' own UVs) under every scheme and option: every stencil
// of the per-level and factorized tables sums to 1, and the factorized table gives the values
// the per-level tables give.
TEST(FVar, TablesArePartitionsOfUnityAndFactorizeExactly) {
    for (const std::string name : {"osd/catmark_fan.obj", "osd/catmark_nonquads.obj", "osd/catmark_cube_creases1.obj",
                                   "osd/loop_cubes_semisharp.obj", "osd/catmark_torus.obj"}) {
        const io::ObjMesh mesh = io::readObj(meshPath(name));
        ASSERT_TRUE(mesh.hasUVs());
        for (Scheme scheme : schemesFor(mesh))
            for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
                SCOPED_TRACE(name + " " + toString(scheme) + " " + toString(fvar));
                Options options;
                options.scheme = scheme;
                options.fvarLinearInterpolation = fvar;
                FVarChannel channel;
                Refiner refiner(mesh.descriptor(channel), mesh.applyTags(options));
                refiner.refineUniform(3);
                EXPECT_EQ(refiner.numFVarValues(0, 0), mesh.numUVs());
                const auto uvs = evaluateChannelLevels(refiner, 0, mesh.uvs, 2);
                for (int L = 1; L <= 3; ++L) {
                    const StencilTable& table = refiner.fvarLevelStencils(0, L);
                    ASSERT_EQ(table.numStencils(), refiner.numFVarValues(0, L));
                    EXPECT_EQ(table.numSourceVertices, refiner.numFVarValues(0, L - 1));
                    const StencilTable factorized = refiner.fvarFactorizedStencils(0, L);
                    ASSERT_EQ(factorized.numStencils(), table.numStencils());
                    EXPECT_EQ(factorized.numSourceVertices, mesh.numUVs());
                    double worstSum = 0;
                    for (int i = 0; i < table.numStencils(); ++i) {
                        worstSum = std::max(worstSum, std::fabs(stencilWeightSum(table, i) - 1.0));
                        worstSum = std::max(worstSum, std::fabs(stencilWeightSum(factorized, i) - 1.0));
                    }
                    EXPECT_LE(worstSum, 1e-6);
                    std::vector<float> direct(std::size_t(factorized.numStencils()) * 2);
                    CpuEvaluator::EvalStencils(mesh.uvs.data(), BufferDescriptor(0, 2, 2), direct.data(),
                                               BufferDescriptor(0, 2, 2), factorized);
                    double worst = 0;
                    for (std::size_t i = 0; i < direct.size(); ++i)
                        worst = std::max(worst, std::fabs(double(direct[i]) - double(uvs[L][i])));
                    EXPECT_LE(worst, 1e-5);
                    const LevelFaces faces = refiner.faces(L);
                    const IndexSpan all = refiner.fvarValues(0, L);
                    ASSERT_EQ(all.size(), faces.numCorners());
                    for (int f = 0; f < faces.numFaces(); ++f) {
                        const IndexSpan values = refiner.fvarValuesOfFace(0, L, f);
                        ASSERT_EQ(values.begin(), all.begin() + faces.offsets()[f]);
                        for (int value : values) ASSERT_TRUE(value >= 0 && value < table.numStencils());
                    }
                }
            }
    }
}

// A 4 x 2 strip: quads on the left (x < 2), triangles on the right, so the tri/quad seam is the
// line x = 2; the UVs are two charts, the bottom row (y < 1) and the top row, so the UV seam is
// the line y = 1, crossing the tri/quad seam at (2, 1). Every refined value belongs to one side
// of the UV seam: its stencil over the control values reads only that side's values, the side of
// the faces it is a corner of.
TEST(FVar, UVSeamAcrossTheTriQuadSeamKeepsEachSideToItself) {
    std::vector<float> positions;
    for (int y = 0; y <= 2; ++y)
        for (int x = 0; x <= 4; ++x) positions.insert(positions.end(), {float(x), float(y), 0.1f * float(x * y)});
    auto id = [](int x, int y) { return y * 5 + x; };
    std::vector<int> sizes, verts, uvIndex;
    // Values: the bottom chart has one value per vertex of rows 0-1, the top chart one per vertex
    // of rows 1-2 (row 1 twice: the seam).
    auto value = [&](int x, int y, bool top) { return top ? 15 + (y - 1) * 5 + x : y * 5 + x; };
    for (int y = 0; y < 2; ++y) {
        const bool top = y == 1;
        for (int x = 0; x < 4; ++x) {
            const int a = id(x, y), b = id(x + 1, y), c = id(x + 1, y + 1), d = id(x, y + 1);
            const int va = value(x, y, top), vb = value(x + 1, y, top), vc = value(x + 1, y + 1, top),
                      vd = value(x, y + 1, top);
            if (x < 2) {
                sizes.push_back(4);
                verts.insert(verts.end(), {a, b, c, d});
                uvIndex.insert(uvIndex.end(), {va, vb, vc, vd});
            } else {
                sizes.insert(sizes.end(), {3, 3});
                verts.insert(verts.end(), {a, b, c, a, c, d});
                uvIndex.insert(uvIndex.end(), {va, vb, vc, va, vc, vd});
            }
        }
    }
    const int numValues = 25;
    auto topValue = [](int v) { return v >= 15; };
    const FVarChannel channel{numValues, uvIndex.data()};
    TopologyDescriptor desc = descriptorOf(15, sizes, verts);
    desc.numFVarChannels = 1;
    desc.fvarChannels = &channel;
    for (Scheme scheme : {Scheme::SchaeferWarren, Scheme::StamLoop, Scheme::CatmarkButterfly, Scheme::CatmullClark})
        for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
            SCOPED_TRACE(std::string(toString(scheme)) + " " + toString(fvar));
            Options options;
            options.scheme = scheme;
            options.fvarLinearInterpolation = fvar;
            Refiner refiner(desc, options);
            refiner.refineUniform(3);
            // Each face's side is its control face's: child faces follow their parent's, in order.
            std::vector<char> side;
            for (int y = 0; y < 2; ++y)
                for (int x = 0; x < 4; ++x) side.insert(side.end(), x < 2 ? 1 : 2, char(y == 1));
            for (int L = 1; L <= 3; ++L) {
                const LevelFaces parents = refiner.faces(L - 1), faces = refiner.faces(L);
                std::vector<char> childSide;
                for (int f = 0; f < parents.numFaces(); ++f) {
                    const int n = parents.faceSize(f);
                    const int children = n == 3 && scheme != Scheme::CatmullClark ? 4 : n;
                    childSide.insert(childSide.end(), children, side[std::size_t(f)]);
                }
                ASSERT_EQ(int(childSide.size()), faces.numFaces());
                side = std::move(childSide);
                const StencilTable table = refiner.fvarFactorizedStencils(0, L);
                int crossing = 0;
                for (int f = 0; f < faces.numFaces(); ++f)
                    for (int value : refiner.fvarValuesOfFace(0, L, f))
                        for (int k = table.offsets[value]; k < table.offsets[value + 1]; ++k)
                            if (topValue(table.indices[std::size_t(k)]) != bool(side[std::size_t(f)])) ++crossing;
                EXPECT_EQ(crossing, 0) << "level " << L << ": values read the other side of the UV seam";
            }
            // The child of the crossing vertex (2, 1) has a value on each side.
            const Topology& level0 = refiner.level(0);
            int facePoints = 0;
            for (int f = 0; f < level0.numFaces(); ++f)
                facePoints += level0.faceSize(f) != 3 || scheme == Scheme::CatmullClark ? 1 : 0;
            const int crossingChild = facePoints + level0.numEdges() + id(2, 1);
            const StencilTable level1 = refiner.fvarFactorizedStencils(0, 1);
            std::set<int> sources;
            const LevelFaces faces = refiner.faces(1);
            for (int f = 0; f < faces.numFaces(); ++f)
                for (int k = 0; k < faces.faceSize(f); ++k) {
                    if (faces.verticesOfFace(f)[k] != crossingChild) continue;
                    const int value = refiner.fvarValuesOfFace(0, 1, f)[k];
                    for (int e = level1.offsets[value]; e < level1.offsets[value + 1]; ++e)
                        sources.insert(topValue(level1.indices[std::size_t(e)]));
                }
            EXPECT_EQ(sources.size(), 2u) << "both sides have values at the crossing";
        }
}

TEST(FVar, TwoChannelsRefineIndependently) {
    const io::ObjMesh mesh = io::readObj(meshPath("osd/catmark_fan.obj"));
    const FVarChannel channels[2] = {{mesh.numUVs(), mesh.faceUVs.data()}, {mesh.numVertices(), mesh.faceVerts.data()}};
    TopologyDescriptor desc = mesh.descriptor();
    desc.numFVarChannels = 2;
    desc.fvarChannels = channels;
    Refiner both(desc, mesh.applyTags(Options()));
    FVarChannel one;
    Refiner first(mesh.descriptor(one), mesh.applyTags(Options()));
    both.refineUniform(2);
    first.refineUniform(2);
    ASSERT_EQ(both.numFVarChannels(), 2);
    for (int L = 1; L <= 2; ++L) {
        EXPECT_EQ(both.fvarLevelStencils(0, L).indices, first.fvarLevelStencils(0, L).indices);
        EXPECT_EQ(both.fvarLevelStencils(0, L).weights, first.fvarLevelStencils(0, L).weights);
        // One value per vertex: the channel's values are the vertices'.
        EXPECT_EQ(both.numFVarValues(1, L), both.faces(L).numVertices());
    }
    EXPECT_THROW(both.fvarLevelStencils(2, 1), TopologyError);
    EXPECT_THROW(both.fvarLevelStencils(0, 3), TopologyError);
    EXPECT_THROW(both.fvarValuesOfFace(0, 1, both.faces(1).numFaces()), TopologyError);
}

// Left-handed input stores each face with its first corner kept and the rest reversed: the
// channel's values follow, so the mirror of a mesh given left-handed refines to the same tables.
TEST(FVar, LeftHandedValuesFollowTheirCorners) {
    const io::ObjMesh mesh = io::readObj(meshPath("osd/catmark_fan.obj"));
    std::vector<int> verts = mesh.faceVerts, values = mesh.faceUVs;
    for (int f = 0, b = 0; f < mesh.numFaces(); b += mesh.faceSizes[f++]) {
        std::reverse(verts.begin() + b + 1, verts.begin() + b + mesh.faceSizes[f]);
        std::reverse(values.begin() + b + 1, values.begin() + b + mesh.faceSizes[f]);
    }
    FVarChannel right;
    const FVarChannel left{mesh.numUVs(), values.data()};
    TopologyDescriptor mirrored = mesh.descriptor();
    mirrored.faceVertIndices = verts.data();
    mirrored.numFVarChannels = 1;
    mirrored.fvarChannels = &left;
    Options leftHanded = mesh.applyTags(Options());
    leftHanded.leftHanded = true;
    Refiner a(mesh.descriptor(right), mesh.applyTags(Options())), b(mirrored, leftHanded);
    a.refineUniform(2);
    b.refineUniform(2);
    for (int L = 1; L <= 2; ++L) {
        EXPECT_EQ(a.fvarLevelStencils(0, L).indices, b.fvarLevelStencils(0, L).indices);
        for (int f = 0; f < a.faces(L).numFaces(); ++f) {
            const IndexSpan x = a.fvarValuesOfFace(0, L, f), y = b.fvarValuesOfFace(0, L, f);
            EXPECT_TRUE(std::equal(x.begin(), x.end(), y.begin(), y.end()));
        }
    }
}

// What a bad channel is refused with: a TopologyError naming the face where there is one.
TEST(FVar, BadChannelsAreRefused) {
    const std::vector<int> sizes{4, 4}, verts{0, 1, 2, 3, 1, 4, 5, 2};
    auto refuse = [&](const std::vector<int>& values, int numValues) -> TopologyError {
        const FVarChannel channel{numValues, values.empty() ? nullptr : values.data()};
        TopologyDescriptor desc = descriptorOf(6, sizes, verts);
        desc.numFVarChannels = 1;
        desc.fvarChannels = &channel;
        try {
            Refiner refiner(desc, Options());
        } catch (const TopologyError& e) {
            return e;
        }
        ADD_FAILURE() << "accepted";
        return TopologyError("");
    };
    const TopologyError range = refuse({0, 1, 2, 3, 1, 4, 9, 2}, 6);
    EXPECT_EQ(range.component(), TopologyDiagnostic::Component::Face);
    EXPECT_EQ(range.index(), 1);
    EXPECT_STREQ(range.what(), "face 1: face-varying channel 0: value index 9 is out of range [0, 6)");
    EXPECT_STREQ(refuse({0, 1, 2, 3, 1, 4, -1, 2}, 6).what(),
                 "face 1: face-varying channel 0: value index -1 is out of range [0, 6)");
    EXPECT_STREQ(refuse({}, 6).what(), "face-varying channel 0: valueIndices is null");
    EXPECT_STREQ(refuse({0, 0, 0, 0, 0, 0, 0, 0}, -1).what(), "face-varying channel 0: numValues is negative (-1)");
    TopologyDescriptor noArray = descriptorOf(6, sizes, verts);
    noArray.numFVarChannels = 1;
    EXPECT_THROW(Refiner(noArray, Options()), TopologyError);

}

// A face that repeats a vertex is read as its loops in a channel too (docs/face_varying.md), each
// kept corner with the value of the input corner it comes from: the first of a collapsed edge's
// corners going around the face, and at a bow tie's knot the corner where the walk leaves it for
// each loop. Catmull-clark keeps a face whose only repeats are collapsed edges as it is, values too.
TEST(FVar, FacesThatRepeatAVertexTakeTheirLoopsValues) {
    struct Case {
        std::vector<int> verts;
        Scheme scheme;
        std::vector<std::vector<int>> faceValues;  // level 0's faces' values (value k is corner k's)
    };
    const std::vector<Case> cases{
        {{0, 1, 2, 2}, Scheme::Bilinear, {{0, 1, 2}}},
        {{2, 0, 1, 2}, Scheme::SchaeferWarren, {{1, 2, 3}}},
        {{0, 1, 1, 2}, Scheme::CatmarkButterfly, {{0, 1, 3}}},
        {{0, 1, 2, 0, 3, 4}, Scheme::Bilinear, {{0, 1, 2}, {3, 4, 5}}},
        {{0, 1, 2, 0, 0, 3, 4}, Scheme::StamLoop, {{0, 1, 2}, {3, 5, 6}}},
        {{0, 1, 2, 0, 3, 4}, Scheme::CatmullClark, {{0, 1, 2}, {3, 4, 5}}},
        {{0, 1, 2, 2}, Scheme::CatmullClark, {{0, 1, 2, 3}}},
        {{2, 0, 1, 2}, Scheme::CatmullClark, {{0, 1, 2, 3}}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(toString(c.scheme)) + " face " + std::to_string(c.verts[0]) + "..." +
                     std::to_string(c.verts.size()));
        const std::vector<int> sizes{int(c.verts.size())};
        std::vector<int> values(c.verts.size());
        for (std::size_t k = 0; k < values.size(); ++k) values[k] = int(k);
        const FVarChannel channel{int(values.size()), values.data()};
        TopologyDescriptor desc = descriptorOf(5, sizes, c.verts);
        desc.numFVarChannels = 1;
        desc.fvarChannels = &channel;
        for (bool leftHanded : {false, true}) {
            Options options;
            options.scheme = c.scheme;
            options.leftHanded = leftHanded;
            Refiner refiner(desc, options);
            ASSERT_EQ(refiner.faces(0).numFaces(), int(c.faceValues.size()));
            for (int f = 0; f < int(c.faceValues.size()); ++f) {
                // Left-handed faces are stored with their first corner kept and the rest reversed.
                std::vector<int> expected = c.faceValues[std::size_t(f)];
                if (leftHanded) std::reverse(expected.begin() + 1, expected.end());
                const IndexSpan got = refiner.fvarValuesOfFace(0, 0, f);
                EXPECT_EQ(std::vector<int>(got.begin(), got.end()), expected) << "face " << f << (leftHanded ? " left-handed" : "");
            }
            refiner.refineUniform(2);
            for (int L = 1; L <= 2; ++L) {
                const StencilTable& table = refiner.fvarLevelStencils(0, L);
                for (int i = 0; i < table.numStencils(); ++i) EXPECT_NEAR(stencilWeightSum(table, i), 1.0, 1e-6);
            }
        }
    }
}

// Collapsed quads at a pole and bow ties under a channel with one value per vertex (no seam): the
// refined values are the positions' linear map, corner by corner, under every scheme that takes
// quads, with the values kept linear nowhere (None) and as OpenSubdiv's default (CornersPlus1).
TEST(FVar, LinearMapThroughFacesThatRepeatAVertex) {
    io::ObjMesh pole = io::readObj(meshPath("osd/catmark_nonman_quadpole8.obj"));
    // A 2 x 2 grid of quads whose other two quads are one bow tie knotted at the middle vertex.
    io::ObjMesh bowTie;
    bowTie.positions = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0.5f, 2, 1, 0, 0, 2, 0, 1, 2, 0, 2, 2, 0};
    bowTie.faceSizes = {4, 4, 8};
    bowTie.faceVerts = {0, 1, 4, 3, 4, 5, 8, 7, 4, 1, 2, 5, 4, 7, 6, 3};
    for (const io::ObjMesh* mesh : {&pole, &bowTie}) {
        const FVarChannel channel{mesh->numVertices(), mesh->faceVerts.data()};
        const std::vector<float> control = linearUVs(mesh->positions);
        for (Scheme scheme : allSchemes())
            for (FVarLinearInterpolation fvar : {FVarLinearInterpolation::None, FVarLinearInterpolation::CornersPlus1}) {
                if (scheme == Scheme::Loop) continue;
                SCOPED_TRACE(std::string(mesh == &pole ? "pole " : "bow tie ") + toString(scheme) + " " + toString(fvar));
                Options options;
                options.scheme = scheme;
                options.fvarLinearInterpolation = fvar;
                options.boundary = BoundaryInterpolation::EdgeAndCorner;
                TopologyDescriptor desc = mesh->descriptor();
                desc.numFVarChannels = 1;
                desc.fvarChannels = &channel;
                Refiner refiner(desc, options);
                refiner.refineUniform(3);
                const auto positions = evaluateLevels(refiner, mesh->positions, 3);
                const auto uvs = evaluateChannelLevels(refiner, 0, control, 2);
                double worst = 0;
                for (int L = 1; L <= 3; ++L) {
                    const std::vector<float> expected = linearUVs(positions[L]);
                    const LevelFaces faces = refiner.faces(L);
                    for (int f = 0; f < faces.numFaces(); ++f) {
                        const IndexSpan verts = faces.verticesOfFace(f), values = refiner.fvarValuesOfFace(0, L, f);
                        for (int k = 0; k < verts.size(); ++k)
                            for (int a = 0; a < 2; ++a)
                                worst = std::max(worst, std::fabs(double(uvs[L][2 * std::size_t(values[k]) + a]) -
                                                                  double(expected[2 * std::size_t(verts[k]) + a])));
                    }
                }
                EXPECT_LE(worst, 1e-5);
            }
    }
}

// The OBJ reader's UVs as channel 0, and a channel error in the file's numbering.
TEST(FVar, ObjUVsBecomeChannelZero) {
    std::istringstream text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                            "f 1/1 2/2 3/3 4/4\n");
    const io::ObjMesh mesh = io::parseObj(text, "quad.obj");
    FVarChannel channel;
    Refiner refiner(mesh.descriptor(channel), Options());
    ASSERT_EQ(refiner.numFVarChannels(), 1);
    refiner.refineUniform(1);
    const auto uvs = evaluateChannelLevels(refiner, 0, mesh.uvs, 2);
    // A lone quad: its UV square's corners stay (corner values are sharp under CornersPlus1) and
    // its middle is the centre.
    const LevelFaces faces = refiner.faces(1);
    const IndexSpan values = refiner.fvarValuesOfFace(0, 1, 0);
    EXPECT_EQ(faces.faceSize(0), 4);
    EXPECT_FLOAT_EQ(uvs[1][2 * std::size_t(values[0])], 0.0f);
    EXPECT_FLOAT_EQ(uvs[1][2 * std::size_t(values[0]) + 1], 0.0f);
    EXPECT_FLOAT_EQ(uvs[1][2 * std::size_t(values[2])], 0.5f);
    EXPECT_FLOAT_EQ(uvs[1][2 * std::size_t(values[2]) + 1], 0.5f);

    // A collapsed edge in a face with UVs: the corners keep their own vt (catmull-clark keeps the
    // quad), the first of them where the scheme merges them.
    std::istringstream pinched("v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n\nf 1/1 2/2 3/3 3/2\n");
    const io::ObjMesh collapsed = io::parseObj(pinched, "pinched.obj");
    for (Scheme scheme : {Scheme::CatmullClark, Scheme::SchaeferWarren}) {
        Options options;
        options.scheme = scheme;
        Refiner r(collapsed.descriptor(channel), options);
        const IndexSpan got = r.fvarValuesOfFace(0, 0, 0);
        const std::vector<int> expected =
            scheme == Scheme::CatmullClark ? std::vector<int>{0, 1, 2, 1} : std::vector<int>{0, 1, 2};
        EXPECT_EQ(std::vector<int>(got.begin(), got.end()), expected);
        r.refineUniform(2);
        EXPECT_GT(r.numFVarValues(0, 2), 0);
    }
}

TEST(FVar, OptionNames) {
    ASSERT_EQ(allFVarLinearInterpolations().size(), 6u);
    for (FVarLinearInterpolation i : allFVarLinearInterpolations())
        EXPECT_EQ(fvarLinearInterpolationNamed(toString(i)), i);
    EXPECT_STREQ(toString(FVarLinearInterpolation::CornersPlus1), "corners-plus1");
    EXPECT_FALSE(fvarLinearInterpolationNamed("smooth").has_value());
    EXPECT_EQ(Options().fvarLinearInterpolation, FVarLinearInterpolation::CornersPlus1);
}

}  // namespace
}  // namespace quadtri::test
