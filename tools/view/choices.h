// The viewer's live choices, as the panel's lists and the script's words spell them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <quadtri/far/options.h>
#include "tools/commands.h"
#include "tools/realtime/surface_tables.h"
#include "tools/render/renderer.h"

namespace quadtri::view {

struct Choices {
    Scheme scheme = Scheme::SchaeferWarren;
    std::optional<Scheme> compare;  // a second viewport with this scheme
    int level = 3;
    BoundaryInterpolation boundary = BoundaryInterpolation::EdgeOnly;
    CreaseMethod creaseMethod = CreaseMethod::Uniform;
    FVarLinearInterpolation uvs = FVarLinearInterpolation::CornersPlus1;
    cli::EvaluatorKind evaluator = cli::EvaluatorKind::Vulkan;
    // FactorizedLimit falls back to LevelsThenLimit where the memory budget refuses it; level 0
    // is always the cage's own limit table.
    realtime::TableRoute tables = realtime::TableRoute::FactorizedLimit;
    // Adaptive tessellation instead of the level: a rate per cage edge, its projected length over
    // this many pixels (ViewedSurface::adapt).
    bool adaptive = false;
    float pixelsPerSegment = 12.0f;
};

const std::vector<BoundaryInterpolation>& allBoundaries();
const std::vector<CreaseMethod>& allCreaseMethods();
const std::vector<cli::EvaluatorKind>& allEvaluators();
using realtime::allTableRoutes;
const char* toString(cli::EvaluatorKind kind);
const char* toString(render::Shading shading);  // as `quadtri render --shading` spells it

// The value whose toString is `name`; std::nullopt for none.
template <typename T>
std::optional<T> named(const std::vector<T>& all, const std::string& name) {
    for (const T& value : all)
        if (name == toString(value)) return value;
    return std::nullopt;
}
const std::vector<render::Shading>& allShadings();

// The MeshArgs that give the choices when passed to cli::makeOptions (flags over the file's tags).
cli::MeshArgs meshArgsOf(const Choices& choices, Scheme scheme);

}  // namespace quadtri::view
