#include "far/edit/tag_changes.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <string>
#include <utility>

#include "far/schemes/crease.h"
#include "far/topology/topology_builder.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

using Component = TopologyDiagnostic::Component;

void checkSharpness(float s, Component component, int index) {
    if (!std::isfinite(s)) throw TopologyError({component, index, -1, "sharpness is not a finite number"});
    if (s < 0.0f) throw TopologyError({component, index, -1, "negative sharpness " + std::to_string(s)});
}

// The items' tags set to what `tagOf` rules, those that end up different listed.
template <class Value, class Rule>
std::vector<int> setTags(std::vector<int> items, std::vector<Value>& tags, Rule&& tagOf) {
    sortUnique(items);
    std::vector<std::pair<int, Value>> before;
    before.reserve(items.size());
    for (int i : items) before.emplace_back(i, tags[std::size_t(i)]);
    std::vector<int> changed;
    for (const auto& [i, old] : before) {
        tags[std::size_t(i)] = tagOf(i);
        if (tags[std::size_t(i)] != old) changed.push_back(i);
    }
    return changed;
}

}  // namespace

void sortUnique(std::vector<int>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

std::vector<int> facesAt(const Topology& t, const std::vector<int>& vertices) {
    std::vector<int> faces;
    for (int v : vertices)
        for (int f : t.facesOfVertex(v)) faces.push_back(f);
    sortUnique(faces);
    return faces;
}

std::vector<int> verticesOf(const Topology& t, const std::vector<int>& faces) {
    std::vector<int> vertices;
    for (int f : faces)
        for (int v : t.verticesOfFace(f)) vertices.push_back(v);
    sortUnique(vertices);
    return vertices;
}

void checkEdits(const Topology& t, const TagEdits& edits) {
    const int nv = t.numVertices;
    auto vertexName = [nv](int v) {
        return "vertex " + std::to_string(v) + " is out of range (level 0 has " + std::to_string(nv) + " vertices)";
    };
    for (std::size_t i = 0; i < edits.creaseWeights.size(); ++i) {
        const int a = edits.creaseVertexPairs[2 * i], b = edits.creaseVertexPairs[2 * i + 1];
        for (int v : {a, b})
            if (v < 0 || v >= nv) throw TopologyError({Component::Crease, int(i), -1, vertexName(v)});
        if (findEdge(t, a, b) < 0)
            throw TopologyError(
                {Component::Crease, int(i), -1,
                 "vertices " + std::to_string(a) + ", " + std::to_string(b) + " are not an edge of level 0"});
        checkSharpness(edits.creaseWeights[i], Component::Crease, int(i));
    }
    for (std::size_t i = 0; i < edits.cornerWeights.size(); ++i) {
        const int v = edits.cornerVertices[i];
        if (v < 0 || v >= nv) throw TopologyError({Component::Corner, int(i), -1, vertexName(v)});
        checkSharpness(edits.cornerWeights[i], Component::Corner, int(i));
    }
    for (std::size_t i = 0; i < edits.holeFlags.size(); ++i) {
        const int f = edits.holeFaces[i];
        if (f < 0 || f >= t.numFaces())
            throw TopologyError({Component::Hole, int(i), -1,
                                 "face " + std::to_string(f) + " is out of range (level 0 has " +
                                     std::to_string(t.numFaces()) + " faces)"});
    }
}

ChangedTags applyToLevel0(Topology& t, const TagEdits& edits, const Options& options,
                          std::vector<std::uint8_t>& givenHoles) {
    ChangedTags changed;
    // The last setting of an item wins.
    std::map<int, float> edgeSettings, vertexSettings;
    for (std::size_t i = 0; i < edits.creaseWeights.size(); ++i)
        edgeSettings[findEdge(t, edits.creaseVertexPairs[2 * i], edits.creaseVertexPairs[2 * i + 1])] =
            edits.creaseWeights[i];
    for (std::size_t i = 0; i < edits.cornerWeights.size(); ++i)
        vertexSettings[edits.cornerVertices[i]] = edits.cornerWeights[i];
    auto itemsOf = [](const std::map<int, float>& settings) {
        std::vector<int> items;
        for (const auto& entry : settings) items.push_back(entry.first);
        return items;
    };
    changed.edges = setTags(itemsOf(edgeSettings), t.edgeSharpness,
                            [&](int e) { return ruledEdgeSharpness(t, e, edgeSettings.at(e)); });
    changed.vertices = setTags(itemsOf(vertexSettings), t.vertSharpness,
                               [&](int v) { return ruledVertexSharpness(t, v, options, vertexSettings.at(v)); });
    // Holes: those asked for, and under BoundaryInterpolation::None those of the faces at a
    // boundary vertex whose sharpness changed.
    std::vector<int> faces;
    for (std::size_t i = 0; i < edits.holeFlags.size(); ++i) {
        givenHoles[std::size_t(edits.holeFaces[i])] = edits.holeFlags[i] ? 1 : 0;
        faces.push_back(edits.holeFaces[i]);
    }
    if (options.boundary == BoundaryInterpolation::None)
        for (int v : changed.vertices)
            for (int f : t.facesOfVertex(v)) faces.push_back(f);
    changed.faces = setTags(faces, t.faceHole, [&](int f) {
        return std::uint8_t(ruledHole(t, f, options, givenHoles[std::size_t(f)] != 0) ? 1 : 0);
    });
    return changed;
}

ChangedTags passOn(const Topology& p, const ChildNumbering& num, const ChangedTags& changed, CreaseMethod creaseMethod,
                   Topology& c) {
    ChangedTags out;
    const bool withSharpness = c.edgeSharpness.size() == std::size_t(c.numEdges()) && c.numEdges() > 0 &&
                               c.vertSharpness.size() == std::size_t(c.numVertices);
    if (withSharpness && changed.sharpness()) {
        std::vector<int> vertices = changed.vertices;
        for (int e : changed.edges)
            vertices.push_back(p.edgeVerts[2 * std::size_t(e)]),
                vertices.push_back(p.edgeVerts[2 * std::size_t(e) + 1]);
        sortUnique(vertices);
        std::vector<float> scratch, before;
        for (int v : vertices) {
            const int vertexPoint = num.vertexPoint(v);
            const IndexSpan edges = p.edgesOfVertex(v);
            // The halves at v: 2e at edgeVerts[2e], 2e + 1 at the other end (a collapsed edge: both).
            auto halves = [&](auto&& each) {
                for (int e : edges) {
                    each(2 * e);
                    each(2 * e + 1);
                }
            };
            before.clear();
            halves([&](int h) { before.push_back(c.edgeSharpness[std::size_t(h)]); });
            const float vertexBefore = c.vertSharpness[std::size_t(vertexPoint)];
            inheritSharpnessAt(p, num, creaseMethod, v, c, scratch);
            std::size_t k = 0;
            halves([&](int h) {
                if (c.edgeSharpness[std::size_t(h)] != before[k++]) out.edges.push_back(h);
            });
            if (c.vertSharpness[std::size_t(vertexPoint)] != vertexBefore) out.vertices.push_back(vertexPoint);
        }
        sortUnique(out.edges);
        sortUnique(out.vertices);
    }
    if (!changed.faces.empty()) {
        const std::vector<int> first = firstChildFaces(p, num);
        for (int f : changed.faces)
            for (int child = first[std::size_t(f)]; child < first[std::size_t(f) + 1]; ++child) {
                c.faceHole[std::size_t(child)] = p.faceHole[std::size_t(f)];
                out.faces.push_back(child);
            }
    }
    return out;
}

std::vector<int> facesNear(const Topology& p, const ChangedTags& changed, int rings) {
    std::vector<int> seeds = changed.vertices;
    for (int e : changed.edges)
        seeds.push_back(p.edgeVerts[2 * std::size_t(e)]), seeds.push_back(p.edgeVerts[2 * std::size_t(e) + 1]);
    return widen(p, facesAt(p, seeds), rings);
}

std::vector<int> widen(const Topology& p, const std::vector<int>& faces, int rings) {
    std::vector<int> out = faces, ring = faces, next, vertices;
    for (int r = 0; r < rings; ++r) {
        vertices.clear();
        for (int f : ring)
            for (int v : p.verticesOfFace(f)) vertices.push_back(v);
        sortUnique(vertices);
        next.clear();
        for (int v : vertices)
            for (int f : p.facesOfVertex(v)) next.push_back(f);
        sortUnique(next);
        // The ring is what is new; `out` stays sorted.
        ring.clear();
        std::set_difference(next.begin(), next.end(), out.begin(), out.end(), std::back_inserter(ring));
        std::vector<int> merged;
        std::merge(out.begin(), out.end(), ring.begin(), ring.end(), std::back_inserter(merged));
        out.swap(merged);
    }
    return out;
}

std::vector<int> childrenOf(const Topology& p, const ChildNumbering& num, const std::vector<int>& faces) {
    std::vector<int> children;
    for (int f : faces) {
        if (num.facePoint[std::size_t(f)] >= 0) children.push_back(num.facePoint[std::size_t(f)]);
        for (int e : p.edgesOfFace(f)) children.push_back(num.edgePoint(e));
        for (int v : p.verticesOfFace(f)) children.push_back(num.vertexPoint(v));
    }
    sortUnique(children);
    return children;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
