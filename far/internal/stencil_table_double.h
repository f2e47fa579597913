// Stencil tables with double weights: how the analyzer builds and composes tables before it
// stores them as StencilTable.
#pragma once

#include <cstddef>
#include <vector>

#include <quadtri/far/stencil_table.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

// A plain CSR table with double weights, one per entry: how the analyzer builds and composes
// tables (stencil i's entries are [offsets[i], offsets[i] + sizes[i])).
struct StencilTableD {
    int numSourceVertices = 0;
    std::vector<int> sizes;
    std::vector<int> offsets;
    std::vector<int> indices;
    std::vector<double> weights;
};

// The float table stored for evaluation (weights rounded to float, then interned), and back to
// plain CSR.
StencilTable toFloatTable(const StencilTableD& table);
StencilTableD toDoubleTable(const StencilTable& table);

// Bytes of a table's arrays.
std::size_t bytesOf(const StencilTableD& table);

struct KnownStencils;  // far/tables/regular_patches.h

// Stencils of a composition that templates give (far/tables/regular_patches.h), rather than
// composition or the inner table.
struct TemplatedStencils {
    // The result's: written from their templates instead of composed (their sources and weights
    // agree with the composition's within rounding, not bitwise, and may come in another order).
    const KnownStencils* result = nullptr;
    // The inner table's: read from their templates, not from the table, which may hold them
    // left out (below).
    const KnownStencils* inner = nullptr;
    // The result's templated stencils left out of its arrays (size 0, no entries), for the next
    // composition, which names them as `inner`, to read from their templates. Double results
    // only: nothing is left out of a float table.
    bool leaveOut = false;
};

// outer ∘ inner: stencils of `outer` (over inner's stencils) expanded over inner's sources.
// Throws std::length_error before the result's arrays would pass `maxBytes` (or 2^31 - 1
// entries, the reach of its int offsets); the caller names what was refused.
// An outer float table composes as its toDoubleTable() would, bitwise, without that copy.
StencilTableD composeStencils(const StencilTableD& outer, const StencilTableD& inner,
                              std::size_t maxBytes = ~std::size_t(0), const TemplatedStencils& templated = {});
StencilTableD composeStencils(const StencilTable& outer, const StencilTableD& inner,
                              std::size_t maxBytes = ~std::size_t(0), const TemplatedStencils& templated = {});
// An inner float table likewise: as over its toDoubleTable(), bitwise (level 2 over level 1's
// stored table).
StencilTableD composeStencils(const StencilTable& outer, const StencilTable& inner,
                              std::size_t maxBytes = ~std::size_t(0), const TemplatedStencils& templated = {});

// The same composition stored as float: bitwise toFloatTable(composeStencils(outer, inner,
// maxBytes, templated)) with nothing left out, refused at the same point, without the double
// result (far/tables/compose_stencils.cpp).
StencilTable composeStencilsToFloat(const StencilTableD& outer, const StencilTableD& inner,
                                    std::size_t maxBytes = ~std::size_t(0), const TemplatedStencils& templated = {});
StencilTable composeStencilsToFloat(const StencilTable& outer, const StencilTableD& inner,
                                    std::size_t maxBytes = ~std::size_t(0), const TemplatedStencils& templated = {});
StencilTable composeStencilsToFloat(const StencilTable& outer, const StencilTable& inner,
                                    std::size_t maxBytes = ~std::size_t(0), const TemplatedStencils& templated = {});

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
