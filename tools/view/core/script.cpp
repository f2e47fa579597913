#include "tools/view/core/script.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace quadtri::view {

namespace {

// Per verb: its spelling, and its arguments: 'i' a positive integer, 'l' a level, 's' a
// sharpness, 'n' a number, 'w' a word.
struct Form {
    ScriptVerb verb;
    const char* arguments;
};

const std::map<std::string, Form>& forms() {
    static const std::map<std::string, Form> table{
        {"select-edge", {ScriptVerb::SelectEdge, "ii"}},   {"add-edge", {ScriptVerb::AddEdge, "ii"}},
        {"select-vertex", {ScriptVerb::SelectVertex, "i"}}, {"add-vertex", {ScriptVerb::AddVertex, "i"}},
        {"clear-selection", {ScriptVerb::ClearSelection, ""}}, {"click", {ScriptVerb::Click, "nn"}},
        {"shift-click", {ScriptVerb::ShiftClick, "nn"}}, {"sharpness", {ScriptVerb::Sharpness, "s"}},
        {"level", {ScriptVerb::Level, "l"}},               {"scheme", {ScriptVerb::Scheme, "w"}},
        {"compare", {ScriptVerb::Compare, "w"}},           {"boundary", {ScriptVerb::Boundary, "w"}},
        {"crease-method", {ScriptVerb::CreaseMethod, "w"}}, {"uvs", {ScriptVerb::UVs, "w"}},
        {"shading", {ScriptVerb::Shading, "w"}},           {"evaluator", {ScriptVerb::Evaluator, "w"}},
        {"tables", {ScriptVerb::Tables, "w"}},             {"adaptive", {ScriptVerb::Adaptive, "w"}},
        {"segment-pixels", {ScriptVerb::SegmentPixels, "n"}},
        {"deform", {ScriptVerb::Deform, "w"}},             {"camera", {ScriptVerb::Camera, "nn"}},
        {"frames", {ScriptVerb::Frames, "i"}},             {"load", {ScriptVerb::Load, "w"}},
        {"save", {ScriptVerb::Save, "w"}},                 {"texture", {ScriptVerb::Texture, "w"}},                 {"screenshot", {ScriptVerb::Screenshot, "w"}},
        {"screenshot-window", {ScriptVerb::ScreenshotWindow, "w"}},
        {"close", {ScriptVerb::Close, ""}},                 {"quit", {ScriptVerb::Quit, ""}}};
    return table;
}

std::string verbList() {
    std::string list;
    for (const auto& entry : forms()) list += (list.empty() ? "" : ", ") + entry.first;
    return list;
}

// The whole word as a finite number, or "inf" / "infinite" where `infinite` allows it.
bool parseNumber(const std::string& word, bool infinite, double& value) {
    if (infinite && (word == "inf" || word == "infinite")) {
        value = INFINITY;
        return true;
    }
    std::istringstream in(word);
    in >> value;
    return in && in.peek() == std::char_traits<char>::eof() && std::isfinite(value);
}

ScriptCommand parseLine(const std::vector<std::string>& words, const std::string& where) {
    const auto found = forms().find(words[0]);
    if (found == forms().end())
        throw ScriptError(where + "unknown command '" + words[0] + "' (expected one of " + verbList() + ")");
    const std::string arguments = found->second.arguments;
    const std::size_t given = words.size() - 1;
    if (given != arguments.size())
        throw ScriptError(where + "'" + words[0] + "' takes " + std::to_string(arguments.size()) + " argument" +
                          (arguments.size() == 1 ? "" : "s") + ", got " + std::to_string(given));
    ScriptCommand command{found->second.verb, {words.begin() + 1, words.end()}, {}, 0};
    for (std::size_t k = 0; k < arguments.size(); ++k) {
        const char kind = arguments[k];
        if (kind == 'w') continue;
        const std::string& word = words[k + 1];
        double value = 0;
        if (!parseNumber(word, kind == 's', value))
            throw ScriptError(where + "'" + words[0] + "': '" + word + "' is not a number");
        if (kind == 'i' && (value < 1 || value != std::floor(value) || value > 2147483647.0))
            throw ScriptError(where + "'" + words[0] + "': '" + word + "' is not a positive integer");
        if (kind == 'l' && (value < 0 || value > 6 || value != std::floor(value)))
            throw ScriptError(where + "'" + words[0] + "': level " + word + " is outside 0-6");
        if (kind == 's' && !(value >= 0))
            throw ScriptError(where + "'" + words[0] + "': sharpness " + word + " is negative");
        command.numbers.push_back(value);
    }
    return command;
}

}  // namespace

std::vector<ScriptCommand> parseScript(std::istream& in, const std::string& name) {
    std::vector<ScriptCommand> commands;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        const std::size_t hash = text.find('#');
        if (hash != std::string::npos) text.resize(hash);
        std::istringstream split(text);
        std::vector<std::string> words;
        for (std::string word; split >> word;) words.push_back(word);
        if (words.empty()) continue;
        ScriptCommand command = parseLine(words, name + ":" + std::to_string(line) + ": ");
        command.line = line;
        commands.push_back(std::move(command));
    }
    if (in.bad()) throw ScriptError(name + ": read error");
    return commands;
}

std::vector<ScriptCommand> readScript(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw ScriptError(path + ": cannot open the script");
    return parseScript(in, path);
}

}  // namespace quadtri::view
