#include "tools/render/surface_data.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace quadtri::render {

std::vector<int> rootFaces(const Refiner& refiner, int level) {
    std::vector<int> roots(std::size_t(refiner.faces(0).numFaces()));
    for (std::size_t f = 0; f < roots.size(); ++f) roots[f] = int(f);
    for (int L = 0; L < level; ++L) {
        const LevelFaces parent = refiner.faces(L), child = refiner.faces(L + 1);
        std::vector<int> next(std::size_t(child.numFaces()));
        int c = 0;
        for (int f = 0; f < parent.numFaces(); ++f) {
            const int n = parent.faceSize(f);
            // A triangle split in four has triangle children; split around a face point, quads.
            const int children = n == 3 && c < child.numFaces() && child.faceSize(c) == 3 ? 4 : n;
            for (int k = 0; k < children && c < child.numFaces(); ++k) next[std::size_t(c++)] = roots[std::size_t(f)];
        }
        roots.swap(next);
    }
    return roots;
}

std::vector<uint32_t> triangleOrigins(const LevelFaces& faces, const LevelFaces& controlFaces,
                                      const std::vector<int>& roots, const DrawBuffers& draw) {
    std::vector<uint32_t> origins;
    origins.reserve(std::size_t(draw.numTriangles()));
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        const int n = controlFaces.faceSize(roots[std::size_t(f)]);
        const uint32_t origin = n == 3 ? kFromTriangle : n == 4 ? kFromQuad : kFromOtherPolygon;
        for (int t = 0; t < faces.faceSize(f) - 2; ++t) origins.push_back(origin);
    }
    origins.resize(std::size_t(draw.numTriangles()), kFromOtherPolygon);
    return origins;
}

std::vector<float> meanCurvature(const LevelFaces& faces, const float* positions, const float* normals) {
    const std::size_t nv = std::size_t(faces.numVertices());
    std::vector<glm::dvec3> laplacian(nv, glm::dvec3(0.0));
    std::vector<double> area(nv, 0.0);
    auto at = [positions](int v) {
        return glm::dvec3(positions[3 * std::size_t(v)], positions[3 * std::size_t(v) + 1],
                          positions[3 * std::size_t(v) + 2]);
    };
    auto addTriangle = [&](int a, int b, int c, double weight) {
        const int v[3] = {a, b, c};
        const glm::dvec3 p[3] = {at(a), at(b), at(c)};
        const double twiceArea = glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
        const double cotScale = weight / twiceArea;
        if (twiceArea <= 0.0) return;
        for (int i = 0; i < 3; ++i) {
            // The angle at corner i weighs the opposite edge (j, k).
            const int j = (i + 1) % 3, k = (i + 2) % 3;
            const double cot = glm::dot(p[j] - p[i], p[k] - p[i]) * cotScale;
            laplacian[std::size_t(v[j])] += cot * (p[k] - p[j]);
            laplacian[std::size_t(v[k])] += cot * (p[j] - p[k]);
            area[std::size_t(v[i])] += weight * twiceArea / 6.0;
        }
    };
    // An edge whose reverse no face uses is on the boundary.
    std::vector<std::pair<int, int>> directed;
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        const IndexSpan c = faces.verticesOfFace(f);
        const int n = faces.faceSize(f);
        if (n == 4) {
            // Both diagonals, half each: one alone would print its direction into the curvature.
            for (int k = 0; k < 4; ++k) addTriangle(c[k], c[(k + 1) % 4], c[(k + 2) % 4], 0.5);
        } else {
            for (int t = 1; t + 1 < n; ++t) addTriangle(c[0], c[t], c[t + 1], 1.0);
        }
        for (int i = 0; i < n; ++i) directed.emplace_back(c[i], c[(i + 1) % n]);
    }
    std::sort(directed.begin(), directed.end());
    std::vector<uint8_t> boundary(nv, 0);
    for (const auto& [a, b] : directed)
        if (!std::binary_search(directed.begin(), directed.end(), std::make_pair(b, a)))
            boundary[std::size_t(a)] = boundary[std::size_t(b)] = 1;
    std::vector<float> h(nv, 0.0f);
    for (std::size_t v = 0; v < nv; ++v) {
        if (boundary[v] || area[v] <= 0.0) continue;
        const glm::dvec3 delta = laplacian[v] / (2.0 * area[v]);
        const glm::dvec3 n(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
        const double sign = glm::dot(delta, n) > 0.0 ? -1.0 : 1.0;
        h[v] = float(sign * glm::length(delta) / 2.0);
    }
    return h;
}

float curvatureRange(const std::vector<float>& curvature) {
    std::vector<float> magnitudes;
    magnitudes.reserve(curvature.size());
    for (float c : curvature)
        if (c != 0.0f && std::isfinite(c)) magnitudes.push_back(std::fabs(c));
    if (magnitudes.empty()) return 0.0f;
    const std::size_t k = std::min(magnitudes.size() - 1, magnitudes.size() * 95 / 100);
    std::nth_element(magnitudes.begin(), magnitudes.begin() + std::ptrdiff_t(k), magnitudes.end());
    return magnitudes[k];
}

glm::vec3 sharpnessColor(float s) {
    if (s <= 0.0f) return {0.30f, 0.30f, 0.30f};
    if (s >= kInfiniteSharpness) return {0.85f, 0.10f, 0.85f};
    const float t = std::min(s, 10.0f) / 10.0f;
    const glm::vec3 low(1.0f, 0.90f, 0.10f), mid(1.0f, 0.50f, 0.0f), high(0.80f, 0.0f, 0.0f);
    return t < 0.5f ? glm::mix(low, mid, t * 2.0f) : glm::mix(mid, high, t * 2.0f - 1.0f);
}

glm::vec3 selectedColor() { return {0.0f, 0.85f, 1.0f}; }

Cage cageOf(const Topology& level0, const float* positions, const std::vector<int>& selectedEdges,
            const std::vector<int>& selectedVertices) {
    Cage cage;
    cage.positions.assign(positions, positions + 3 * std::size_t(level0.numVertices));
    for (int e = 0; e < level0.numEdges(); ++e) {
        cage.edges.push_back(uint32_t(level0.edgeVerts[2 * std::size_t(e)]));
        cage.edges.push_back(uint32_t(level0.edgeVerts[2 * std::size_t(e) + 1]));
        const bool boundary = (level0.edgeFlags[std::size_t(e)] & kEdgeBoundary) != 0;
        cage.edgeColors.emplace_back(
            sharpnessColor(boundary ? kInfiniteSharpness : level0.edgeSharpness[std::size_t(e)]), 1.0f);
    }
    for (int v = 0; v < level0.numVertices; ++v) {
        const float s = std::size_t(v) < level0.vertSharpness.size() ? level0.vertSharpness[std::size_t(v)] : 0.0f;
        cage.pointColors.emplace_back(s > 0.0f ? sharpnessColor(s) : glm::vec3(0.15f, 0.80f, 0.30f), 1.0f);
    }
    for (int e : selectedEdges)
        if (e >= 0 && std::size_t(e) < cage.edgeColors.size())
            cage.edgeColors[std::size_t(e)] = glm::vec4(selectedColor(), 1.0f);
    for (int v : selectedVertices)
        if (v >= 0 && std::size_t(v) < cage.pointColors.size())
            cage.pointColors[std::size_t(v)] = glm::vec4(selectedColor(), 1.0f);
    return cage;
}

}  // namespace quadtri::render
