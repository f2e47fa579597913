// The check behind a composition memo hit (far/internal/composition_memo.h): the output entries'
// sources taken from their first products, sources[s] = products[first[s]] for s < size, then
// whether products[p] == sources[pattern[p]] for every p < n. A gather (and a compare) per
// entry; on x86-64 CPUs with AVX2 eight at a time (far/same_sources_avx2.cpp).
#pragma once

namespace quadtri {
inline namespace v0 {

bool sameSources(const int* products, int n, const int* first, int size, const int* pattern, int* sources);

}  // namespace v0
}  // namespace quadtri
