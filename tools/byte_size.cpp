#include "tools/byte_size.h"

#include <cctype>
#include <charconv>
#include <limits>
#include <string>

namespace quadtri::cli {

std::optional<std::size_t> parseByteSize(std::string_view text) {
    unsigned long long count = 0;
    const char* const end = text.data() + text.size();
    const auto [unitStart, ec] = std::from_chars(text.data(), end, count);
    if (ec != std::errc() || unitStart == text.data()) return std::nullopt;  // also "-1" and "+1"

    std::string unit(unitStart, end);
    if (unit.size() > 1 && unit[0] == ' ') unit.erase(0, 1);  // "8 GiB"
    for (char& c : unit) c = char(std::tolower(static_cast<unsigned char>(c)));
    static const char* const prefixes = "kmgt";
    unsigned long long scale = 1;
    if (!unit.empty() && unit != "b") {
        const std::size_t power = std::string_view(prefixes).find(unit[0]);
        const bool binary = unit.size() == 3 && unit.substr(1) == "ib";
        if (power == std::string_view::npos || !(binary || unit.substr(1) == "b")) return std::nullopt;
        for (std::size_t p = 0; p <= power; ++p) scale *= binary ? 1024 : 1000;
    }
    constexpr unsigned long long kMax = std::numeric_limits<std::size_t>::max();
    if (count > kMax / scale) return std::nullopt;
    return std::size_t(count * scale);
}

}  // namespace quadtri::cli
