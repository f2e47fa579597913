// quadtri in one page: analyse a mixed quad/triangle mesh once (at load time), then evaluate its
// refined vertices (every frame, as the control points move). docs/getting_started.md walks
// through it. Built with the tools and run by ctest (`tutorial`).
#include <quadtri/quadtri.h>

#include <cstdio>
#include <vector>

int main() {
    // The control mesh as flat arrays, as engines keep it: xyz per vertex, the corner count of
    // each face, then every face's corners (counter-clockwise seen from outside). A square
    // pyramid: one quad and four triangles, so both the quad and the triangle rules run.
    const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 1};
    const std::vector<int> faceSizes = {4, 3, 3, 3, 3};
    std::vector<int> faceVerts = {0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};

    // The descriptor only points at the arrays: nothing is copied until the Refiner is built.
    // Creases, corners and holes are optional arrays of the same kind (left empty here).
    quadtri::TopologyDescriptor desc;
    desc.numVertices = int(positions.size() / 3);
    desc.numFaces = int(faceSizes.size());
    desc.numVertsPerFace = faceSizes.data();
    desc.faceVertIndices = faceVerts.data();

    // The scheme decides what happens where quads meet triangles: Schaefer-Warren (the default)
    // is smoothest across that seam; CatmarkButterfly keeps triangle vertices where they are.
    quadtri::Options options;
    options.scheme = quadtri::Scheme::SchaeferWarren;

    // Validation comes first, so bad input fails here, before any work, naming the face.
    quadtri::Refiner refiner(desc, options);
    const int level = 2;
    // The last level keeps only its faces (what drawing needs); ask for TopologyDetail::Full
    // as a second argument to read its edges and incidences with refiner.level(2) too.
    refiner.refineUniform(level);

    // Two kinds of tables. Per level (refiner.levelStencils(l): level l from level l-1) gives
    // every level, for levels of detail. Factorized gives level 2 straight from the control
    // points: one pass per frame, which is what this program wants.
    const quadtri::StencilTable table = refiner.factorizedStencils(level);

    // Evaluation is a sparse matrix times the control data. The BufferDescriptor (offset, floats
    // per vertex, stride) says where each vertex's floats are, so UVs or colours, interleaved or
    // not, go through the same table.
    const quadtri::BufferDescriptor xyz(0, 3, 3);
    std::vector<float> refined(3 * std::size_t(table.numStencils()));
    quadtri::CpuEvaluator::EvalStencils(positions.data(), xyz, refined.data(), xyz, table);
    // The same call on oneTBB's threads, bit for bit the same; it pays off past a few thousand stencils.
    quadtri::TbbEvaluator::EvalStencils(positions.data(), xyz, refined.data(), xyz, table);

    // To draw: level 2's faces index `refined`. Triangles stay triangles and quads split into
    // two; hole faces (none here) are skipped.
    const quadtri::LevelFaces faces = refiner.faces(level);
    std::vector<int> triangles;
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        const quadtri::IndexSpan v = faces.verticesOfFace(f);
        for (int k = 2; k < v.size(); ++k) triangles.insert(triangles.end(), {v[0], v[k - 1], v[k]});
    }
    std::printf("level %d: %d vertices, %zu triangles to draw; vertex 0 at (%.3f %.3f %.3f)\n", level,
                table.numStencils(), triangles.size() / 3, refined[0], refined[1], refined[2]);

    // Bad input throws quadtri::TopologyError; what() counts from 0. diagnostic() names the item
    // by its index in your arrays, so a file reader can report it in the file's own numbering.
    faceVerts[4] = 9;  // the second face's first corner: there is no vertex 9
    try {
        quadtri::Refiner broken(desc, options);
        return 1;  // not reached: the mesh is refused
    } catch (const quadtri::TopologyError& e) {
        const quadtri::TopologyDiagnostic& d = e.diagnostic();
        std::printf("refused: %s\n", e.what());
        if (d.component == quadtri::TopologyDiagnostic::Component::Face)
            std::printf("in an OBJ file's 1-based numbering: face %d\n", d.index + 1);
    }
    return 0;
}
