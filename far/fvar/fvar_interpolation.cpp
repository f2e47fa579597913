// Names of the face-varying linear-interpolation options, one row each, in the order help texts
// list them (the CLI's choices and their errors come from here).
#include <quadtri/far/options.h>

#include <algorithm>
#include <iterator>

namespace quadtri {
inline namespace v0 {

namespace {

struct Named {
    FVarLinearInterpolation interpolation;
    const char* name;
};

constexpr Named kNames[] = {
    {FVarLinearInterpolation::None, "none"},
    {FVarLinearInterpolation::CornersOnly, "corners-only"},
    {FVarLinearInterpolation::CornersPlus1, "corners-plus1"},
    {FVarLinearInterpolation::CornersPlus2, "corners-plus2"},
    {FVarLinearInterpolation::Boundaries, "boundaries"},
    {FVarLinearInterpolation::All, "all"},
};

}  // namespace

const char* toString(FVarLinearInterpolation interpolation) {
    const auto it = std::find_if(std::begin(kNames), std::end(kNames),
                                 [&](const Named& n) { return n.interpolation == interpolation; });
    return it == std::end(kNames) ? "?" : it->name;
}

const std::vector<FVarLinearInterpolation>& allFVarLinearInterpolations() {
    static const std::vector<FVarLinearInterpolation> all = [] {
        std::vector<FVarLinearInterpolation> list;
        for (const Named& n : kNames) list.push_back(n.interpolation);
        return list;
    }();
    return all;
}

std::optional<FVarLinearInterpolation> fvarLinearInterpolationNamed(std::string_view name) {
    for (const Named& n : kNames)
        if (name == n.name) return n.interpolation;
    return std::nullopt;
}

}  // namespace v0
}  // namespace quadtri
