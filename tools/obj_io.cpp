#include "tools/obj_io.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <istream>
#include <ostream>
#include <string_view>

namespace quadtri::io {

namespace {

// Parses one OBJ stream; `fail` and `warn` prefix messages with "name:line: ".
class Parser {
public:
    Parser(std::istream& in, const std::string& name) : in_(in), name_(name) { mesh_.name = name; }

    ObjMesh run() {
        std::string line;
        while (std::getline(in_, line)) {
            ++line_;
            parseLine(line);
        }
        if (in_.bad()) throw ObjError(line_ == 0 ? name_ + ": cannot read file" : where(line_ + 1) + "read error");
        checkFaceIndices();
        return std::move(mesh_);
    }

private:
    std::istream& in_;
    const std::string& name_;
    int line_ = 0;
    ObjMesh mesh_;

    std::string where(int line) const { return name_ + ":" + std::to_string(line) + ": "; }
    [[noreturn]] void fail(const std::string& problem) const { throw ObjError(where(line_) + problem); }
    void warn(const std::string& problem) { mesh_.warnings.push_back(where(line_) + problem); }

    static std::vector<std::string_view> split(std::string_view s) {
        std::vector<std::string_view> tokens;
        size_t i = 0;
        while (i < s.size()) {
            while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
            size_t start = i;
            while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
            if (i > start) tokens.push_back(s.substr(start, i - start));
        }
        return tokens;
    }

    static std::string_view skipPlus(std::string_view s) {
        return s.size() > 1 && s[0] == '+' && s[1] != '-' && s[1] != '+' ? s.substr(1) : s;
    }

    int toInt(std::string_view s, const char* what) const {
        std::string_view t = skipPlus(s);
        int value = 0;
        auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
        if (ec != std::errc() || end != t.data() + t.size() || t.empty())
            fail("cannot parse " + std::string(what) + " '" + std::string(s) + "'");
        return value;
    }

    float toFloat(std::string_view s, const char* what) const {
        std::string_view t = skipPlus(s);
        float value = 0;
        auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
        if (ec != std::errc() || end != t.data() + t.size() || t.empty() || !std::isfinite(value))
            fail("cannot parse " + std::string(what) + " '" + std::string(s) + "'");
        return value;
    }

    void parseLine(std::string_view line) {
        size_t hash = line.find('#');
        if (hash != std::string_view::npos) line = line.substr(0, hash);
        std::vector<std::string_view> tok = split(line);
        if (tok.empty()) return;
        std::string_view key = tok[0];
        if (key == "v") {
            parseVertex(tok);
        } else if (key == "f") {
            parseFace(tok);
        } else if (key == "t") {
            parseTag(tok);
        } else if (key == "vt" || key == "vn" || key == "vp" || key == "o" || key == "g" || key == "s" ||
                   key == "usemtl" || key == "mtllib") {
            // Not needed for refinement.
        } else {
            warn("unknown statement '" + std::string(key) + "' ignored");
        }
    }

    void parseVertex(const std::vector<std::string_view>& tok) {
        if (tok.size() < 4) fail("vertex needs 3 coordinates");
        for (int c = 1; c <= 3; ++c) mesh_.positions.push_back(toFloat(tok[c], "coordinate"));
        for (size_t c = 4; c < tok.size(); ++c) toFloat(tok[c], "coordinate");  // w, or vertex colours
    }

    void parseFace(const std::vector<std::string_view>& tok) {
        int corners = int(tok.size()) - 1;
        if (corners < 3) fail("face has " + std::to_string(corners) + " corners, needs at least 3");
        for (int c = 1; c <= corners; ++c) {
            std::string_view corner = tok[c];
            std::string_view pos = corner.substr(0, corner.find('/'));
            int index = toInt(pos, "face index");
            if (index == 0) fail("face index 0 (OBJ indices start at 1)");
            if (index < 0) {
                index += mesh_.numVertices();
                if (index < 0)
                    fail("face index " + std::string(pos) + " is before the first vertex (" +
                         std::to_string(mesh_.numVertices()) + " read so far)");
            } else {
                index -= 1;  // checked against the final vertex count in checkFaceIndices()
            }
            mesh_.faceVerts.push_back(index);
        }
        mesh_.faceSizes.push_back(corners);
        mesh_.faceLines.push_back(line_);
    }

