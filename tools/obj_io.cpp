#include "tools/obj_io.h"

#include <cctype>
#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <string_view>
#include <unordered_map>

namespace quadtri::io {

namespace {

// " (No such file or directory)" for an errno value; "" for 0.
std::string reason(int error) { return error ? std::string(" (") + std::strerror(error) + ")" : std::string(); }

// Parses one OBJ stream; `fail` prefixes messages with "name:line: ".
class Parser {
public:
    Parser(std::istream& in, const std::string& name) : in_(in), name_(name) { mesh_.name = name; }

    ObjMesh run() {
        std::string line;
        while (std::getline(in_, line)) {
            ++line_;
            if (line_ == 1 && line.rfind(kUtf8Bom, 0) == 0) line.erase(0, kUtf8Bom.size());
            checkText(line);
            parseLine(line);
        }
        if (in_.bad()) throw ObjError(line_ == 0 ? name_ + ": cannot read file" : where(line_ + 1) + "read error");
        reportUnknown();
        checkFaceIndices();
        checkUVIndices();
        return std::move(mesh_);
    }

private:
    static constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

    // Statements this reader skips without a word: parts of OBJ that refinement does not use.
    static bool ignored(std::string_view key) {
        return key == "vn" || key == "vp" || key == "o" || key == "g" || key == "s" ||
               key == "usemtl" || key == "mtllib";
    }

    struct Unknown {
        std::string what;  // "statement 'l'" or "tag 'smoothtriangles'"
        int firstLine = 0;
        int count = 0;
    };

    std::istream& in_;
    const std::string& name_;
    int line_ = 0;
    int firstFaceLine_ = 0;        // the first `f` line: whether its first corner names a `vt` decides for all
    bool cornersHaveUVs_ = false;
    bool sawContent_ = false;  // a line with a statement was seen (for the format sniffing)
    bool sawObjStatement_ = false;
    std::vector<Unknown> unknown_;  // in order of first appearance
    std::unordered_map<std::string, size_t> unknownIndex_;  // Unknown::what -> its place in unknown_
    ObjMesh mesh_;

    std::string where(int line) const { return name_ + ":" + std::to_string(line) + ": "; }
    [[noreturn]] void fail(const std::string& problem) const { throw ObjError(where(line_) + problem); }

    // `s` quoted for a message, cut short so that one huge token cannot flood the terminal.
    static std::string quote(std::string_view s) {
        constexpr size_t kMax = 40;
        std::string text(1, '\'');
        text.append(s.substr(0, kMax)).append(s.size() > kMax ? "...'" : "'");
        return text;
    }

    // Binary data (a mesh in another format, a compressed file) has control bytes that OBJ text
    // never has; the first line tells other text formats apart.
    void checkText(std::string_view line) const {
        if (line_ == 1 && line.rfind("glTF", 0) == 0) fail("a binary glTF (.glb) file, not OBJ");
        if (line_ == 1 && (line.rfind("\xFF\xFE", 0) == 0 || line.rfind("\xFE\xFF", 0) == 0))
            fail("a UTF-16 text file; OBJ is read as ASCII or UTF-8");
        for (size_t i = 0; i < line.size(); ++i) {
            const unsigned char c = static_cast<unsigned char>(line[i]);
            if ((c < 0x20 && c != '\t' && c != '\r' && c != '\v' && c != '\f') || c == 0x7F) {
                char byte[8];
                std::snprintf(byte, sizeof byte, "0x%02X", c);
                fail("not an OBJ text file (byte " + std::string(byte) + " in column " + std::to_string(i + 1) + ")");
            }
        }
    }

    void sniffFormat(const std::vector<std::string_view>& tok) const {
        if (line_ == 1 && tok.size() == 1 && tok[0] == "ply") fail("a PLY file, not OBJ");
        if (tok[0][0] == '{') fail("a glTF (JSON) file, not OBJ");
        if (tok[0] == "solid") fail("an STL file, not OBJ");
    }

    void noteUnknown(std::string what) {
        const auto [it, isNew] = unknownIndex_.emplace(what, unknown_.size());
        if (isNew)
            unknown_.push_back({std::move(what), line_, 1});
        else
            ++unknown_[it->second].count;
    }

