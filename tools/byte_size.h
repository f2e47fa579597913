// Sizes on the command line: "4294967296", "512MiB", "8GiB", "2GB".
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace quadtri::cli {

// What parseByteSize accepts, for error messages.
constexpr const char* kByteSizeForms =
    "a whole number of bytes with an optional unit: B, KB, MB, GB, TB (powers of 1000) or KiB, MiB, GiB, TiB "
    "(powers of 1024), e.g. 8GiB";

// A whole number with an optional case-insensitive unit (see kByteSizeForms); nothing for
// anything else, a negative number or a size that does not fit in std::size_t.
std::optional<std::size_t> parseByteSize(std::string_view text);

}  // namespace quadtri::cli
