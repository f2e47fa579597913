// OBJ reading (positions, faces, OpenSubdiv tags, errors) and writing.
#include <gtest/gtest.h>

#include <climits>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/test_support.h"
#include "tools/byte_size.h"
#include "tools/obj_io.h"

namespace quadtri::io {
namespace {

ObjMesh parse(const std::string& text, const std::string& name = "mesh.obj") {
    std::istringstream in(text);
    return parseObj(in, name);
}

// The message of the ObjError that parsing `text` throws, or "" if it parses.
std::string parseError(const std::string& text) {
    try {
        parse(text, "bad.obj");
    } catch (const ObjError& e) {
        return e.what();
    }
    return "";
}

// Expects parsing to fail at `line` with a message containing `problem`.
void expectError(const std::string& text, int line, const std::string& problem) {
    std::string message = parseError(text);
    std::string prefix = "bad.obj:" + std::to_string(line) + ": ";
    EXPECT_EQ(message.substr(0, prefix.size()), prefix) << "message: " << message << "\ninput:\n" << text;
    EXPECT_NE(message.find(problem), std::string::npos) << "message: " << message << "\nexpected: " << problem;
}

const char* kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjIo, PositionsAndFaces) {
    ObjMesh m = parse("# a comment\n\nv 0 0 0\nv 1.5 -2 3e2 1.0\nv 0 1 0  # trailing\nv 1 1 1\n"
                      "vt 0 0\nvn 0 0 1\no obj\ng grp\ns 1\nusemtl m\nmtllib m.mtl\n"
                      "f 1 2 3\nf 2 4 3 1\n");
    EXPECT_EQ(m.numVertices(), 4);
    ASSERT_EQ(m.positions.size(), 12u);
    EXPECT_FLOAT_EQ(m.positions[3], 1.5f);
    EXPECT_FLOAT_EQ(m.positions[4], -2.0f);
    EXPECT_FLOAT_EQ(m.positions[5], 300.0f);
    EXPECT_EQ(m.faceSizes, (std::vector<int>{3, 4}));
    EXPECT_EQ(m.faceVerts, (std::vector<int>{0, 1, 2, 1, 3, 2, 0}));
    EXPECT_TRUE(m.warnings.empty());
    EXPECT_FALSE(m.boundary.has_value());
    EXPECT_FALSE(m.creaseMethod.has_value());
}

TEST(ObjIo, SlashFormsAndNegativeIndices) {
    ObjMesh m = parse(std::string(kQuad) + "f 1//1 2//2 3//3 4//4\nf -4 -3 -2//1\n");
    EXPECT_EQ(m.faceSizes, (std::vector<int>{4, 3}));
    EXPECT_EQ(m.faceVerts, (std::vector<int>{0, 1, 2, 3, 0, 1, 2}));
    EXPECT_FALSE(m.hasUVs());
    // With texture coordinates: v/vt and v/vt/vn, relative vt indices too.
    ObjMesh t = parse(std::string(kQuad) + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1 0.5\nf 1/1 2/2/2 3/-2 4/4/4\nf -4/-4 -3/2 -2/3/1\n");
    EXPECT_EQ(t.faceVerts, (std::vector<int>{0, 1, 2, 3, 0, 1, 2}));
    EXPECT_EQ(t.faceUVs, (std::vector<int>{0, 1, 2, 3, 0, 1, 2}));
    EXPECT_EQ(t.uvs, (std::vector<float>{0, 0, 1, 0, 1, 1, 0, 1}));
    // Relative to the vertices read so far, not to the final count.
    ObjMesh r = parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nf -1 -2 -3\n");
    EXPECT_EQ(r.faceVerts, (std::vector<int>{0, 1, 2, 3, 2, 1}));
}

TEST(ObjIo, WindowsLineEndingsAndPlusSigns) {
    ObjMesh m = parse("v +1 0 0\r\nv 0 1 0\r\nv 0 0 +1.5\r\nf 1 2 +3\r\nt interpolateboundary 1/0/0 1\r\n");
    EXPECT_EQ(m.positions, (std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1.5f}));
    EXPECT_EQ(m.faceVerts, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(m.boundary, BoundaryInterpolation::EdgeAndCorner);
    EXPECT_TRUE(m.warnings.empty());
}

TEST(ObjIo, FacesBeforeVertices) {
    ObjMesh m = parse("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
    EXPECT_EQ(m.faceVerts, (std::vector<int>{0, 1, 2}));
}

TEST(ObjIo, CreaseTags) {
    ObjMesh m = parse(std::string(kQuad) +
                      "t crease 2/1/0 0 1 2.5\n"
                      "t crease 4/1/0 1 2 2 3 10\n"
                      "t crease 4/2/0 3 0 0 2 1 0.5\n");
    EXPECT_EQ(m.creasePairs, (std::vector<int>{0, 1, 1, 2, 2, 3, 3, 0, 0, 2}));
    EXPECT_EQ(m.creaseSharpness, (std::vector<float>{2.5f, 10.0f, 10.0f, 1.0f, 0.5f}));
    TopologyDescriptor d = m.descriptor();
    EXPECT_EQ(d.numCreases, 5);
    EXPECT_EQ(d.creaseVertexPairs[9], 2);
    EXPECT_EQ(d.creaseWeights[4], 0.5f);
}

TEST(ObjIo, CornerAndHoleTags) {
    ObjMesh m = parse(std::string(kQuad) + "f 1 2 3 4\nf 4 3 2 1\n"
                                           "t corner 1/1/0 2 3.0\n"
                                           "t corner 2/1/0 0 1 1.5\n"
                                           "t corner 2/2/0 3 1 4 5\n"
                                           "t hole 1/0/0 1\n"
                                           "t hole 2/0/0 0 1\n");
    EXPECT_EQ(m.corners, (std::vector<int>{2, 0, 1, 3, 1}));
    EXPECT_EQ(m.cornerSharpness, (std::vector<float>{3.0f, 1.5f, 1.5f, 4.0f, 5.0f}));
    EXPECT_EQ(m.holes, (std::vector<int>{1, 0, 1}));
    TopologyDescriptor d = m.descriptor();
    EXPECT_EQ(d.numVertices, 4);
    EXPECT_EQ(d.numFaces, 2);
    EXPECT_EQ(d.numVertsPerFace[1], 4);
    EXPECT_EQ(d.faceVertIndices[4], 3);
    EXPECT_EQ(d.numCorners, 5);
    EXPECT_EQ(d.cornerVertexIndices[0], 2);
    EXPECT_EQ(d.cornerWeights[3], 4.0f);
    EXPECT_EQ(d.numHoles, 3);
    EXPECT_EQ(d.holeIndices[1], 0);
}

TEST(ObjIo, BoundaryAndCreaseMethodTags) {
    const std::pair<int, BoundaryInterpolation> cases[] = {{0, BoundaryInterpolation::None},
                                                           {1, BoundaryInterpolation::EdgeAndCorner},
                                                           {2, BoundaryInterpolation::EdgeOnly}};
    for (auto [value, expected] : cases) {
        ObjMesh m = parse(std::string(kQuad) + "t interpolateboundary 1/0/0 " + std::to_string(value) + "\n");
        ASSERT_TRUE(m.boundary.has_value());
        EXPECT_EQ(*m.boundary, expected) << value;
    }
    EXPECT_EQ(parse("t creasemethod 0/0/1 chaikin\n").creaseMethod, CreaseMethod::Chaikin);
    EXPECT_EQ(parse("t creasemethod 0/0/1 uniform\n").creaseMethod, CreaseMethod::Uniform);
    EXPECT_EQ(parse("t creasemethod 0/0/1 normal\n").creaseMethod, CreaseMethod::Uniform);  // OpenSubdiv's name
}

TEST(ObjIo, ApplyTags) {
    Options base;
    base.scheme = Scheme::Bilinear;
    base.boundary = BoundaryInterpolation::None;
    base.creaseMethod = CreaseMethod::Uniform;
    base.leftHanded = true;

    Options untouched = parse(kQuad).applyTags(base);
    EXPECT_EQ(untouched.boundary, BoundaryInterpolation::None);
    EXPECT_EQ(untouched.creaseMethod, CreaseMethod::Uniform);

    Options tagged = parse("t interpolateboundary 1/0/0 1\nt creasemethod 0/0/1 chaikin\n").applyTags(base);
    EXPECT_EQ(tagged.boundary, BoundaryInterpolation::EdgeAndCorner);
    EXPECT_EQ(tagged.creaseMethod, CreaseMethod::Chaikin);
    EXPECT_EQ(tagged.scheme, Scheme::Bilinear);
    EXPECT_TRUE(tagged.leftHanded);
}

TEST(ObjIo, ByteOrderMarkIsSkipped) {
    const std::string text = std::string(kQuad) + "f 1 2 3 4\n";
    ObjMesh plain = parse(text);
    ObjMesh marked = parse("\xEF\xBB\xBF" + text);
    EXPECT_EQ(marked.positions, plain.positions);
    EXPECT_EQ(marked.faceVerts, plain.faceVerts);
    EXPECT_TRUE(marked.warnings.empty());
}

TEST(ObjIo, OtherFormatsAreNamed) {
    expectError(std::string("v 0 0 0\nv 1 0\0 0\n", 18), 2, "not an OBJ text file (byte 0x00 in column 6)");
    expectError("\x1f\x8b\x08\x00", 1, "not an OBJ text file (byte 0x1F in column 1)");  // gzip
    expectError("ply\nformat ascii 1.0\nelement vertex 3\n", 1, "a PLY file, not OBJ");
    expectError("ply\r\nformat binary_little_endian 1.0\r\n", 1, "a PLY file, not OBJ");
    expectError("{\n  \"asset\": {\"version\": \"2.0\"}\n}\n", 1, "a glTF (JSON) file, not OBJ");
    expectError(std::string("glTF\x02\0\0\0", 8), 1, "a binary glTF (.glb) file, not OBJ");
    expectError("solid cube\n  facet normal 0 0 1\n", 1, "an STL file, not OBJ");
    expectError(std::string("\xFF\xFEv\0 \0", 6), 1, "a UTF-16 text file");
    // Text that is not OBJ at all: named once, at its first line.
    expectError("\nHello,\nthis is a letter.\n", 2, "not an OBJ file (no line is an OBJ statement; statement 'Hello,'");
}

TEST(ObjIo, LongLinesAreCutShortInMessages) {
    std::string v = "v";
    for (int i = 0; i < 200000; ++i) v += " 1";
    expectError(v + "\n", 1, "v takes 3 or 4 coordinates (6 with colour), got 200000");
    const std::string message = parseError("v 0 0 " + std::string(100000, '7') + "x\n");
    EXPECT_LT(message.size(), 200u) << message.substr(0, 200);
}

TEST(ObjIo, TinyCoordinatesRoundToFloat) {
    ObjMesh m = parse("v 1e-50 -1e-400 1e-40\n");
    EXPECT_EQ(m.positions[0], 0.0f);
    EXPECT_EQ(m.positions[1], 0.0f);
    EXPECT_GT(m.positions[2], 0.0f);  // a denormal, not 0
    EXPECT_LT(m.positions[2], 1.1e-40f);
}

TEST(ObjIo, UnknownStatementsWarnOncePerKeyword) {
    ObjMesh m = parse(std::string(kQuad) + "l 1 2\nf 1 2 3\nl 2 3\ncurv 0 1 1 2\nl 3 4\nt foo 0/0/0\nt foo 0/0/0\n", "w.obj");
    ASSERT_EQ(m.warnings.size(), 3u);
    EXPECT_EQ(m.warnings[0], "w.obj:5: unknown statement 'l' ignored, 3 lines in all");
    EXPECT_EQ(m.warnings[1], "w.obj:8: unknown statement 'curv' ignored");
    EXPECT_EQ(m.warnings[2], "w.obj:10: unknown tag 'foo' ignored, 2 lines in all");
    // Many keywords: the first few, then a count.
    std::string many = "v 0 0 0\n";
    for (int k = 0; k < 1000; ++k) many += "x" + std::to_string(k) + "\n";
    ObjMesh n = parse(many, "n.obj");
    ASSERT_EQ(n.warnings.size(), 9u);
    EXPECT_EQ(n.warnings[0], "n.obj:2: unknown statement 'x0' ignored");
    EXPECT_EQ(n.warnings[8], "n.obj: 992 more unknown keywords ignored");
}

TEST(ObjIo, DescribeUsesTheFileNumbering) {
    using Component = TopologyDiagnostic::Component;
    ObjMesh m = parse(std::string(kQuad) + "# faces\nf 1 2 3\nf 1 3 4 3\nt crease 2/1/0 1 3 2.0\n"
                                           "t corner 1/1/0 2 1.0\nt hole 1/0/0 0\n");
    EXPECT_EQ(m.describe({Component::Face, 1, 2, "appears more than once"}), "mesh.obj:7: face 2: vertex 3 appears more than once");
    EXPECT_EQ(m.describe({Component::Crease, 0, -1, "vertices 1, 3 are not an edge of the mesh; crease ignored"}),
              "mesh.obj:8: t crease: vertices 1, 3 are not an edge of the mesh; crease ignored");
    EXPECT_EQ(m.describe({Component::Corner, 0, -1, "vertex 2: negative sharpness -1"}),
              "mesh.obj:9: t corner: vertex 2: negative sharpness -1");
    EXPECT_EQ(m.describe({Component::Hole, 0, -1, "face index 0 is out of range [0, 0)"}),
              "mesh.obj:10: t hole: face index 0 is out of range [0, 0)");
    EXPECT_EQ(m.describe({Component::None, -1, -1, "level 2 is too deep"}), "mesh.obj: level 2 is too deep");
}

TEST(ObjIo, UnknownTagsAndStatementsWarn) {
    ObjMesh m = parse(std::string(kQuad) + "t facevaryinginterpolateboundary 1/0/0 1\nf 1 2 3\nl 1 2\n", "w.obj");
    ASSERT_EQ(m.warnings.size(), 2u);
    EXPECT_EQ(m.warnings[0], "w.obj:5: unknown tag 'facevaryinginterpolateboundary' ignored");
    EXPECT_EQ(m.warnings[1].rfind("w.obj:7: ", 0), 0u) << m.warnings[1];
    EXPECT_EQ(m.numFaces(), 1);
}

TEST(ObjIo, NumberErrors) {
    expectError("v 0 0 0\nv 1 x 0\n", 2, "cannot parse coordinate 'x'");
    expectError("v 0 0 0\nv 1 1.5.2 0\n", 2, "cannot parse coordinate '1.5.2'");
    expectError("v 0 0 nan\n", 1, "cannot parse coordinate");
    expectError("v 0 0 +-1\n", 1, "cannot parse coordinate '+-1'");
    expectError("v 0 0 1e60\n", 1, "coordinate '1e60' is beyond the float range");
    expectError("v 0 0\n", 1, "v takes 3 or 4 coordinates (6 with colour), got 2");
    expectError("v 0 0 0 1 1\n", 1, "v takes 3 or 4 coordinates (6 with colour), got 5");
    expectError("v 0 0 0 1 1 1 1\n", 1, "v takes 3 or 4 coordinates (6 with colour), got 7");
    expectError("v 0 0 0 1 red 1\n", 1, "cannot parse colour 'red'");
    expectError(std::string(kQuad) + "f 1 2 a\n", 5, "cannot parse face index 'a'");
    expectError(std::string(kQuad) + "f 1 2 99999999999\n", 5, "cannot parse face index");
    expectError(std::string(kQuad) + "t crease 2/1/0 0 1 sharp\n", 5, "cannot parse tag value 'sharp'");
    expectError(std::string(kQuad) + "t corner 1/1/0 a 1\n", 5, "cannot parse tag integer 'a'");
    expectError(std::string(kQuad) + "t crease 2-1-0 0 1 1\n", 5, "cannot parse counts '2-1-0'");
}

TEST(ObjIo, FaceErrors) {
    expectError(std::string(kQuad) + "f 1 2\n", 5, "face has 2 corners, needs at least 3");
    expectError(std::string(kQuad) + "f 1 0 2\n", 5, "face index 0");
    expectError(std::string(kQuad) + "f 1 -5 2\n", 5, "face index -5 is before the first vertex");
    // Out of range of the final vertex count: reported after the whole file, naming the face's line.
    expectError("v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\nf 1 2 4\n# end\n", 5,
                "face index 4 is out of range (3 vertices)");
}

TEST(ObjIo, TextureCoordinates) {
    // vt lines without corners that name them: no channel.
    ObjMesh plain = parse(std::string(kQuad) + "vt 0 0\nf 1 2 3 4\n");
    EXPECT_EQ(plain.numUVs(), 1);
    EXPECT_FALSE(plain.hasUVs());
    FVarChannel channel;
    EXPECT_EQ(plain.descriptor(channel).numFVarChannels, 0);
    ObjMesh uv = parse(std::string(kQuad) + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n");
    const TopologyDescriptor d = uv.descriptor(channel);
    ASSERT_EQ(d.numFVarChannels, 1);
    EXPECT_EQ(d.fvarChannels, &channel);
    EXPECT_EQ(channel.numValues, 4);
    EXPECT_EQ(std::vector<int>(channel.valueIndices, channel.valueIndices + 4), (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(uv.descriptor().numFVarChannels, 0);
}

TEST(ObjIo, TextureCoordinateErrors) {
    const std::string q = std::string(kQuad) + "vt 0 0\nvt 1 0\nvt 1 1\n";
    // Some corners name a vt and others not: the corner, and the line that decided.
    expectError(q + "f 1/1 2/2 3/3\nf 1/1 3/3 4\n", 9, "corner 3 '4' names no texture coordinate (vt) but the first corner of line 8 does");
    expectError(q + "f 1 2 3\nf 1/1 3/3 4/1\n", 9, "corner 1 '1/1' names a texture coordinate (vt) but the first corner of line 8 does not");
    expectError(q + "f 1/1 2//2 3/3\n", 8, "corner 2 '2//2' names no texture coordinate");
    // Out of range: after the whole file, naming the face's line.
    expectError(q + "f 1/1 2/2 3/4\n# end\n", 8, "texture index 4 is out of range (3 texture coordinates)");
    expectError(q + "f 1/1 2/0 3/3\n", 8, "texture index 0 (OBJ indices start at 1)");
    expectError(q + "f 1/1 2/-4 3/3\n", 8, "texture index -4 is before the first texture coordinate (3 read so far)");
    expectError(q + "f 1/1 2/x 3/3\n", 8, "cannot parse texture index 'x'");
    // Not finite, or malformed.
    expectError(std::string(kQuad) + "vt 0 nan\n", 5, "cannot parse texture coordinate 'nan'");
    expectError(std::string(kQuad) + "vt inf 0\n", 5, "cannot parse texture coordinate 'inf'");
    expectError(std::string(kQuad) + "vt 0 0 1e60\n", 5, "texture coordinate '1e60' is beyond the float range");
    expectError(std::string(kQuad) + "vt 0\n", 5, "vt takes 2 texture coordinates (3 with w), got 1");
    expectError(std::string(kQuad) + "vt 0 0 0 0\n", 5, "vt takes 2 texture coordinates (3 with w), got 4");
}

TEST(ObjIo, TagErrors) {
    std::string q(kQuad);
    expectError(q + "t crease 2/1/0 0 1\n", 5, "announces 3 arguments, has 2");
    expectError(q + "t crease 2/1/0 0 1 1 2\n", 5, "announces 3 arguments, has 4");
    expectError(q + "t crease 3/1/0 0 1 2 1\n", 5, "must be 2N/1/0 or 2N/N/0");
    expectError(q + "t crease 4/3/0 0 1 1 2 1 1 1\n", 5, "must be 2N/1/0 or 2N/N/0");
    expectError(q + "t crease 2/1/0 0 -1 1\n", 5, "negative vertex index -1");
    expectError(q + "t corner 2/3/0 0 1 1 1 1\n", 5, "must be N/1/0 or N/N/0");
    expectError(q + "t corner 1/1/0 -2 1\n", 5, "negative vertex index -2");
    expectError(q + "t hole 1/1/0 0 1\n", 5, "must be N/0/0");
    expectError(q + "t hole 1/0/0 -1\n", 5, "negative face index -1");
    expectError(q + "t interpolateboundary 1/0/0 3\n", 5, "interpolateboundary value 3");
    expectError(q + "t interpolateboundary 1/0/0 -1\n", 5, "interpolateboundary value -1");
    expectError(q + "t interpolateboundary 2/0/0 1 1\n", 5, "must be 1/0/0");
    expectError(q + "t creasemethod 0/0/1 smooth\n", 5, "creasemethod 'smooth' is not chaikin, uniform or normal");
    expectError(q + "t creasemethod 0/0/0\n", 5, "must be 0/0/1");
    // Counts up to INT_MAX each: their sum does not overflow.
    expectError(q + "t crease 2147483647/1/0 0 1 1\n", 5, "announces 2147483648 arguments, has 3");
    expectError(q + "t crease 2147483647/2147483647/2147483647 0\n", 5, "announces 6442450941 arguments, has 1");
    expectError(q + "t crease 2147483648/1/0 0 1 1\n", 5, "cannot parse tag count '2147483648'");
}

// A scratch folder for the file tests, removed afterwards.
struct ScratchDir {
    std::filesystem::path path;
    explicit ScratchDir(const std::string& name) : path(std::filesystem::temp_directory_path() / name) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~ScratchDir() { std::filesystem::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
    int entries() const {
        return int(std::distance(std::filesystem::directory_iterator(path), std::filesystem::directory_iterator()));
    }
};

TEST(ObjIo, MissingFile) {
    try {
        readObj("/nonexistent/dir/mesh.obj");
        FAIL() << "no error";
    } catch (const ObjError& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/dir/mesh.obj: cannot open file (No such file or directory)");
    }
    ScratchDir dir("quadtri_test_read_folder");
    try {
        readObj(dir.path.string());
        FAIL() << "no error";
    } catch (const ObjError& e) {
        EXPECT_EQ(std::string(e.what()), dir.path.string() + ": is a folder, not an OBJ file");
    }
}

// A small Topology with faceOffsets/faceVerts/faceHole filled by hand: LevelFaces reads nothing else.
Topology twoFaceTopology() {
    Topology t;
    t.numVertices = 5;
    t.faceOffsets = {0, 4, 7};
    t.faceVerts = {0, 1, 2, 3, 1, 4, 2};
    t.faceHole = {0, 0};
    return t;
}

TEST(ObjIo, WriteThenParse) {
    Topology t = twoFaceTopology();
    const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2.0f / 3.0f, 1e-7f, -123456.789f};
    std::ostringstream out;
    writeObj(out, positions.data(), LevelFaces(t));
    std::istringstream in(out.str());
    ObjMesh m = parseObj(in, "roundtrip");
    EXPECT_EQ(m.positions, positions);  // %.9g round-trips floats exactly
    EXPECT_EQ(m.faceSizes, (std::vector<int>{4, 3}));
    EXPECT_EQ(m.faceVerts, t.faceVerts);
}

TEST(ObjIo, WriteSkipsHoles) {
    Topology t = twoFaceTopology();
    t.faceHole = {1, 0};
    const std::vector<float> positions(15, 0.5f);
    std::ostringstream out;
    writeObj(out, positions.data(), LevelFaces(t));
    EXPECT_EQ(out.str(), "v 0.5 0.5 0.5\nv 0.5 0.5 0.5\nv 0.5 0.5 0.5\nv 0.5 0.5 0.5\nv 0.5 0.5 0.5\nf 2 5 3\n");
}

TEST(ObjIo, WriteToUnwritablePath) {
    Topology t = twoFaceTopology();
    const std::vector<float> positions(15, 0.0f);
    try {
        writeObj("/nonexistent/dir/out.obj", positions.data(), LevelFaces(t));
        FAIL() << "no error";
    } catch (const ObjError& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/dir/out.obj: cannot write file (No such file or directory)");
    }
}

std::string contents(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The error writeReplacing reports, or "" if it succeeds.
std::string replaceError(const std::string& path, const std::function<void(std::ostream&)>& write) {
    try {
        writeReplacing(path, write);
    } catch (const ObjError& e) {
        return e.what();
    }
    return "";
}

TEST(ObjIo, WriteReplacesTheTargetWhole) {
    ScratchDir dir("quadtri_test_write_replace");
    const std::string target = dir.file("mesh.obj");
    std::ofstream(target) << "old\n";
    std::filesystem::permissions(target, std::filesystem::perms(0640));
    EXPECT_EQ(replaceError(target, [](std::ostream& out) { out << "new\n"; }), "");
    EXPECT_EQ(contents(target), "new\n");
    EXPECT_EQ(dir.entries(), 1);  // no temporary left
    EXPECT_EQ(std::filesystem::status(target).permissions(), std::filesystem::perms(0640));
}

TEST(ObjIo, FailedWriteKeepsTheOldFile) {
    ScratchDir dir("quadtri_test_write_fail");
    const std::string target = dir.file("mesh.obj");
    std::ofstream(target) << "old\n";
    // A stream that fails midway, as on a full disk.
    auto fullDisk = [](std::ostream& out) {
        out << "v 0 0 0\n";
        out.setstate(std::ios::badbit);
    };
    EXPECT_EQ(replaceError(target, fullDisk).rfind(target + ": cannot write file", 0), 0u);
    EXPECT_EQ(contents(target), "old\n");
    EXPECT_EQ(dir.entries(), 1);
    // A writer that throws leaves the same.
    EXPECT_THROW(writeReplacing(target, [](std::ostream&) { throw std::runtime_error("interrupted"); }),
                 std::runtime_error);
    EXPECT_EQ(contents(target), "old\n");
    EXPECT_EQ(dir.entries(), 1);
}

TEST(ObjIo, WriteIntoNothingWritable) {
    ScratchDir dir("quadtri_test_write_nowhere");
    auto write = [](std::ostream& out) { out << "v 0 0 0\n"; };
    EXPECT_EQ(replaceError(dir.file("missing/mesh.obj"), write),
              dir.file("missing/mesh.obj") + ": cannot write file (No such file or directory)");
    std::filesystem::create_directory(dir.file("folder.obj"));
    EXPECT_EQ(replaceError(dir.file("folder.obj"), write), dir.file("folder.obj") + ": cannot write file (it is a directory)");
    std::ofstream(dir.file("plain")) << "old\n";
    EXPECT_EQ(replaceError(dir.file("plain/mesh.obj"), write),
              dir.file("plain/mesh.obj") + ": cannot write file (Not a directory)");
    EXPECT_EQ(contents(dir.file("plain")), "old\n");
    EXPECT_EQ(dir.entries(), 2);
    // A device is written in place, and its failure is caught at the flush.
    if (std::filesystem::exists("/dev/full")) {
        EXPECT_EQ(replaceError("/dev/full", write), "/dev/full: cannot write file (No space left on device)");
    }
}

TEST(ObjIo, WriteThroughASymlinkReplacesItsTarget) {
    ScratchDir dir("quadtri_test_write_link");
    std::ofstream(dir.file("real.obj")) << "old\n";
    std::filesystem::create_symlink("real.obj", dir.file("link.obj"));
    EXPECT_EQ(replaceError(dir.file("link.obj"), [](std::ostream& out) { out << "new\n"; }), "");
    EXPECT_TRUE(std::filesystem::is_symlink(dir.file("link.obj")));
    EXPECT_EQ(contents(dir.file("real.obj")), "new\n");
    EXPECT_EQ(dir.entries(), 2);
}

TEST(ByteSize, UnitsAndRefusals) {
    using cli::parseByteSize;
    EXPECT_EQ(parseByteSize("0"), std::size_t(0));
    EXPECT_EQ(parseByteSize("4096"), std::size_t(4096));
    EXPECT_EQ(parseByteSize("12B"), std::size_t(12));
    EXPECT_EQ(parseByteSize("3KB"), std::size_t(3000));
    EXPECT_EQ(parseByteSize("3kib"), std::size_t(3072));
    EXPECT_EQ(parseByteSize("512MiB"), std::size_t(512) << 20);
    EXPECT_EQ(parseByteSize("2mb"), std::size_t(2000000));
    EXPECT_EQ(parseByteSize("8GiB"), std::size_t(8) << 30);
    EXPECT_EQ(parseByteSize("8 GiB"), std::size_t(8) << 30);
    EXPECT_EQ(parseByteSize("5GB"), std::size_t(5000000000ull));
    EXPECT_EQ(parseByteSize("1TiB"), std::size_t(1) << 40);
    EXPECT_EQ(parseByteSize("2tb"), std::size_t(2000000000000ull));
    for (const char* bad : {"", "GiB", "8 parsecs", "-1", "+1", "1.5GiB", "8G", "8gibs", "8 ", "8  GiB", "0x10",
                            "99999999999999999999", "16777216TiB", "18446744073709551616"})
        EXPECT_FALSE(parseByteSize(bad).has_value()) << bad;
    EXPECT_EQ(parseByteSize("18446744073709551615"), std::size_t(18446744073709551615ull));
}

TEST(ObjIo, ReadsOpenSubdivShape) {
    ObjMesh m = readObj(test::meshPath("osd/catmark_edgeonly.obj"));
    EXPECT_GT(m.numVertices(), 0);
    EXPECT_GT(m.numFaces(), 0);
    EXPECT_EQ(m.corners, (std::vector<int>{16, 19, 36, 37, 38, 39}));
    EXPECT_EQ(m.cornerSharpness, (std::vector<float>{10, 10, 10, 10, 2, 2}));
    ASSERT_TRUE(m.boundary.has_value());
    EXPECT_EQ(*m.boundary, BoundaryInterpolation::EdgeOnly);
    EXPECT_TRUE(m.creasePairs.empty());
    EXPECT_TRUE(m.warnings.empty());
    for (int v : m.faceVerts) {
        EXPECT_GE(v, 0);
        EXPECT_LT(v, m.numVertices());
    }
}

TEST(ObjIo, ReadsEveryTestMeshAndWritesItBack) {
    // Every shape parses; writing level 0 as-is and reading it back gives the same mesh.
    int files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(test::meshPath(""))) {
        if (entry.path().extension() != ".obj") continue;
        ++files;
        const std::string name = entry.path().string();
        ObjMesh m = readObj(name);
        Topology t;
        t.numVertices = m.numVertices();
        for (int f = 0; f < m.numFaces(); ++f) t.faceOffsets.push_back(t.faceOffsets.back() + m.faceSizes[f]);
        t.faceVerts = m.faceVerts;
        t.faceHole.assign(m.numFaces(), 0);
        std::ostringstream out;
        writeObj(out, m.positions.data(), LevelFaces(t));
        std::istringstream in(out.str());
        ObjMesh back = parseObj(in, name);
        EXPECT_EQ(back.positions, m.positions) << name;
        EXPECT_EQ(back.faceSizes, m.faceSizes) << name;
        EXPECT_EQ(back.faceVerts, m.faceVerts) << name;
    }
    EXPECT_GT(files, 40);
}

}  // namespace
}  // namespace quadtri::io
