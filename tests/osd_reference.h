// OpenSubdiv as the reference for the agreement tests: uniform refinement of an ObjMesh with
// Far::TopologyRefiner + Far::PrimvarRefiner, and a position-based comparison of two vertex sets
// (OpenSubdiv orders refined vertices differently from quadtri, so vertices are matched by position).
// Used only by tests; the library never depends on OpenSubdiv.
#pragma once

#include <string>
#include <vector>

#include <quadtri/far/options.h>
#include "tests/position_match.h"
#include "tools/obj_io.h"

namespace quadtri::test {

// OpenSubdiv's subdivision scheme used as the reference (Sdc::SCHEME_*).
enum class OsdScheme { Catmark, Loop, Bilinear };

const char* toString(OsdScheme scheme);

// Connectivity of one OpenSubdiv level as plain arrays, and where its components' children went:
// enough to find, for a quadtri child vertex, the OpenSubdiv child of the same parent component.
struct OsdLevelTopology {
    std::vector<int> faceOffsets{0};  // faces: faceVerts[faceOffsets[f] .. faceOffsets[f+1])
    std::vector<int> faceVerts;
    std::vector<int> edgeVerts;       // 2 per edge
    std::vector<int> faceChild;       // child vertex in the next level (-1: none / last level)
    std::vector<int> edgeChild;
    std::vector<int> vertexChild;
    std::vector<float> edgeSharpness;
    std::vector<float> vertexSharpness;
    std::vector<int> vertexRule;      // Sdc::Crease::Rule: 0 unknown, 1 smooth, 2 dart, 4 crease, 8 corner
    std::vector<char> vertexBoundary;
    std::vector<char> vertexNonManifold;
    std::vector<char> edgeNonManifold;
    int numFaces() const { return int(faceOffsets.size()) - 1; }
    int numEdges() const { return int(edgeVerts.size() / 2); }
};

const char* vertexRuleName(int rule);

struct OsdRefinement {
    // positions[L]: 3 floats per vertex of level L, in OpenSubdiv's vertex order (level 0 = control).
    std::vector<std::vector<float>> positions;
    std::vector<int> numVertices;            // per level
    std::vector<int> numFaces;               // per level (hole faces included)
    std::vector<std::vector<char>> faceHole; // per level, per face: Far::TopologyLevel::IsFaceHole
    std::vector<OsdLevelTopology> topology;  // per level
    int numHoleFaces(int level) const;
};

// Refines `mesh` uniformly to `maxLevel` with OpenSubdiv (default refinement options) and
// interpolates positions level by level. Creases, corners and holes of the mesh are passed through
// the Far::TopologyDescriptor; `boundary`, `creaseMethod` and `smoothTriangles` (TRI_SUB_SMOOTH,
// else TRI_SUB_CATMARK) set the Sdc options (the mesh's own tags are NOT applied here: the caller
// resolves them). Throws std::runtime_error if OpenSubdiv refuses the topology.
OsdRefinement osdRefine(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                        CreaseMethod creaseMethod, int maxLevel, bool smoothTriangles = false);

// OpenSubdiv's limit at the vertices of one level: Far::PrimvarRefinerReal<double>::Limit with
// tangents (refinement and limit in double).
struct OsdLimit {
    std::vector<float> refined;    // level `level`'s vertices, 3 floats each, OpenSubdiv's order
    std::vector<double> position;  // their limit positions
    std::vector<double> du, dv;    // Limit's two tangents
    std::vector<int> vertexRule;  // per vertex, Sdc::Crease::Rule as in OsdLevelTopology
    std::vector<char> vertexNonManifold;
};

// Refines `mesh` to `level` as osdRefine does (isLeftHanded set as asked) and evaluates the limit
// there.
OsdLimit osdLimit(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                  CreaseMethod creaseMethod, int level, bool smoothTriangles = false, bool leftHanded = false);
// The same computed in float throughout (PrimvarRefinerReal<float>), as an engine running
// OpenSubdiv in float gets it: how much float data alone moves its limit.
OsdLimit osdLimitInFloat(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                         CreaseMethod creaseMethod, int level, bool smoothTriangles = false, bool leftHanded = false);

// OpenSubdiv's limit surface at points of base faces: Bfr::RefinerSurfaceFactory with both
// approximation levels (SetApproxLevelSmooth, SetApproxLevelSharp) at `approxLevel`, in double.
// Point i is (faces[i], uv[2i], uv[2i + 1]); a face without a limit surface (a hole) gets
// evaluated[i] = 0.
struct OsdSurfacePoints {
    std::vector<double> position, du, dv;  // 3 per point
    std::vector<char> evaluated;
};
OsdSurfacePoints osdSurfacePoints(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                                  CreaseMethod creaseMethod, int approxLevel, const std::vector<int>& faces,
                                  const std::vector<double>& uv, bool leftHanded = false);
// The same for the mesh's UVs (channel 0 from `vt`) under `fvar`: Bfr's face-varying surface
// (InitFaceVaryingSurface), 2 doubles per point in position, du and dv.
OsdSurfacePoints osdSurfaceUVs(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                               CreaseMethod creaseMethod, FVarLinearInterpolation fvar, int approxLevel,
                               const std::vector<int>& faces, const std::vector<double>& uv, bool leftHanded = false);

// OpenSubdiv's refined positions of one level (PrimvarRefiner::Interpolate) and its varying
// interpolation of the control positions there (InterpolateVarying), both in its vertex order.
struct OsdVarying {
    std::vector<float> refined;    // 3 floats per vertex
    std::vector<double> varying;   // 3 per vertex
};
OsdVarying osdVarying(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                      CreaseMethod creaseMethod, int level, bool smoothTriangles = false);

// OpenSubdiv's face-varying refinement of the mesh's UVs (channel 0 from `vt`), level by level
// with Far::PrimvarRefiner::InterpolateFaceVarying (float), under `fvar` (Sdc's
// FVarLinearInterpolation of the same name); positions refined too, to match faces by them.
struct OsdFaceVarying {
    std::vector<std::vector<float>> positions;    // per level, 3 floats per vertex
    std::vector<std::vector<int>> faceOffsets;    // per level: faceVerts[faceOffsets[f] .. faceOffsets[f + 1])
    std::vector<std::vector<int>> faceVerts;      // per level
    std::vector<std::vector<int>> faceValues;     // per level, parallel to faceVerts: the corner's value
    std::vector<std::vector<float>> uvs;          // per level, 2 floats per value
};
OsdFaceVarying osdFaceVarying(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                              CreaseMethod creaseMethod, FVarLinearInterpolation fvar, int maxLevel);

// OpenSubdiv's limit of the mesh's UVs at one level: refined to `level` as osdFaceVarying does
// but in double (PrimvarRefinerReal<double>: Interpolate, InterpolateFaceVarying), then
// LimitFaceVarying there.
struct OsdFaceVaryingLimit {
    std::vector<float> positions;                  // the level's vertices, 3 floats each
    std::vector<int> faceOffsets, faceVerts, faceValues;  // the level's faces, as in OsdFaceVarying
    std::vector<double> uvs;                       // the level's refined UVs, 2 per value
    std::vector<double> limit;                     // their limits, 2 per value
};
OsdFaceVaryingLimit osdFaceVaryingLimit(const io::ObjMesh& mesh, OsdScheme scheme, BoundaryInterpolation boundary,
                                        CreaseMethod creaseMethod, FVarLinearInterpolation fvar, int level);

}  // namespace quadtri::test
