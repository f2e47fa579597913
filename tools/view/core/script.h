// `quadtri view --script FILE`: a line-based command language that drives the viewer for tests
// and demonstrations (docs/viewer.md lists the commands). Each command runs after a
// rendered frame; blank lines and `#` comments are skipped.
#pragma once

#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace quadtri::view {

// A script that cannot be parsed or run; the message starts with "file:line: ".
class ScriptError : public std::runtime_error {
public:
    explicit ScriptError(const std::string& what) : std::runtime_error(what) {}
};

enum class ScriptVerb {
    SelectEdge,    // select-edge V1 V2: the cage edge between two vertices (1-based, the file's numbering)
    AddEdge,       // add-edge V1 V2: the same, added to the selection (shift-click)
    SelectVertex,  // select-vertex V
    AddVertex,     // add-vertex V
    ClearSelection,
    Click,         // click X Y: a left click at window pixel (X, Y), picking as the mouse does
    ShiftClick,    // shift-click X Y
    Sharpness,     // sharpness S|inf: the selected edges' crease and vertices' corner sharpness
    Level,         // level N (0-6)
    Scheme,        // scheme NAME
    Compare,       // compare NAME|off: a second viewport with that scheme
    Boundary,      // boundary edge-only|edge-and-corner|none
    CreaseMethod,  // crease-method uniform|chaikin
    UVs,           // uvs NAME (a face-varying option, e.g. corners-plus1)
    Shading,       // shading smooth|flat|reflection-lines|mean-curvature|face-type|textured
    Evaluator,     // evaluator cpu|tbb|vulkan
    Tables,        // tables factorized|levels|patches (the frame's table route)
    Adaptive,      // adaptive on|off: adaptive tessellation instead of the level
    SegmentPixels, // segment-pixels N: the adaptive tessellation's target, pixels per segment (> 0)
    Deform,        // deform on|off
    Camera,        // camera YAW PITCH (degrees)
    Frames,        // frames N: render N more frames
    Load,          // load PATH (a file that fails is reported on stderr; the mesh shown stays)
    Save,          // save PATH: the cage with its tags
    Texture,       // texture PATH: a PNG or JPEG for textured shading (and that shading)
    Screenshot,    // screenshot PATH: the view as PNG, without the panel
    ScreenshotWindow,  // screenshot-window PATH: the same with the panel
    Close,         // close: the window's close button (with unsaved edits the prompt opens instead)
    Quit,          // quit: ends the script at once
};

struct ScriptCommand {
    ScriptVerb verb;
    std::vector<std::string> words;  // the arguments as written
    std::vector<double> numbers;     // the numeric arguments, parsed ("inf": infinity)
    int line = 0;
};

// Every command of `in` (named `name` in messages), checked for its verb, the count and form of
// its arguments and the ranges the script language fixes (vertices >= 1, level 0-6, sharpness
// >= 0); names of schemes and modes are checked when they run.
std::vector<ScriptCommand> parseScript(std::istream& in, const std::string& name);
std::vector<ScriptCommand> readScript(const std::string& path);

}  // namespace quadtri::view