    // One warning per unknown keyword, for the first few keywords; a file of nothing else is not
    // OBJ at all.
    void reportUnknown() {
        constexpr size_t kMaxWarnings = 8;
        if (!sawObjStatement_ && !unknown_.empty())
            throw ObjError(where(unknown_[0].firstLine) + "not an OBJ file (no line is an OBJ statement; " +
                           unknown_[0].what + " is not one)");
        for (size_t i = 0; i < unknown_.size() && i < kMaxWarnings; ++i) {
            const Unknown& u = unknown_[i];
            mesh_.warnings.push_back(where(u.firstLine) + "unknown " + u.what + " ignored" +
                                     (u.count > 1 ? ", " + std::to_string(u.count) + " lines in all" : ""));
        }
        if (unknown_.size() > kMaxWarnings)
            mesh_.warnings.push_back(name_ + ": " + std::to_string(unknown_.size() - kMaxWarnings) +
                                     " more unknown keywords ignored");
    }

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
            fail("cannot parse " + std::string(what) + " " + quote(s));
        return value;
    }

    float toFloat(std::string_view s, const char* what) const {
        std::string_view t = skipPlus(s);
        float value = 0;
        auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
        if (end != t.data() + t.size() || t.empty() || (ec != std::errc() && ec != std::errc::result_out_of_range) ||
            !std::isfinite(value))
            fail("cannot parse " + std::string(what) + " " + quote(s));
        if (ec == std::errc::result_out_of_range) {
            // Too small for a float rounds to it (1e-50 is 0); too large is refused.
            const double d = std::strtod(std::string(t).c_str(), nullptr);
            if (!(std::fabs(d) <= double(FLT_MAX)))
                fail(std::string(what) + " " + quote(s) + " is beyond the float range (largest 3.4e38)");
            value = float(d);
        }
        return value;
    }

    void parseLine(std::string_view line) {
        size_t hash = line.find('#');
        if (hash != std::string_view::npos) line = line.substr(0, hash);
        std::vector<std::string_view> tok = split(line);
        if (tok.empty()) return;
        if (!sawContent_) sniffFormat(tok);
        sawContent_ = true;
        std::string_view key = tok[0];
        if (key == "v") {
            parseVertex(tok);
        } else if (key == "vt") {
            parseTexCoord(tok);
        } else if (key == "f") {
            parseFace(tok);
        } else if (key == "t") {
            parseTag(tok);
        } else if (!ignored(key)) {
            noteUnknown("statement " + quote(key));
            return;
        }
        sawObjStatement_ = true;
    }

    void parseVertex(const std::vector<std::string_view>& tok) {
        const size_t n = tok.size() - 1;
        if (n != 3 && n != 4 && n != 6)
            fail("v takes 3 or 4 coordinates (6 with colour), got " + std::to_string(n));
        for (size_t c = 1; c <= 3; ++c) mesh_.positions.push_back(toFloat(tok[c], "coordinate"));
        for (size_t c = 4; c <= n; ++c) toFloat(tok[c], n == 4 ? "coordinate" : "colour");  // checked, not used
    }

    void parseTexCoord(const std::vector<std::string_view>& tok) {
        const size_t n = tok.size() - 1;
        if (n != 2 && n != 3) fail("vt takes 2 texture coordinates (3 with w), got " + std::to_string(n));
        for (size_t c = 1; c <= 2; ++c) mesh_.uvs.push_back(toFloat(tok[c], "texture coordinate"));
        if (n == 3) toFloat(tok[3], "texture coordinate");  // checked, not used
    }

    // A 1-based or negative (relative) OBJ index into `count` items read so far, made 0-based;
    // an index past the end is checked once the whole file is read.
    int toIndex(std::string_view text, const char* what, const char* items, int count) const {
        int index = toInt(text, what);
        if (index == 0) fail(std::string(what) + " 0 (OBJ indices start at 1)");
        if (index > 0) return index - 1;
        index += count;
        if (index < 0)
            fail(std::string(what) + " " + std::string(text) + " is before the first " + items + " (" +
                 std::to_string(count) + " read so far)");
        return index;
    }

