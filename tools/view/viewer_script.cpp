// The script language's commands (tools/view/core/script.h) run against the viewer.
#include <cmath>
#include <cstdio>

#include "tools/view/core/cage_edits.h"
#include "tools/view/viewer.h"

namespace quadtri::view {

namespace {

template <typename T>
T namedOrFail(const std::vector<T>& all, const std::string& name, const std::string& where, const char* what) {
    if (const std::optional<T> value = named(all, name)) return *value;
    std::string list;
    for (const T& value : all) list += (list.empty() ? "" : ", ") + std::string(toString(value));
    throw ScriptError(where + "unknown " + what + " '" + name + "' (expected " + list + ")");
}

bool onOff(const std::string& word, const std::string& where) {
    if (word == "on") return true;
    if (word == "off") return false;
    throw ScriptError(where + "'" + word + "' is not on or off");
}

}  // namespace

void Viewer::runCommand(const ScriptCommand& command, const std::string& script) {
    const std::string where = script + ":" + std::to_string(command.line) + ": ";
    const std::vector<std::string>& w = command.words;
    const io::ObjMesh& mesh = document_.mesh();
    // A 1-based vertex of the file, as a 0-based index.
    auto vertex = [&](std::size_t k) {
        const double v = command.numbers[k];
        if (v > mesh.numVertices())
            throw ScriptError(where + "vertex " + w[k] + " does not exist (the mesh has " +
                              std::to_string(mesh.numVertices()) + ")");
        return int(v) - 1;
    };
    auto edge = [&](bool add) {
        const int a = vertex(0), b = vertex(1);
        const std::vector<uint32_t>& edges = surfaces_[0]->edges();
        for (std::size_t e = 0; 2 * e + 1 < edges.size(); ++e)
            if ((int(edges[2 * e]) == a && int(edges[2 * e + 1]) == b) || (int(edges[2 * e]) == b && int(edges[2 * e + 1]) == a))
                return document_.selectEdge(a, b, add);
        throw ScriptError(where + "vertices " + w[0] + " and " + w[1] + " are not joined by an edge of the cage");
    };
    switch (command.verb) {
        case ScriptVerb::SelectEdge: edge(false); break;
        case ScriptVerb::AddEdge: edge(true); break;
        case ScriptVerb::SelectVertex:
        case ScriptVerb::AddVertex:
            document_.selectVertex(vertex(0), command.verb == ScriptVerb::AddVertex);
            view_.showPoints = true;
            break;
        case ScriptVerb::ClearSelection: document_.clearSelection(); break;
        case ScriptVerb::Click:
        case ScriptVerb::ShiftClick:
            pick({float(command.numbers[0]), float(command.numbers[1])}, command.verb == ScriptVerb::ShiftClick);
            break;
        case ScriptVerb::Sharpness:
            if (!document_.hasSelection()) throw ScriptError(where + "'sharpness' with nothing selected");
            editSelection(std::isinf(command.numbers[0]) ? kInfiniteSharpness : float(command.numbers[0]));
            break;
        case ScriptVerb::Level: choices_.level = int(command.numbers[0]); needsRebuild_ = true; break;
        case ScriptVerb::Scheme: choices_.scheme = namedOrFail(allSchemes(), w[0], where, "scheme"); needsRebuild_ = true; break;
        case ScriptVerb::Compare:
            choices_.compare = w[0] == "off" ? std::nullopt : std::optional<Scheme>(namedOrFail(allSchemes(), w[0], where, "scheme"));
            needsRebuild_ = true;
            break;
        case ScriptVerb::Boundary:
            choices_.boundary = namedOrFail(allBoundaries(), w[0], where, "boundary");
            needsRebuild_ = true;
            break;
        case ScriptVerb::CreaseMethod:
            choices_.creaseMethod = namedOrFail(allCreaseMethods(), w[0], where, "crease method");
            needsRebuild_ = true;
            break;
        case ScriptVerb::UVs:
            choices_.uvs = namedOrFail(allFVarLinearInterpolations(), w[0], where, "UV option");
            needsRebuild_ = true;
            break;
        case ScriptVerb::Shading: view_.shading = namedOrFail(allShadings(), w[0], where, "shading"); needsUpdate_ = true; break;
        case ScriptVerb::Evaluator:
            choices_.evaluator = namedOrFail(allEvaluators(), w[0], where, "evaluator");
            needsRebuild_ = true;
            break;
        case ScriptVerb::Tables:
            if (const auto route = realtime::tableRouteNamed(w[0]))
                choices_.tables = *route;
            else
                throw ScriptError(where + "unknown tables '" + w[0] + "' (expected factorized, levels, patches)");
            needsRebuild_ = true;
            break;
        case ScriptVerb::Adaptive:
            choices_.adaptive = onOff(w[0], where);
            needsRebuild_ = true;
            break;
        case ScriptVerb::SegmentPixels:
            if (!(command.numbers[0] > 0)) throw ScriptError(where + "segment-pixels must be above 0");
            choices_.pixelsPerSegment = float(command.numbers[0]);
            break;
        case ScriptVerb::Deform: deform_ = onOff(w[0], where); needsUpdate_ = true; break;
        case ScriptVerb::Camera:
            view_.camera.yawDegrees = float(command.numbers[0]);
            view_.camera.pitchDegrees = float(command.numbers[1]);
            break;
        case ScriptVerb::Frames:
            for (int i = 1; i < int(command.numbers[0]); ++i) frame(nullptr);
            break;
        case ScriptVerb::Load:
            // As in the panel: a file that fails keeps the mesh shown; the script goes on.
            load(w[0]);
            if (!message_.empty()) {
                std::fprintf(stderr, "quadtri: %s%s (the mesh shown is kept)\n", where.c_str(), message_.c_str());
                message_.clear();
            }
            break;
        case ScriptVerb::Texture:
            loadTexture(w[0]);
            if (!message_.empty()) throw ScriptError(where + message_);
            break;
        case ScriptVerb::Save:
            try {
                document_.save(w[0]);
            } catch (const io::ObjError& e) {
                throw ScriptError(where + e.what());
            }
            break;
        case ScriptVerb::Screenshot:
        case ScriptVerb::ScreenshotWindow:
            try {
                saveScreenshot(w[0], command.verb == ScriptVerb::ScreenshotWindow);
            } catch (const io::ObjError& e) {
                throw ScriptError(where + e.what());
            }
            break;
        case ScriptVerb::Close: closeRequested(); break;
        case ScriptVerb::Quit: quit_ = true; break;
    }
    needsUpdate_ = true;
}

}  // namespace quadtri::view
