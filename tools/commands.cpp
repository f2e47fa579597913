#include "tools/commands.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <vector>

#include <quadtri/far/draw_buffers.h>
#include <quadtri/far/limit_surface.h>
#include <quadtri/far/refiner.h>
#include <quadtri/far/tessellation.h>
#include <quadtri/osd/cpu_evaluator.h>
#include "tools/gltf_io.h"
#include "tools/obj_io.h"
#include "tools/vertex_cache.h"

namespace quadtri::cli {

io::ObjMesh loadMesh(const MeshArgs& args) {
    io::ObjMesh mesh = io::readObj(args.input);
    if (mesh.numFaces() == 0)
        throw io::ObjError(args.input + ": no faces to refine (" +
                           (mesh.numVertices() ? std::to_string(mesh.numVertices()) + " vertices and no f line"
                                               : std::string("no v or f line")) +
                           ")");
    for (const std::string& w : mesh.warnings) std::cerr << "quadtri: warning: " << w << "\n";
    return mesh;
}

// The analyzer over a file's mesh, with its UVs as face-varying channel 0 when the file has
// them; topology errors name the file line of the face or tag at fault.
Refiner makeRefiner(const io::ObjMesh& mesh, const Options& options) {
    try {
        FVarChannel uvs;
        Refiner refiner(mesh.descriptor(uvs), options);
        for (const TopologyDiagnostic& w : refiner.warnings()) std::cerr << "quadtri: warning: " << mesh.describe(w) << "\n";
        return refiner;
    } catch (const MemoryBudgetError&) {
        throw;  // main() says which flag to raise
    } catch (const TopologyError& e) {
        throw io::ObjError(mesh.describe(e.diagnostic()));
    }
}

// Finite input can still overflow: a scheme with weights of both signs sums terms larger than the
// result. The error names the vertex in the output file's numbering.
void checkFinite(const std::vector<float>& positions, const io::ObjMesh& mesh, int level, Scheme scheme) {
    const auto bad = std::find_if(positions.begin(), positions.end(), [](float x) { return !std::isfinite(x); });
    if (bad == positions.end()) return;
    float largest = 0;
    for (float x : mesh.positions) largest = std::max(largest, std::fabs(x));
    char text[256];
    std::snprintf(text, sizeof text,
                  ": level %d: output vertex %zu has coordinate %g; the input's largest coordinate magnitude, %g, "
                  "leaves no headroom for the %s weights (scale the mesh down)",
                  level, size_t(bad - positions.begin()) / 3 + 1, double(*bad), double(largest), toString(scheme));
    throw io::ObjError(mesh.name + text);
}

Options makeOptions(const MeshArgs& args, const io::ObjMesh& mesh) {
    Options base;
    if (args.scheme) base.scheme = *args.scheme;
    Options options = mesh.applyTags(base);
    if (args.smoothTriangles) options.smoothTriangles = true;  // the Refiner refuses it where the scheme has no such rule
    if (args.boundary) options.boundary = *args.boundary;
    if (args.creaseMethod) options.creaseMethod = *args.creaseMethod;
    if (args.uvInterpolation) options.fvarLinearInterpolation = *args.uvInterpolation;
    if (args.memoryBudget) options.memoryBudgetBytes = *args.memoryBudget;
    return options;
}

namespace {

int outputFaces(const LevelFaces& faces) { return faces.numFaces() - faces.numHoles(); }

template <typename T>
int countFlag(const std::vector<uint8_t>& flags, T flag) {
    return int(std::count_if(flags.begin(), flags.end(), [flag](uint8_t f) { return (f & flag) != 0; }));
}


// Boundary edges are infinitely sharp by rule; count the sharp edges the mesh asks for.
struct SharpEdges {
    int sharp = 0, infinite = 0;
};
SharpEdges countSharpEdges(const Topology& t) {
    SharpEdges count;
    for (int e = 0; e < t.numEdges(); ++e) {
        if (t.edgeFlags[e] & kEdgeBoundary) continue;
        count.sharp += t.edgeSharpness[e] > 0;
        count.infinite += t.edgeSharpness[e] >= kInfiniteSharpness;
    }
    return count;
}

void printBase(const Topology& t, const Options& options) {
    std::printf("scheme %s, boundary %s, crease method %s\n", toString(options.scheme), toString(options.boundary),
                toString(options.creaseMethod));
    std::printf("vertices %d, faces %d, edges %d, holes %d\n", t.numVertices, t.numFaces(), t.numEdges(),
                LevelFaces(t).numHoles());

    std::map<int, int> sizes;
    for (int f = 0; f < t.numFaces(); ++f) ++sizes[t.faceSize(f)];
    std::printf("face sizes:");
    for (auto [size, count] : sizes) std::printf(" %d-gon %d", size, count);
    std::printf("\n");

    SharpEdges sharp = countSharpEdges(t);
    std::printf("edges: boundary %d, non-manifold %d, seam %d, sharp non-boundary %d (infinite %d)\n",
                countFlag(t.edgeFlags, kEdgeBoundary), countFlag(t.edgeFlags, kEdgeNonManifold),
                countFlag(t.edgeFlags, kEdgeSeam), sharp.sharp, sharp.infinite);
    std::printf("vertices: boundary %d, non-manifold %d, seam %d, corner %d, sharp %d\n",
                countFlag(t.vertFlags, kVertexBoundary), countFlag(t.vertFlags, kVertexNonManifold),
                countFlag(t.vertFlags, kVertexSeam), countFlag(t.vertFlags, kVertexCorner),
                int(std::count_if(t.vertSharpness.begin(), t.vertSharpness.end(), [](float s) { return s > 0; })));

    // Vertex types by incident (quad-like, triangle) faces.
    std::map<std::pair<int, int>, int> types;
    for (int v = 0; v < t.numVertices; ++v) {
        VertexFaceCounts c = countVertexFaces(t, v);
        ++types[{c.quads, c.triangles}];
    }
    std::printf("vertex types (quads,triangles):");
    for (auto [type, count] : types) std::printf(" (%d,%d) %d", type.first, type.second, count);
    std::printf("\n");
}

// "face-varying channel 0 (uv): 14 values, ..." per channel, or that there are none.
void printChannels(const Refiner& refiner) {
    if (refiner.numFVarChannels() == 0) std::printf("no face-varying channels\n");
    for (int c = 0; c < refiner.numFVarChannels(); ++c) {
        const FVarSeams seams = countFVarSeams(refiner, c);
        std::printf("face-varying channel %d (uv): %d values, interpolation %s; seams: %d edges, %d vertices with "
                    "more than one value\n",
                    c, refiner.numFVarValues(c, 0), toString(refiner.options().fvarLinearInterpolation), seams.edges,
                    seams.vertices);
    }
}

// " 14 |" per channel: its number of values at level L.
std::string channelValues(const Refiner& refiner, int L) {
    std::string cells;
    for (int c = 0; c < refiner.numFVarChannels(); ++c) cells += " " + std::to_string(refiner.numFVarValues(c, L)) + " |";
    return cells;
}

}  // namespace

namespace {

// What draws the level in a glTF file: its draw buffers in vertex-cache order, positions and
// normals gathered into draw-vertex order, and UVs (`uvs.values` set) by the draw vertices' values.
io::TriangleMesh triangleMeshOf(const LevelFaces& faces, const Surface& surface, const io::ObjUVs& uvs) {
    DrawBuffers b = uvs.values ? buildDrawBuffers(faces, {uvs.cornerValues}, {uvs.numValues}) : buildDrawBuffers(faces);
    io::optimizeVertexCache(b);
    io::TriangleMesh m;
    m.triangles = b.triangles;
    for (int d = 0; d < b.numVertices(); ++d) {
        const std::size_t v = std::size_t(b.vertexOf[std::size_t(d)]);
        const float* p = surface.positions.data() + 3 * v;
        m.positions.insert(m.positions.end(), p, p + 3);
        if (!surface.normals.empty()) m.normals.insert(m.normals.end(), &surface.normals[3 * v], &surface.normals[3 * v] + 3);
        if (!uvs.values) continue;
        const float* uv = uvs.values + 2 * std::size_t(b.valueOf[0][std::size_t(d)]);
        m.uvs.insert(m.uvs.end(), uv, uv + 2);
    }
    return m;
}

}  // namespace

const std::vector<std::string>& renderShadings() {
    static const std::vector<std::string> names{"smooth", "flat", "reflection-lines", "mean-curvature", "face-type",
                                                "textured"};
    return names;
}

// Whether `output` names a glTF file (.gltf, .glb) rather than OBJ; an empty name or another
// extension is refused before any work.
bool writesGltf(const std::string& output) {
    if (output.empty()) throw io::ObjError("-o: the output file name is empty");
    std::string extension = std::filesystem::path(output).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    const bool gltf = extension == ".gltf" || extension == ".glb";
    if (!extension.empty() && extension != ".obj" && !gltf)
        throw io::ObjError(output + ": writes OBJ (.obj) or glTF (.gltf, .glb), not " + extension);
    return gltf;
}

int runRefine(const RefineArgs& args) {
    const bool gltf = writesGltf(args.output);
    io::ObjMesh mesh = loadMesh(args.mesh);
    const Options options = makeOptions(args.mesh, mesh);
    Refiner refiner = makeRefiner(mesh, options);
    refiner.refineUniform(args.level);
    // The positions and, where the file has them, the UVs (channel 0), level by level.
    std::vector<LevelData> data{positionLevels(refiner, args.level, mesh.positions)};
    const bool withUVs = refiner.numFVarChannels() > 0;
    if (withUVs) data.push_back(fvarLevels(refiner, 0, args.level, mesh.uvs, 2));
    std::vector<std::vector<float>> refined = evaluateLevels(args.evaluator, data);
    // glTF viewers shade with the file's normals: mesh normals unless asked otherwise.
    const NormalKind fallback = gltf ? NormalKind::Mesh : NormalKind::None;
    const NormalKind normals = args.normals.value_or(args.limit ? NormalKind::Limit : fallback);
    const Surface surface = evaluateSurface(args.evaluator, refiner, args.level, std::move(refined[0]), args.limit, normals);
    checkFinite(surface.positions, mesh, args.level, options.scheme);
    const LevelFaces faces = refiner.faces(args.level);
    io::ObjUVs uvs;
    if (withUVs) uvs = {refined[1].data(), refiner.numFVarValues(0, args.level), refiner.fvarValues(0, args.level).begin()};
    if (gltf)
        io::writeGltf(args.output, triangleMeshOf(faces, surface, uvs));
    else
        io::writeObj(args.output, surface.positions.data(), faces, surface.normals.empty() ? nullptr : surface.normals.data(),
                     uvs);
    std::printf("%s: level %d, %d vertices, %d faces -> %s\n", args.mesh.input.c_str(), args.level,
                faces.numVertices(), outputFaces(faces), args.output.c_str());
    return 0;
}

int runEvaluate(const EvaluateArgs& args) {
    io::ObjMesh mesh = loadMesh(args.mesh);
    const Options options = makeOptions(args.mesh, mesh);
    Refiner refiner = makeRefiner(mesh, options);
    const LimitSurface surface(refiner);
    if (args.uv && surface.numFVarChannels() == 0)
        throw io::ObjError(args.mesh.input + ": has no UVs (vt): --uv needs them");
    if (surface.numFaces() != mesh.numFaces())
        throw io::ObjError(args.mesh.input + ": a face repeats a vertex and was split or left out; " +
                           "evaluate needs the file's faces as they are");
    // Every line is read and checked before anything is evaluated or written.
    std::ifstream in(args.points);
    if (!in) throw io::ObjError(args.points + ": cannot be read");
    std::vector<int> faces;  // the points, 0-based faces
    std::vector<double> us, vs;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string where = args.points + ":" + std::to_string(number) + ": ";
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        std::istringstream fields(line);
        long long face = 0;
        double u = 0, v = 0;
        std::string rest;
        if (!(fields >> face >> u >> v) || (fields >> rest))
            throw io::ObjError(where + "expected 'face u v' (an integer and two numbers), got '" + line + "'");
        if (face < 1 || face > surface.numFaces())
            throw io::ObjError(where + "face " + std::to_string(face) + " is out of range: " + args.mesh.input + " has " +
                               std::to_string(surface.numFaces()) + " faces, numbered from 1");
        const int f = int(face - 1);
        const FaceParameterization p = surface.parameterization(f);
        if (surface.isHole(f)) throw io::ObjError(where + "face " + std::to_string(face) + " is a hole: it has no surface");
        if (!p.contains(u, v))
            throw io::ObjError(where + "(" + line.substr(first) + "): (u, v) is outside face " + std::to_string(face) +
                               "'s domain, " + p.describe());
        faces.push_back(f);
        us.push_back(u);
        vs.push_back(v);
    }
    // One limit table for all the points, evaluated as every limit table is (unit normals
    // included, with the evaluators' rule for degenerate tangents).
    const std::size_t n = faces.size();
    const LimitStencilTable table = surface.stencilTable(int(n), faces.data(), us.data(), vs.data());
    std::vector<float> position(3 * n), du(3 * n), dv(3 * n), normal(3 * n);
    const BufferDescriptor xyz(0, 3, 3);
    if (n > 0)
        CpuEvaluator::EvalLimitStencils(mesh.positions.data(), xyz, position.data(), xyz, du.data(), xyz, dv.data(), xyz,
                                        normal.data(), xyz, table);
    std::vector<float> uv;
    if (args.uv) {
        const LimitStencilTable uvTable = surface.fvarStencilTable(0, int(n), faces.data(), us.data(), vs.data());
        uv.resize(2 * n);
        const BufferDescriptor st(0, 2, 2);
        if (n > 0)
            CpuEvaluator::EvalLimitStencils(mesh.uvs.data(), st, uv.data(), st, nullptr, {}, nullptr, {}, nullptr, {},
                                            uvTable);
    }
    std::ostringstream text;
    text.precision(9);
    auto triple = [&text](const std::vector<float>& a, std::size_t i) {
        text << ' ' << a[3 * i] << ' ' << a[3 * i + 1] << ' ' << a[3 * i + 2];
    };
    for (std::size_t i = 0; i < n; ++i) {
        text << position[3 * i] << ' ' << position[3 * i + 1] << ' ' << position[3 * i + 2];
        triple(normal, i);
        if (args.derivatives) {
            triple(du, i);
            triple(dv, i);
        }
        if (args.uv) text << ' ' << uv[2 * i] << ' ' << uv[2 * i + 1];
        text << '\n';
    }
    if (args.output.empty()) {
        std::fputs(text.str().c_str(), stdout);
        return 0;
    }
    std::ofstream out(args.output);
    if (!(out << text.str()) || !out.flush()) {
        out.close();
        std::remove(args.output.c_str());
        throw io::ObjError(args.output + ": cannot be written");
    }
    std::fprintf(stderr, "%s: %zu points -> %s\n", args.mesh.input.c_str(), n, args.output.c_str());
    return 0;
}

