// Sizes on the command line: "4294967296", "512MiB", "8GiB", "2GB".
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include <quadtri/far/options.h>

namespace quadtri::cli {

// What parseByteSize accepts, for error messages.
constexpr const char* kByteSizeForms =
    "a whole number of bytes with an optional unit: B, KB, MB, GB, TB (powers of 1000) or KiB, MiB, GiB, TiB "
    "(powers of 1024), e.g. 8GiB";

// A whole number with an optional case-insensitive unit (see kByteSizeForms); nothing for
// anything else, a negative number or a size that does not fit in std::size_t.
std::optional<std::size_t> parseByteSize(std::string_view text);

// "2.18 MiB (2289780 bytes)", or "512 bytes".
std::string bytesText(std::size_t bytes);
// A --memory-budget value just above `bytes`, e.g. "3MiB" for 2.18 MiB.
std::string budgetAbove(std::size_t bytes);

// A refusal by the memory budget in the command line's terms: "IN.obj: level 4 needs at least
// ... over the memory budget of ...; raise --memory-budget (e.g. ...) or ask for fewer levels".
std::string budgetRefusal(const std::string& input, const MemoryBudgetError& error);

}  // namespace quadtri::cli
