// The subcommands of the `quadtri` command-line tool. Each returns the process exit status and
// lets TopologyError, io::ObjError and other exceptions escape to main(), which reports them.
#pragma once

#include <optional>
#include <string>

#include "far/options.h"

namespace quadtri::cli {

// Flags shared by every subcommand.
struct MeshArgs {
    std::string input;
    std::optional<Scheme> scheme;                   // default: Schaefer-Warren
    std::optional<BoundaryInterpolation> boundary;  // default: the file's tag, else edge only
    std::optional<CreaseMethod> creaseMethod;       // default: the file's tag, else uniform
};

// Largest refinement level accepted on the command line (the memory budget may refuse less).
constexpr int kMaxLevel = 10;

struct RefineArgs {
    MeshArgs mesh;
    int level = 1;
    std::string output;
};

struct InfoArgs {
    MeshArgs mesh;
    int level = 3;
};

struct DemoArgs {
    MeshArgs mesh;
    int levels = 3;
    std::string outDir = ".";
};

int runRefine(const RefineArgs& args);
int runInfo(const InfoArgs& args);
int runDemo(const DemoArgs& args);

}  // namespace quadtri::cli
