#include "tests/surface/surface_support.h"

#include <algorithm>
#include <array>
#include <map>
#include <vector>

#include <quadtri/far/limit_surface.h>
#include "far/schemes/scheme.h"

namespace quadtri::test {

namespace {
using UV = std::array<double, 2>;
}  // namespace

void forEachDescendantCorner(const Refiner& r, int face, int L,
                             const std::function<void(int, int, double, double)>& visit) {
    const Scheme scheme = r.options().scheme;
    const bool inFour = FaceParameterization::of(scheme, 3).type == FaceParameterization::Type::Triangle;
    auto firstChild = [&](int level, int f) {
        const LevelFaces faces = r.faces(level);
        int first = 0;
        for (int g = 0; g < f; ++g) first += (faces.faceSize(g) == 3 && inFour) ? 4 : faces.faceSize(g);
        return first;
    };
    auto mid = [](UV a, UV b) { return UV{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2}; };
    std::function<void(int, int, std::vector<UV>)> walk = [&](int level, int f, std::vector<UV> c) {
        if (level == L) {
            for (int i = 0; i < int(c.size()); ++i) visit(f, i, c[i][0], c[i][1]);
            return;
        }
        const int first = firstChild(level, f), n = int(c.size());
        if (n == 4) {
            const UV centre = mid(mid(c[0], c[2]), mid(c[1], c[3]));
            for (int i = 0; i < 4; ++i)
                walk(level + 1, first + i, {c[i], mid(c[i], c[(i + 1) % 4]), centre, mid(c[(i + 3) % 4], c[i])});
        } else {
            for (int i = 0; i < 3; ++i)
                walk(level + 1, first + i, {c[i], mid(c[i], c[(i + 1) % 3]), mid(c[(i + 2) % 3], c[i])});
            walk(level + 1, first + 3, {mid(c[0], c[1]), mid(c[1], c[2]), mid(c[2], c[0])});
        }
    };
    const FaceParameterization p = FaceParameterization::of(scheme, r.faces(0).faceSize(face));
    std::vector<UV> corners(p.type == FaceParameterization::Type::QuadSubFaces ? 0 : p.faceSize);
    for (std::size_t i = 0; i < corners.size(); ++i) p.cornerCoord(int(i), corners[i][0], corners[i][1]);
    if (!corners.empty()) return walk(0, face, corners);
    if (L == 0) return;
    const int first = firstChild(0, face);
    for (int i = 0; i < p.faceSize; ++i) {
        const double x = i % p.gridWidth, y = i / p.gridWidth;
        walk(1, first + i, {{x, y}, {x + 0.5, y}, {x + 0.5, y + 0.5}, {x, y + 0.5}});
    }
}

bool exactUniformLimit(const Topology& t, int vertex) {
    auto exactSharpness = [](float s) { return s == 0.0f || s >= kInfiniteSharpness; };
    if (!exactSharpness(t.vertSharpness[vertex])) return false;
    int sharp = 0;
    for (int e : t.edgesOfVertex(vertex)) {
        if (!exactSharpness(t.edgeSharpness[e])) return false;
        if (t.edgeSharpness[e] != 0.0f || (t.edgeFlags[e] & kEdgeBoundary)) ++sharp;
    }
    return sharp != 1;
}

std::pair<double, double> randomPointOf(const FaceParameterization& p, int k, std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double u = unit(random), v = unit(random);
    if (p.type == FaceParameterization::Type::Triangle && u + v > 1) {
        u = 1 - u;
        v = 1 - v;
    } else if (p.type == FaceParameterization::Type::QuadSubFaces) {
        const int i = k % p.faceSize;
        u = i % p.gridWidth + 0.5 * u;
        v = i / p.gridWidth + 0.5 * v;
    }
    return {u, v};
}

void forEachMeshAndScheme(int levels, const std::function<void(const std::string&, Scheme, RefinedMesh&)>& visit) {
    for (const std::string& mesh : allMeshes())
        for (Scheme scheme : allSchemes()) {
            Options options;
            options.scheme = scheme;
            RefinedMesh r;
            try {
                r = refineMesh(mesh, levels, options);
            } catch (const TopologyError&) {
                continue;
            }
            visit(mesh, scheme, r);
        }
}

std::pair<LimitSurfaceOptions, LimitSurfaceOptions> narrowAndWiderCuts(Scheme scheme, int maxDepth) {
    const internal::SchemeRules& rules = internal::rulesOf(scheme);
    LimitSurfaceOptions narrow, wider;
    narrow.maxDepth = wider.maxDepth = maxDepth;
    wider.rings = std::max(rules.surfaceRings() + 1, rules.surfaceLimitRings());
    return {narrow, wider};
}

bool sameWeights(const LimitPointStencil& a, const LimitPointStencil& b) {
    auto byIndex = [](const LimitPointStencil& s) {
        std::map<int, std::array<double, 3>> out;
        for (int k = 0; k < s.size(); ++k)
            out[s.indices[std::size_t(k)]] = {s.position[std::size_t(k)], s.du[std::size_t(k)], s.dv[std::size_t(k)]};
        return out;
    };
    return a.size() == b.size() && byIndex(a) == byIndex(b);
}

}  // namespace quadtri::test