    void checkFaceIndices() const {
        int n = mesh_.numVertices();
        size_t k = 0;
        for (int f = 0; f < mesh_.numFaces(); ++f)
            for (int c = 0; c < mesh_.faceSizes[f]; ++c, ++k)
                if (mesh_.faceVerts[k] >= n)
                    throw ObjError(where(mesh_.faceLines[f]) + "face index " +
                                   std::to_string(mesh_.faceVerts[k] + 1) + " is out of range (" +
                                   std::to_string(n) + " vertices)");
    }

    // `t name I/F/S ints floats strings`
    void parseTag(const std::vector<std::string_view>& tok) {
        if (tok.size() < 2) fail("tag without a name");
        std::string name(tok[1]);
        if (name != "crease" && name != "corner" && name != "hole" && name != "interpolateboundary" &&
            name != "creasemethod") {
            warn("unknown tag '" + name + "' ignored");
            return;
        }
        if (tok.size() < 3) fail("tag '" + name + "' has no argument counts");
        int counts[3];
        std::string_view spec = tok[2];
        for (int i = 0; i < 3; ++i) {
            size_t slash = spec.find('/');
            if ((i < 2) == (slash == std::string_view::npos))
                fail("tag '" + name + "': cannot parse counts '" + std::string(tok[2]) + "'");
            counts[i] = toInt(spec.substr(0, slash), "tag count");
            if (counts[i] < 0) fail("tag '" + name + "': negative count in '" + std::string(tok[2]) + "'");
            spec = i < 2 ? spec.substr(slash + 1) : std::string_view();
        }
        const int nInt = counts[0], nFloat = counts[1], nString = counts[2];
        if (tok.size() - 3 != size_t(nInt) + size_t(nFloat) + size_t(nString))
            fail("tag '" + name + "' announces " + std::to_string(nInt + nFloat + nString) + " arguments, has " +
                 std::to_string(tok.size() - 3));
        std::vector<int> ints;
        std::vector<float> floats;
        for (int i = 0; i < nInt; ++i) ints.push_back(toInt(tok[3 + i], "tag integer"));
        for (int i = 0; i < nFloat; ++i) floats.push_back(toFloat(tok[3 + nInt + i], "tag value"));
        std::vector<std::string_view> strings(tok.begin() + 3 + nInt + nFloat, tok.end());

        auto expect = [&](bool ok, const char* form) {
            if (!ok) fail("tag '" + name + "' must be " + form + ", got " + std::string(tok[2]));
        };
        auto nonNegative = [&](const char* what) {
            for (int v : ints)
                if (v < 0) fail("tag '" + name + "': negative " + what + " " + std::to_string(v));
        };
        if (name == "crease") {
            expect(nInt >= 2 && nInt % 2 == 0 && (nFloat == 1 || nFloat == nInt / 2) && nString == 0,
                   "2N/1/0 or 2N/N/0");
            nonNegative("vertex index");
            for (int p = 0; p < nInt / 2; ++p) {
                mesh_.creasePairs.push_back(ints[2 * p]);
                mesh_.creasePairs.push_back(ints[2 * p + 1]);
                mesh_.creaseSharpness.push_back(floats[nFloat == 1 ? 0 : p]);
                mesh_.creaseLines.push_back(line_);
            }
        } else if (name == "corner") {
            expect(nInt >= 1 && (nFloat == 1 || nFloat == nInt) && nString == 0, "N/1/0 or N/N/0");
            nonNegative("vertex index");
            for (int i = 0; i < nInt; ++i) {
                mesh_.corners.push_back(ints[i]);
                mesh_.cornerSharpness.push_back(floats[nFloat == 1 ? 0 : i]);
                mesh_.cornerLines.push_back(line_);
            }
        } else if (name == "hole") {
            expect(nFloat == 0 && nString == 0, "N/0/0");
            nonNegative("face index");
            mesh_.holes.insert(mesh_.holes.end(), ints.begin(), ints.end());
            mesh_.holeLines.insert(mesh_.holeLines.end(), ints.size(), line_);
        } else if (name == "interpolateboundary") {
            expect(nInt == 1 && nFloat == 0 && nString == 0, "1/0/0");
            switch (ints[0]) {
                case 0: mesh_.boundary = BoundaryInterpolation::None; break;
                case 1: mesh_.boundary = BoundaryInterpolation::EdgeAndCorner; break;
                case 2: mesh_.boundary = BoundaryInterpolation::EdgeOnly; break;
                default:
                    fail("interpolateboundary value " + std::to_string(ints[0]) +
                         " is not 0 (none), 1 (edge and corner) or 2 (edge only)");
            }
        } else {  // creasemethod
            expect(nInt == 0 && nFloat == 0 && nString == 1, "0/0/1");
            if (strings[0] == "chaikin")
                mesh_.creaseMethod = CreaseMethod::Chaikin;
            else if (strings[0] == "uniform" || strings[0] == "normal")  // "normal": OpenSubdiv's name
                mesh_.creaseMethod = CreaseMethod::Uniform;
            else
                fail("creasemethod '" + std::string(strings[0]) + "' is not chaikin, uniform or normal");
        }
    }
};

}  // namespace

TopologyDescriptor ObjMesh::descriptor() const {
    TopologyDescriptor d;
    d.numVertices = numVertices();
    d.numFaces = numFaces();
    d.numVertsPerFace = faceSizes.data();
    d.faceVertIndices = faceVerts.data();
    d.numCreases = int(creaseSharpness.size());
    d.creaseVertexPairs = creasePairs.data();
    d.creaseWeights = creaseSharpness.data();
    d.numCorners = int(corners.size());
    d.cornerVertexIndices = corners.data();
    d.cornerWeights = cornerSharpness.data();
    d.numHoles = int(holes.size());
    d.holeIndices = holes.data();
    return d;
}

Options ObjMesh::applyTags(Options base) const {
    if (boundary) base.boundary = *boundary;
    if (creaseMethod) base.creaseMethod = *creaseMethod;
    return base;
}

std::string ObjMesh::locate(const TopologyDiagnostic& diagnostic) const {
    using Component = TopologyDiagnostic::Component;
    const Component c = diagnostic.component;
    const std::vector<int>* lines = c == Component::Face     ? &faceLines
                                    : c == Component::Crease ? &creaseLines
                                    : c == Component::Corner ? &cornerLines
                                    : c == Component::Hole   ? &holeLines
                                                             : nullptr;
    const int i = diagnostic.index;
    if (lines && i >= 0 && size_t(i) < lines->size()) return name + ":" + std::to_string((*lines)[i]) + ": ";
    return name + ": ";
}

ObjMesh parseObj(std::istream& in, const std::string& name) { return Parser(in, name).run(); }

ObjMesh readObj(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ObjError(path + ": cannot open file");
    return parseObj(in, path);
}

void writeObj(std::ostream& out, const float* positions, const Topology& topology) {
    char buf[128];
    for (int v = 0; v < topology.numVertices; ++v) {
        const float* p = positions + 3 * size_t(v);
        std::snprintf(buf, sizeof buf, "v %.9g %.9g %.9g\n", double(p[0]), double(p[1]), double(p[2]));
        out << buf;
    }
    for (int f = 0; f < topology.numFaces(); ++f) {
        if (size_t(f) < topology.faceHole.size() && topology.faceHole[f]) continue;
        out << 'f';
        for (int k = topology.faceOffsets[f]; k < topology.faceOffsets[f + 1]; ++k) out << ' ' << topology.faceVerts[k] + 1;
        out << '\n';
    }
}

void writeObj(const std::string& path, const float* positions, const Topology& topology) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw ObjError(path + ": cannot write file");
    writeObj(out, positions, topology);
    out.close();
    if (!out) throw ObjError(path + ": cannot write file");
}

}  // namespace quadtri::io
