#include <quadtri/far/refiner.h>

#include <stdexcept>
#include <string>

#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include "far/internal/refine_topology.h"
#include "far/internal/rules.h"
#include "far/internal/stencil_table_double.h"
#include "far/internal/topology_builder.h"

namespace quadtri {
inline namespace v0 {

Refiner::Refiner(const TopologyDescriptor& desc, const Options& options) : options_(options) {
    levels_.push_back(buildBaseTopology(desc, options, &warnings_));
    detail_.push_back(TopologyDetail::Full);
}

const Topology& Refiner::level(int L) const {
    const Topology& topology = levels_.at(L);
    if (detail_[L] == TopologyDetail::FacesOnly)
        throw std::logic_error("level " + std::to_string(L) + " holds its faces only: read them with faces(" +
                               std::to_string(L) + "), or refine with refineUniform(" + std::to_string(L) +
                               ", TopologyDetail::Full) for its edges and incidences");
    return topology;
}

std::size_t Refiner::estimateLevelBytes(int L) const {
    const Topology& p = levels_.at(L - 1);
    std::size_t faces = 0, corners = 0, entries = 0, facePoints = 0;
    for (int f = 0; f < p.numFaces(); ++f) {
        const std::size_t n = p.faceSize(f);
        faces += n == 3 ? 4 : n;
        corners += n == 3 ? 12 : 4 * n;
        facePoints += n == 3 ? 0 : 1;
        // Each face contributes its corners to its face point and to the masks of its edges'
        // and vertices' points.
        entries += n + 2 * n * n;
    }
    // A faces-only level has no edges yet: one per corner bounds them (an open mesh's count).
    const std::size_t parentEdges = p.edgeVerts.empty() ? p.faceVerts.size() : std::size_t(p.numEdges());
    const std::size_t edges = 2 * parentEdges + corners / 4;
    const std::size_t vertices = facePoints + parentEdges + p.numVertices;
    entries += 4 * parentEdges + p.numVertices;
    if (options_.scheme == Scheme::CatmarkButterfly) {
        // Zorin's edge masks read the whole ring of an extraordinary vertex with triangles only:
        // each of its K edges' masks has up to K + 1 more entries than counted above.
        std::vector<std::size_t> corners(std::size_t(p.numVertices), 0);
        std::vector<uint8_t> touchesQuad(std::size_t(p.numVertices), 0);
        for (int f = 0; f < p.numFaces(); ++f)
            for (int i = p.faceOffsets[f]; i < p.faceOffsets[f + 1]; ++i) {
                ++corners[std::size_t(p.faceVerts[i])];
                touchesQuad[std::size_t(p.faceVerts[i])] |= p.faceSize(f) != 3;
            }
        auto extraordinary = [&](int v, std::size_t k) { return !touchesQuad[std::size_t(v)] && k >= 3 && k != 6; };
        if (p.vertEdgeOffsets.size() == std::size_t(p.numVertices) + 1) {
            // Zorin's rule applies where both ends have triangles only, at an end whose faces
            // close a manifold fan.
            for (int e = 0; e < p.numEdges(); ++e) {
                const int a = p.edgeVerts[2 * e], b = p.edgeVerts[2 * e + 1];
                if (touchesQuad[std::size_t(a)] || touchesQuad[std::size_t(b)]) continue;
                for (int v : {a, b}) {
                    const std::size_t k = std::size_t(p.vertexEdgeCount(v));
                    if (!(p.vertFlags[std::size_t(v)] & (kVertexBoundary | kVertexNonManifold)) && extraordinary(v, k))
                        entries += k + 1;
                }
            }
        } else {
            // Faces only: a vertex has at most one edge more than it has corners.
            for (int v = 0; v < p.numVertices; ++v) {
                const std::size_t k = corners[std::size_t(v)] + 1;
                if (extraordinary(v, k)) entries += k * (k + 1);
            }
        }
    }
    const std::size_t topologyBytes = corners * 16 + edges * 25 + vertices * 22 + faces * 5;
    // An index per entry and two offsets per stencil (weights are pooled), twice over: the parts
    // built by other threads are copied into the table (buildLevelStencils).
    const std::size_t tableBytes = 2 * (entries * 4 + vertices * 8);
    const std::size_t outputBytes = vertices * 3 * sizeof(float);
    // Per thread, a sparse accumulator over the parent's vertices; for Schaefer-Warren, each
    // parent vertex's two unzipped copies (one entry per network neighbour, two per vertex).
    const std::size_t threads = std::size_t(tbb::this_task_arena::max_concurrency());
    const std::size_t scratchBytes = threads * std::size_t(p.numVertices) * 16;
    const std::size_t unzipBytes = options_.scheme == Scheme::SchaeferWarren
                                       ? 2 * (std::size_t(p.numVertices) * (8 + 12) + 2 * parentEdges * 12)
                                       : 0;
    return topologyBytes + tableBytes + outputBytes + scratchBytes + unzipBytes;
}

std::size_t Refiner::bytes() const {
    std::size_t total = 0;
    for (const Topology& t : levels_) total += bytesOf(t);
    for (const StencilTable& t : levelTables_) total += t.bytes();
    return total;
}

namespace {

// Bytes of a float table converted to a double one (toDoubleTable).
std::size_t doubleBytes(const StencilTable& t) {
    return std::size_t(2 * t.numStencils()) * sizeof(int) + t.numEntries() * (sizeof(int) + sizeof(double));
}

}  // namespace

void Refiner::completeLevel(int L) {
    if (detail_[L] == TopologyDetail::Full) return;
    const Topology& parent = levels_[L - 1];
    levels_[L] = refineTopology(parent, numberChildren(parent), options_.creaseMethod, TopologyDetail::Full);
    detail_[L] = TopologyDetail::Full;
}

void Refiner::refineUniform(int maxLevel, TopologyDetail lastLevel) {
    if (maxLevel < 0) throw TopologyError("refinement level " + std::to_string(maxLevel) + " is negative");
    while (this->maxLevel() < maxLevel) {
        const int L = this->maxLevel() + 1;
        completeLevel(L - 1);  // within the budget level L - 1 was built under
        const std::size_t estimate = estimateLevelBytes(L), held = bytes();
        if (held > options_.memoryBudgetBytes || estimate > options_.memoryBudgetBytes - held)
            throw MemoryBudgetError("level " + std::to_string(L), held + estimate, held, options_.memoryBudgetBytes);
        const Topology& parent = levels_.back();
        const ChildNumbering numbering = numberChildren(parent);
        const TopologyDetail detail = L == maxLevel ? lastLevel : TopologyDetail::Full;
        // Both read only the parent level: build them side by side.
        StencilTable table;
        Topology child;
        tbb::parallel_invoke([&] { table = buildLevelStencils<StencilTable>(parent, numbering, options_); },
                             [&] { child = refineTopology(parent, numbering, options_.creaseMethod, detail); });
        levelTables_.push_back(std::move(table));
        levels_.push_back(std::move(child));
        detail_.push_back(detail);
    }
    if (lastLevel == TopologyDetail::Full) completeLevel(maxLevel);
}

StencilTable Refiner::factorizedStencils(int L) const {
    if (L < 1 || L > maxLevel())
        throw TopologyError("factorized stencils asked for level " + std::to_string(L) + "; refined levels are 1.." +
                            std::to_string(maxLevel()));
    const std::size_t budget = options_.memoryBudgetBytes, held = bytes();
    std::size_t used = 0;  // bytes of the double tables alive at this point
    auto refuse = [&](std::size_t needed) {
        return MemoryBudgetError("the factorized stencils of level " + std::to_string(L), needed, held, budget);
    };
    auto reserve = [&](std::size_t more) {
        if (held > budget || used > budget - held || more > budget - held - used) throw refuse(held + used + more);
        used += more;
    };
    reserve(doubleBytes(levelTables_[0]));
    StencilTableD composed = toDoubleTable(levelTables_[0]);
    for (int l = 2; l <= L; ++l) {
        reserve(doubleBytes(levelTables_[l - 1]));
        const StencilTableD outer = toDoubleTable(levelTables_[l - 1]);
        try {
            StencilTableD next = composeStencils(outer, composed, budget - held - used);
            used -= doubleBytes(levelTables_[l - 1]);
            used += bytesOf(next) - bytesOf(composed);
            composed = std::move(next);
        } catch (const std::length_error&) {
            throw refuse(budget + 1);  // composition stopped at the budget: more, by how much is unknown
        }
    }
    // The float table (an index per entry, two ints per stencil, a weight pool of at most one
    // float per entry) and a 3-float output per stencil, while the double table still lives.
    const std::size_t n = composed.sizes.size(), entries = composed.indices.size();
    reserve(entries * (sizeof(int) + sizeof(float)) + n * (2 * sizeof(int) + 3 * sizeof(float)));
    return toFloatTable(composed);
}

}  // namespace v0
}  // namespace quadtri