int runTessellate(const TessellateArgs& args) {
    const bool gltf = writesGltf(args.output);
    io::ObjMesh mesh = loadMesh(args.mesh);
    const Options options = makeOptions(args.mesh, mesh);
    Refiner refiner = makeRefiner(mesh, options);
    const LimitSurface surface(refiner);
    const Tessellation tess(surface, args.rate);
    // The points in blocks, each block's limit table built, evaluated and dropped: memory stays
    // that of the points, whatever their number.
    const std::size_t n = std::size_t(tess.numPoints());
    Surface points;
    points.positions.resize(3 * n);
    points.normals.resize(3 * n);
    std::vector<float> du(3 * n), dv(3 * n);
    const BufferDescriptor xyz(0, 3, 3);
    constexpr int kBlock = 1 << 16;
    for (int first = 0; first < tess.numPoints(); first += kBlock) {
        const int count = std::min(kBlock, tess.numPoints() - first);
        const LimitStencilTable table = surface.stencilTable(count, tess.faces() + first, tess.u() + first, tess.v() + first);
        const std::size_t at = 3 * std::size_t(first);
        CpuEvaluator::EvalLimitStencils(mesh.positions.data(), xyz, &points.positions[at], xyz, &du[at], xyz, &dv[at], xyz,
                                        &points.normals[at], xyz, table);
    }
    checkFinite(points.positions, mesh, 0, options.scheme);
    // UVs per (point, value around it): a point on a UV seam is written once per side.
    Tessellation::FVarPoints uvPoints;
    std::vector<float> uvs;
    if (surface.numFVarChannels() > 0) {
        uvPoints = tess.fvarPoints(surface, 0);
        uvs.resize(2 * std::size_t(uvPoints.numValues()));
        const BufferDescriptor st(0, 2, 2);
        for (int first = 0; first < uvPoints.numValues(); first += kBlock) {
            const int count = std::min(kBlock, uvPoints.numValues() - first);
            const LimitStencilTable table = surface.fvarStencilTable(0, count, uvPoints.faces.data() + first,
                                                                     uvPoints.u.data() + first, uvPoints.v.data() + first);
            CpuEvaluator::EvalLimitStencils(mesh.uvs.data(), st, &uvs[2 * std::size_t(first)], st, nullptr, {}, nullptr,
                                            {}, nullptr, {}, table);
        }
    }
    const io::ObjUVs objUVs =
        uvs.empty() ? io::ObjUVs{} : io::ObjUVs{uvs.data(), uvPoints.numValues(), uvPoints.cornerValues.data()};
    Topology triangles;  // the index buffer as a mesh, to write as refine writes its levels
    triangles.numVertices = tess.numPoints();
    triangles.faceVerts = tess.triangles();
    triangles.faceOffsets.resize(std::size_t(tess.numTriangles()) + 1);
    for (int t = 0; t <= tess.numTriangles(); ++t) triangles.faceOffsets[std::size_t(t)] = 3 * t;
    const LevelFaces faces(triangles);
    if (gltf)
        io::writeGltf(args.output, triangleMeshOf(faces, points, objUVs));
    else
        io::writeObj(args.output, points.positions.data(), faces, points.normals.data(), objUVs);
    std::printf("%s: rate %d, %d points, %d triangles -> %s\n", args.mesh.input.c_str(), args.rate, tess.numPoints(),
                tess.numTriangles(), args.output.c_str());
    return 0;
}

