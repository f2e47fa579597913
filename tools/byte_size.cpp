#include "tools/byte_size.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

namespace quadtri::cli {

namespace {

// A size in the largest binary unit that keeps it at least 1: {value, "GiB"}.
std::pair<double, const char*> binaryUnits(std::size_t bytes) {
    static const char* const units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    double value = double(bytes);
    int unit = 0;
    while (value >= 1024 && unit < 6) value /= 1024, ++unit;
    return {value, units[unit]};
}

}  // namespace

// "4 GiB (4294967296 bytes)".
std::string bytesText(std::size_t bytes) {
    const auto [value, unit] = binaryUnits(bytes);
    if (bytes < 1024) return std::to_string(bytes) + " bytes";
    char text[96];
    std::snprintf(text, sizeof text, "%.3g %s (%zu bytes)", value, unit, bytes);
    return text;
}

// A --memory-budget value just above `bytes`, e.g. "3MiB" for 2.18 MiB.
std::string budgetAbove(std::size_t bytes) {
    const auto [value, unit] = binaryUnits(bytes);
    return bytes < 1024 ? std::to_string(bytes + 1) : std::to_string((long long)std::floor(value) + 1) + unit;
}

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

std::string budgetRefusal(const std::string& input, const MemoryBudgetError& e) {
    std::string text = input + ": " + e.subject() + " needs at least " + bytesText(e.needed());
    if (e.held() > 0) text += ", " + bytesText(e.held()) + " of them held by the levels already built";
    return text + ", over the memory budget of " + bytesText(e.budget()) + "; raise --memory-budget (e.g. --memory-budget " +
           budgetAbove(e.needed()) + ") or ask for fewer levels";
}

}  // namespace quadtri::cli
