#include "tests/far/edit_support.h"

#include <iterator>

#include "far/schemes/crease.h"

namespace quadtri::test {

void addTags(io::ObjMesh& mesh, const TagEdits& edits) {
    for (std::size_t i = 0; i < edits.creaseWeights.size(); ++i) {
        mesh.creasePairs.push_back(edits.creaseVertexPairs[2 * i]);
        mesh.creasePairs.push_back(edits.creaseVertexPairs[2 * i + 1]);
        mesh.creaseSharpness.push_back(edits.creaseWeights[i]);
        mesh.creaseLines.push_back(0);
    }
    for (std::size_t i = 0; i < edits.cornerWeights.size(); ++i) {
        mesh.corners.push_back(edits.cornerVertices[i]);
        mesh.cornerSharpness.push_back(edits.cornerWeights[i]);
        mesh.cornerLines.push_back(0);
    }
    for (std::size_t i = 0; i < edits.holeFlags.size(); ++i) {
        const int f = edits.holeFaces[i];
        std::vector<int> holes;
        for (int h : mesh.holes)
            if (h != f) holes.push_back(h);
        if (edits.holeFlags[i]) holes.push_back(f);
        mesh.holes = holes;
    }
    mesh.holeLines.assign(mesh.holes.size(), 0);
}

std::unique_ptr<Refiner> build(const io::ObjMesh& mesh, const Options& options, int levels) {
    FVarChannel uvs;
    auto refiner = std::make_unique<Refiner>(mesh.hasUVs() ? mesh.descriptor(uvs) : mesh.descriptor(), options);
    refiner->refineUniform(levels, TopologyDetail::Full);
    return refiner;
}

Options optionsOf(const io::ObjMesh& mesh, Scheme scheme) {
    Options options;
    options.scheme = scheme;
    return mesh.applyTags(options);
}

std::unique_ptr<Refiner> buildIfTaken(const io::ObjMesh& mesh, Scheme scheme, int levels) {
    try {
        return build(mesh, optionsOf(mesh, scheme), levels);
    } catch (const TopologyError&) {
        return nullptr;
    }
}

namespace {

const float kSharpness[] = {0.0f, 0.4f, 1.0f, 1.6f, 2.5f, 3.0f, kInfiniteSharpness};

}  // namespace

TagEdits randomEdits(const Topology& level0, std::mt19937& random, bool holes) {
    TagEdits edits;
    auto pick = [&random](int n) { return std::uniform_int_distribution<int>(0, n - 1)(random); };
    auto sharpness = [&] { return kSharpness[pick(int(std::size(kSharpness)))]; };
    for (int k = pick(3) + 1; k > 0; --k) {
        const int e = pick(level0.numEdges());
        edits.setCrease(level0.edgeVerts[2 * std::size_t(e)], level0.edgeVerts[2 * std::size_t(e) + 1], sharpness());
    }
    if (pick(2)) edits.setCorner(pick(level0.numVertices), sharpness());
    if (holes && pick(3) == 0) edits.setHole(pick(level0.numFaces()), pick(2) == 0);
    return edits;
}

}  // namespace quadtri::test
