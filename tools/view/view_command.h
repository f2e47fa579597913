// `quadtri view IN.obj`: the viewer's command-line arguments and entry point (tools/view/; in a
// build without Vulkan, GLFW or Dear ImGui, tools/view/no_viewer.cpp says so).
#pragma once

#include <string>

#include "tools/commands.h"
#include "tools/realtime/surface_tables.h"

namespace quadtri::view {

struct ViewerArgs {
    cli::MeshArgs mesh;        // the file and the flags that override its tags
    int level = 3;
    cli::EvaluatorKind evaluator = cli::EvaluatorKind::Vulkan;
    realtime::TableRoute tables = realtime::TableRoute::FactorizedLimit;  // --tables
    std::string texture;       // PNG or JPEG for textured shading
    std::string script;        // --script FILE: run its commands, then quit
    int width = 1280, height = 800;
};

// Opens the viewer; without a display, a Vulkan device that can present, or with a lost device:
// one message on stderr and status 2. Errors in the file and the script likewise.
int runView(const ViewerArgs& args);

}  // namespace quadtri::view
