// Shared helpers of the tests: mesh paths, refinement plus evaluation, geometry.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <quadtri/far/refiner.h>
#include "far/schemes/scheme.h"
#include "tools/obj_io.h"

namespace quadtri::test {

// The tests read the analyzer's internals (quadtri::internal) as well as its public API.
using namespace quadtri::internal;

// The registered schemes (allSchemes(), in registry order) whose rules satisfy `keep`: a test of
// "every scheme that ..." follows the registry, so a new scheme is tested without editing it.
template <typename Keep>
std::vector<Scheme> schemesWhere(Keep keep) {
    std::vector<Scheme> schemes;
    for (Scheme scheme : allSchemes())
        if (keep(rulesOf(scheme))) schemes.push_back(scheme);
    return schemes;
}
// Every scheme that takes quads (all but Loop).
inline std::vector<Scheme> schemesTakingQuads() {
    return schemesWhere([](const SchemeRules& rules) { return rules.acceptsNonTriangles(); });
}

// Absolute path of a mesh under tests/meshes, e.g. meshPath("osd/catmark_cube.obj").
std::string meshPath(const std::string& relative);

// A mesh from tests/meshes refined to `maxLevel` with the file's tags applied over `options`.
struct RefinedMesh {
    io::ObjMesh mesh;
    Options options;
    std::unique_ptr<Refiner> refiner;
    // positions[L]: 3 floats per vertex of level L, evaluated level by level with CpuEvaluator.
    std::vector<std::vector<float>> positions;
};
RefinedMesh refineMesh(const std::string& relative, int maxLevel, Options options = Options());

// Level-by-level evaluation of `width`-float data through the per-level tables.
std::vector<std::vector<float>> evaluateLevels(const Refiner& refiner, const std::vector<float>& control, int width);
// The same for face-varying channel `channel`'s values, through its per-level tables.
std::vector<std::vector<float>> evaluateChannelLevels(const Refiner& refiner, int channel,
                                                      const std::vector<float>& control, int width);

double boundingBoxDiagonal(const std::vector<float>& xyz);

// Sum of the weights of stencil i.
double stencilWeightSum(const StencilTable& table, int i);

// Every mesh of tests/meshes/osd and tests/meshes/mixed ("osd/catmark_cube.obj", ...), sorted.
std::vector<std::string> allMeshes();

// The message of the std::invalid_argument `call` throws, or "(no exception)".
std::string messageOf(const std::function<void()>& call);

// `text` with every character that is not a letter or digit replaced by '_' (a test name).
std::string testNameOf(std::string text);

// A descriptor over faces of the given sizes and corners (no tags); valid while `sizes` and
// `verts` live.
TopologyDescriptor descriptorOf(int numVertices, const std::vector<int>& sizes, const std::vector<int>& verts);
// `desc` with one crease of sharpness 2 along the edge from vertex 0 to vertex 1 (and no other).
TopologyDescriptor withOneCrease(TopologyDescriptor desc);

// Three stencils over four sources: 0.5 s0 + 0.5 s1, s3, 0.25 (s0 + s1 + s2 + s3).
StencilTable handCheckedTable();

// Float tables of smooth levels take the regular masks' short cut (far/schemes/regular_masks.h):
// checks (gtest EXPECTs) that levels 1-3 of `mesh` under `options` (the file's tags applied) are
// exactly the tables the rules build (the double table, rounded and interned).
void expectShortCutEqualsTheRules(const std::string& mesh, const Options& options);

// A level's face arrays as vectors, to compare levels with EXPECT_EQ.
inline std::vector<int> cornersOf(const LevelFaces& f) { return {f.vertices(), f.vertices() + f.numCorners()}; }
inline std::vector<int> offsetsOf(const LevelFaces& f) { return {f.offsets(), f.offsets() + f.numFaces() + 1}; }
inline std::vector<uint8_t> holesOf(const LevelFaces& f) { return {f.holes(), f.holes() + f.numFaces()}; }

}  // namespace quadtri::test