int runInfo(const InfoArgs& args) {
    io::ObjMesh mesh = loadMesh(args.mesh);
    Options options = makeOptions(args.mesh, mesh);
    Refiner refiner = makeRefiner(mesh, options);
    std::printf("%s\n", args.mesh.input.c_str());
    printBase(refiner.level(0), options);

    printChannels(refiner);

    refiner.refineUniform(args.level, TopologyDetail::Full);  // the table counts sharp edges of every level
    // One column more per face-varying channel: its values at each level.
    std::string channelHeads, channelRule;
    for (int c = 0; c < refiner.numFVarChannels(); ++c) {
        channelHeads += " channel " + std::to_string(c) + " values |";
        channelRule += "---:|";
    }
    std::printf("\n| level | vertices | faces | sharp edges | stencils | level table bytes | factorized table bytes |%s\n",
                channelHeads.c_str());
    std::printf("|---:|---:|---:|---:|---:|---:|---:|%s\n", channelRule.c_str());
    for (int L = 0; L <= args.level; ++L) {
        const Topology& t = refiner.level(L);
        const int sharp = countSharpEdges(t).sharp;
        if (L == 0) {
            std::printf("| 0 | %d | %d | %d | - | - | - |%s\n", t.numVertices, outputFaces(LevelFaces(t)), sharp,
                        channelValues(refiner, 0).c_str());
            continue;
        }
        const StencilTable& perLevel = refiner.levelStencils(L);
        // A factorized table can be far larger than the per-level ones (near high-valence
        // vertices); one over the budget is reported, not fatal: refine does not need it.
        std::string factorized = "over the memory budget";
        try {
            factorized = std::to_string(refiner.factorizedStencils(L).bytes());
        } catch (const MemoryBudgetError&) {
        }
        std::printf("| %d | %d | %d | %d | %d | %zu | %s |%s\n", L, t.numVertices, outputFaces(LevelFaces(t)), sharp,
                    perLevel.numStencils(), perLevel.bytes(), factorized.c_str(), channelValues(refiner, L).c_str());
    }
    return 0;
}

}  // namespace quadtri::cli
