// The registry: every scheme's rules, one row each, in the order help texts list them. The
// names, descriptions, the CLI's --scheme choices and their error message all come from here.
#include <algorithm>
#include <iterator>

#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {

using namespace internal;

namespace internal {
// Each defined in its scheme's file.
const SchemeRules& schaeferWarrenRules();
const SchemeRules& stamLoopRules();
const SchemeRules& catmarkButterflyRules();
const SchemeRules& bilinearRules();
const SchemeRules& catmullClarkRules();
const SchemeRules& loopRules();
}  // namespace internal

namespace {

struct Registered {
    Scheme scheme;
    const SchemeRules& (*rules)();
};

constexpr Registered kSchemes[] = {
    {Scheme::SchaeferWarren, schaeferWarrenRules},
    {Scheme::StamLoop, stamLoopRules},
    {Scheme::CatmarkButterfly, catmarkButterflyRules},
    {Scheme::Bilinear, bilinearRules},
    {Scheme::CatmullClark, catmullClarkRules},
    {Scheme::Loop, loopRules},
};

const Registered* find(Scheme scheme) {
    const auto it = std::find_if(std::begin(kSchemes), std::end(kSchemes),
                                 [&](const Registered& r) { return r.scheme == scheme; });
    return it == std::end(kSchemes) ? nullptr : it;
}

}  // namespace

const SchemeRules& internal::rulesOf(Scheme scheme) {
    const Registered* r = find(scheme);
    if (!r) throw TopologyError("scheme " + std::to_string(int(scheme)) + " is not a registered scheme");
    return r->rules();
}

const std::vector<Scheme>& allSchemes() {
    static const std::vector<Scheme> schemes = [] {
        std::vector<Scheme> list;
        for (const Registered& r : kSchemes) list.push_back(r.scheme);
        return list;
    }();
    return schemes;
}

const char* toString(Scheme scheme) {
    const Registered* r = find(scheme);
    return r ? r->rules().name() : "?";
}

const char* describe(Scheme scheme) {
    const Registered* r = find(scheme);
    return r ? r->rules().description() : "?";
}

bool takesSmoothTriangles(Scheme scheme) { return rulesOf(scheme).acceptsSmoothTriangles(); }

std::optional<Scheme> schemeNamed(std::string_view name) {
    for (const Registered& r : kSchemes)
        if (name == r.rules().name()) return r.scheme;
    return std::nullopt;
}

}  // namespace v0
}  // namespace quadtri