    void parseFace(const std::vector<std::string_view>& tok) {
        int corners = int(tok.size()) - 1;
        if (corners < 3) fail("face has " + std::to_string(corners) + " corners, needs at least 3");
        const bool first = firstFaceLine_ == 0;
        if (first) firstFaceLine_ = line_;
        for (int c = 1; c <= corners; ++c) {
            std::string_view corner = tok[c];
            const size_t slash = corner.find('/');
            std::string_view pos = corner.substr(0, slash);
            mesh_.faceVerts.push_back(toIndex(pos, "face index", "vertex", mesh_.numVertices()));
            std::string_view uv = slash == std::string_view::npos ? std::string_view() : corner.substr(slash + 1);
            uv = uv.substr(0, uv.find('/'));
            if (first && c == 1) cornersHaveUVs_ = !uv.empty();
            if (uv.empty() == cornersHaveUVs_)
                fail("corner " + std::to_string(c) + " " + quote(corner) + (uv.empty() ? " names no" : " names a") +
                     " texture coordinate (vt) but the first corner of line " + std::to_string(firstFaceLine_) +
                     (uv.empty() ? " does" : " does not") + "; every corner must name one, or none");
            if (!uv.empty()) mesh_.faceUVs.push_back(toIndex(uv, "texture index", "texture coordinate", mesh_.numUVs()));
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

    void checkUVIndices() const {
        const int n = mesh_.numUVs();
        size_t k = 0;
        for (int f = 0; f < mesh_.numFaces() && !mesh_.faceUVs.empty(); ++f)
            for (int c = 0; c < mesh_.faceSizes[f]; ++c, ++k)
                if (mesh_.faceUVs[k] >= n)
                    throw ObjError(where(mesh_.faceLines[f]) + "texture index " + std::to_string(mesh_.faceUVs[k] + 1) +
                                   " is out of range (" + std::to_string(n) + " texture coordinates)");
    }

    // `t name I/F/S ints floats strings`
    void parseTag(const std::vector<std::string_view>& tok) {
        if (tok.size() < 2) fail("tag without a name");
        std::string name(tok[1]);
        if (name != "crease" && name != "corner" && name != "hole" && name != "interpolateboundary" &&
            name != "creasemethod" && name != "smoothtriangles") {
            noteUnknown("tag " + quote(name));
            return;
        }
        if (tok.size() < 3) fail("tag '" + name + "' has no argument counts");
        int counts[3];
        std::string_view spec = tok[2];
        for (int i = 0; i < 3; ++i) {
            size_t slash = spec.find('/');
            if ((i < 2) == (slash == std::string_view::npos))
                fail("tag '" + name + "': cannot parse counts " + quote(tok[2]));
            counts[i] = toInt(spec.substr(0, slash), "tag count");
            if (counts[i] < 0) fail("tag '" + name + "': negative count in " + quote(tok[2]));
            spec = i < 2 ? spec.substr(slash + 1) : std::string_view();
        }
        const int nInt = counts[0], nFloat = counts[1], nString = counts[2];
        // Each count may be up to INT_MAX: add them in 64 bits.
        const long long announced = (long long)nInt + nFloat + nString;
        if ((long long)tok.size() - 3 != announced)
            fail("tag '" + name + "' announces " + std::to_string(announced) + " arguments, has " +
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
        } else if (name == "smoothtriangles") {  // OpenSubdiv's spelling: smooth or catmark (the default rule)
            expect(nInt == 0 && nFloat == 0 && nString == 1, "0/0/1");
            if (strings[0] != "smooth" && strings[0] != "catmark")
                fail("smoothtriangles '" + std::string(strings[0]) + "' is not smooth or catmark");
            mesh_.smoothTriangles = strings[0] == "smooth";
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

TopologyDescriptor ObjMesh::descriptor(FVarChannel& uvChannel) const {
    TopologyDescriptor d = descriptor();
    if (!hasUVs()) return d;
    uvChannel.numValues = numUVs();
    uvChannel.valueIndices = faceUVs.data();
    d.numFVarChannels = 1;
    d.fvarChannels = &uvChannel;
    return d;
}

Options ObjMesh::applyTags(Options base) const {
    if (boundary) base.boundary = *boundary;
    if (creaseMethod) base.creaseMethod = *creaseMethod;
    if (smoothTriangles && takesSmoothTriangles(base.scheme)) base.smoothTriangles = *smoothTriangles;
    return base;
}

std::string ObjMesh::describe(const TopologyDiagnostic& diagnostic) const {
    using Component = TopologyDiagnostic::Component;
    const Component c = diagnostic.component;
    const std::vector<int>* lines = c == Component::Face     ? &faceLines
                                    : c == Component::Crease ? &creaseLines
                                    : c == Component::Corner ? &cornerLines
                                    : c == Component::Hole   ? &holeLines
                                                             : nullptr;
    const int i = diagnostic.index;
    if (!lines || i < 0 || size_t(i) >= lines->size()) return name + ": " + diagnostic.message();
    std::string text = name + ":" + std::to_string((*lines)[i]) + ": ";
    if (c == Component::Face) {
        text += "face " + std::to_string(i + 1) + ": ";
        if (diagnostic.vertex >= 0) text += "vertex " + std::to_string(diagnostic.vertex + 1) + " ";
    } else {
        text += c == Component::Crease ? "t crease: " : c == Component::Corner ? "t corner: " : "t hole: ";
        if (diagnostic.vertex >= 0) text += "vertex " + std::to_string(diagnostic.vertex) + " ";
    }
    return text + diagnostic.problem;
}

ObjMesh parseObj(std::istream& in, const std::string& name) { return Parser(in, name).run(); }

ObjMesh readObj(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw ObjError(path + ": is a folder, not an OBJ file");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ObjError(path + ": cannot open file" + reason(errno));
    return parseObj(in, path);
}

void writeObj(std::ostream& out, const float* positions, const LevelFaces& faces, const float* normals,
              const ObjUVs& uvs) {
    char buf[128];
    auto writeTriples = [&](const char* tag, const float* data) {
        for (int v = 0; v < faces.numVertices(); ++v) {
            const float* p = data + 3 * size_t(v);
            std::snprintf(buf, sizeof buf, "%s %.9g %.9g %.9g\n", tag, double(p[0]), double(p[1]), double(p[2]));
            out << buf;
        }
    };
    writeTriples("v", positions);
    const bool withUVs = uvs.values != nullptr;
    for (int i = 0; withUVs && i < uvs.numValues; ++i) {
        const float* uv = uvs.values + 2 * size_t(i);
        std::snprintf(buf, sizeof buf, "vt %.9g %.9g\n", double(uv[0]), double(uv[1]));
        out << buf;
    }
    if (normals) writeTriples("vn", normals);
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        out << 'f';
        int corner = faces.offsets()[f];
        for (int v : faces.verticesOfFace(f)) {
            out << ' ' << v + 1;
            if (withUVs) out << '/' << uvs.cornerValues[corner] + 1;
            if (normals) out << (withUVs ? "/" : "//") << v + 1;
            ++corner;
        }
        out << '\n';
    }
}

namespace {

// A fresh file beside `target`, created exclusively so that no other file is truncated.
std::string createTemporary(const std::filesystem::path& target) {
    std::string hidden(1, '.');
    hidden += target.filename().string();
    const std::string stem = (target.parent_path() / hidden).string();
    for (int attempt = 0;; ++attempt) {
        const std::string name = stem + "." + std::to_string(attempt) + ".tmp";
        errno = 0;
        if (std::FILE* f = std::fopen(name.c_str(), "wbx")) {
            std::fclose(f);
            return name;
        }
        if (errno != EEXIST || attempt == 99) throw ObjError(target.string() + ": cannot write file" + reason(errno));
    }
}

// Runs `write` on `out` (already open on `name`) and closes it; false if any of it failed.
bool writeAndClose(std::ofstream& out, const std::function<void(std::ostream&)>& write) {
    write(out);
    out.flush();
    const bool written = bool(out);
    out.close();
    return written && bool(out);
}

}  // namespace

void writeReplacing(const std::string& path, const std::function<void(std::ostream&)>& write) {
    namespace fs = std::filesystem;
    const std::string failed = path + ": cannot write file";
    std::error_code ec;
    fs::path target = fs::path(path);
    if (fs::is_symlink(fs::symlink_status(target, ec))) {  // replace what the link names, not the link
        target = fs::canonical(target, ec);
        if (ec) throw ObjError(failed + reason(ec.value()));
    }
    const fs::file_status status = fs::status(target, ec);  // file_type::not_found if there is none
    if (fs::is_directory(status)) throw ObjError(failed + " (it is a directory)");
    if (fs::exists(status) && !fs::is_regular_file(status)) {  // a device or a pipe: nothing to replace
        std::ofstream out(target, std::ios::binary);
        errno = 0;
        if (!out || !writeAndClose(out, write)) throw ObjError(failed + reason(errno));
        return;
    }
    const std::string temporary = createTemporary(target);
    try {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        errno = 0;
        if (!out || !writeAndClose(out, write)) throw ObjError(failed + reason(errno));
        if (fs::exists(status)) fs::permissions(temporary, status.permissions(), ec);  // keep the old file's mode
        fs::rename(temporary, target, ec);
        if (ec) throw ObjError(failed + reason(ec.value()));
    } catch (...) {
        fs::remove(temporary, ec);
        throw;
    }
}

void writeObj(const std::string& path, const float* positions, const LevelFaces& faces, const float* normals,
              const ObjUVs& uvs) {
    writeReplacing(path, [&](std::ostream& out) { writeObj(out, positions, faces, normals, uvs); });
}

}  // namespace quadtri::io
