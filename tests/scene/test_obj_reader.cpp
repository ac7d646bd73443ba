// lenslab's strict OBJ reader (src/scene/obj_reader.h): what it reads, and the one message
// "NAME:LINE: REASON" for each input tinyobjloader, the reader it replaced, took silently
// (NaN and infinite or unreadable coordinates read as 0, fractional indices truncated, an
// index beyond the integer range wrapped round, a face of two corners dropped, a negative index
// reported with the wrong number).

#include <gtest/gtest.h>

#include <string>

#include "scene/obj_reader.h"

namespace lenslab {
namespace {

// The message read_obj() refuses `text` with, or "read" when it reads it.
std::string obj_refusal(const std::string& text, const ObjLimits& limits = {}) {
    try {
        (void)read_obj(text, "t.obj", limits);
    } catch (const ObjError& e) {
        return e.what();
    }
    return "read";
}

const std::string kObjTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
const std::string kObjSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjReader, ReadsVerticesAndFacesInEveryCornerForm) {
    const ObjMesh m = read_obj(kObjSquare +
                                   "vt 0 0\nvt 1\nvt 0.5 0.5 0\nvn 0 0 1\n"
                                   "f 1 2 3\nf 1/1 3/2 4/3\nf 1//1 2//1 3//1\nf 1/1/1 3/2/1 4/3/1\n"
                                   "f -4 -3 -2 -1\n",
                               "t.obj");
    ASSERT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.vertices[2].x, 1.0);
    EXPECT_EQ(m.vertices[2].y, 1.0);
    ASSERT_EQ(m.faces.size(), 5u);
    EXPECT_EQ(m.faces[1].first, 3u);
    EXPECT_EQ(m.faces[1].count, 3u);
    EXPECT_EQ(m.faces[1].line, 10u);
    EXPECT_EQ(m.faces[4].count, 4u);
    const std::vector<int32_t> corners = {0, 1, 2, 0, 2, 3, 0, 1, 2, 0, 2, 3, 0, 1, 2, 3};
    EXPECT_EQ(m.corners, corners);
}

TEST(ObjReader, NumbersAreWholeTokensInTheCLocalesNotation) {
    const ObjMesh m =
        read_obj("v +1.5 -2e3 .25\nv 1 0 0 1\nv 0 1 0 0.5 0.5 0.5\nf 1 2 3\n", "t.obj");
    EXPECT_EQ(m.vertices[0].x, 1.5);
    EXPECT_EQ(m.vertices[0].y, -2000.0);
    EXPECT_EQ(m.vertices[0].z, 0.25);
    EXPECT_EQ(obj_refusal("v 1,5 0 0\n"), "t.obj:1: vertex coordinate '1,5' is not a number");
    EXPECT_EQ(obj_refusal("v 1.5x 0 0\n"), "t.obj:1: vertex coordinate '1.5x' is not a number");
    EXPECT_EQ(obj_refusal("v 0x10 0 0\n"), "t.obj:1: vertex coordinate '0x10' is not a number");
    EXPECT_EQ(obj_refusal("v +-1 0 0\n"), "t.obj:1: vertex coordinate '+-1' is not a number");
    EXPECT_EQ(obj_refusal("v 1e999 0 0\n"),
              "t.obj:1: vertex coordinate '1e999' is out of the range of a double");
}

TEST(ObjReader, NotFiniteCoordinatesAreRefused) {
    EXPECT_EQ(obj_refusal("v nan 0 0\n"),
              "t.obj:1: vertex coordinate 'nan' is not a finite number");
    EXPECT_EQ(obj_refusal("v 0 inf 0\n"),
              "t.obj:1: vertex coordinate 'inf' is not a finite number");
    EXPECT_EQ(obj_refusal("v 0 0 -Infinity\n"),
              "t.obj:1: vertex coordinate '-Infinity' is not a finite number");
    EXPECT_EQ(obj_refusal("v 0 0 0 NaN\n"), "t.obj:1: vertex weight 'NaN' is not a finite number");
    EXPECT_EQ(obj_refusal(kObjTriangle + "vn 0 nan 1\n"),
              "t.obj:4: normal 'nan' is not a finite number");
    EXPECT_EQ(obj_refusal(kObjTriangle + "vt inf\n"),
              "t.obj:4: texture coordinate 'inf' is not a finite number");
}

TEST(ObjReader, WordsAreNotNumbers) {
    EXPECT_EQ(obj_refusal("v abc def ghi\n"), "t.obj:1: vertex coordinate 'abc' is not a number");
    EXPECT_EQ(obj_refusal("v 1 2 3 r g b\n"), "t.obj:1: vertex colour 'r' is not a number");
}

TEST(ObjReader, CoordinatesBeyondTheSceneLimitAreRefused) {
    EXPECT_EQ(obj_refusal("v 1e16 0 0\n"),
              "t.obj:1: vertex coordinate '1e16' is not between -1e15 and 1e15");
    EXPECT_EQ(obj_refusal("v 1e15 -1e15 0\n"), "read");
}

TEST(ObjReader, StatementsNeedTheirNumberOfValues) {
    EXPECT_EQ(obj_refusal("v 1 2\n"),
              "t.obj:1: a vertex is v x y z, v x y z w or v x y z r g b, got 2 numbers");
    EXPECT_EQ(obj_refusal("v 1 2 3 4 5\n"),
              "t.obj:1: a vertex is v x y z, v x y z w or v x y z r g b, got 5 numbers");
    EXPECT_EQ(obj_refusal("vn 0 1\n"), "t.obj:1: a normal is vn x y z, got 2 numbers");
    EXPECT_EQ(obj_refusal("vt\n"), "t.obj:1: a texture coordinate is vt u [v [w]], got 0 numbers");
}

TEST(ObjReader, FractionalIndicesAreRefused) {
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1.7 2.2 3.9\n"),
              "t.obj:4: vertex index '1.7' is not a whole number");
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1 2 three\n"),
              "t.obj:4: vertex index 'three' is not a whole number");
    EXPECT_EQ(obj_refusal(kObjTriangle + "vt 0 0\nf 1/1.5 2/1 3/1\n"),
              "t.obj:5: texture coordinate index '1.5' is not a whole number");
}

TEST(ObjReader, IndicesBeyondTheIntegerRangeAreRefused) {
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1 2 99999999999999999999999\n"),
              "t.obj:4: vertex index '99999999999999999999999' is beyond the integer range");
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1 2 2147483648\n"),
              "t.obj:4: vertex index '2147483648' is beyond the integer range");
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1 2 -2147483648\n"),
              "t.obj:4: vertex index '-2147483648' is beyond the integer range");
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1 2 2147483647\n"),
              "t.obj:4: face 1 refers to vertex 2147483647, but only 3 vertices are defined "
              "before this line");
}

TEST(ObjReader, FacesOfFewerThanThreeCornersAreRefused) {
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1 2\n"),
              "t.obj:4: a face needs at least 3 corners, got 2");
    EXPECT_EQ(obj_refusal(kObjTriangle + "f\n"), "t.obj:4: a face needs at least 3 corners, got 0");
}

TEST(ObjReader, OutOfRangeIndicesAreReportedAsWritten) {
    EXPECT_EQ(obj_refusal(kObjSquare + "f -9 -2 -1\n"),
              "t.obj:5: face 1 refers to vertex -9, but only 4 vertices are defined before this "
              "line (-1 is the last, -4 the first)");
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1 2 3\nf 1 2 9\n"),
              "t.obj:5: face 2 refers to vertex 9, but only 3 vertices are defined before this "
              "line");
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1 2 0\n"),
              "t.obj:4: face 1 refers to vertex 0, but OBJ numbers them from 1 (or back from the "
              "last with -1)");
    EXPECT_EQ(obj_refusal("f 1 2 3\n"),
              "t.obj:1: face 1 refers to vertex 1, but no vertices are defined before this line");
}

TEST(ObjReader, IndicesCountOnlyWhatIsDefinedSoFar) {
    // Relative indices count back from the vertices defined before the face, not the file's.
    const ObjMesh m = read_obj(kObjTriangle + "f -3 -2 -1\nv 5 5 5\nf -3 -2 -1\n", "t.obj");
    const std::vector<int32_t> corners = {0, 1, 2, 1, 2, 3};
    EXPECT_EQ(m.corners, corners);
    EXPECT_EQ(obj_refusal("v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n"),
              "t.obj:3: face 1 refers to vertex 3, but only 2 vertices are defined before this "
              "line");
}

TEST(ObjReader, TextureAndNormalIndicesAreChecked) {
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1/1 2/1 3/1\n"),
              "t.obj:4: face 1 refers to texture coordinate 1, but no texture coordinates are "
              "defined before this line");
    EXPECT_EQ(obj_refusal(kObjTriangle + "vn 0 0 1\nf 1//1 2//1 3//-2\n"),
              "t.obj:5: face 1 refers to normal -2, but only 1 normal is defined before this "
              "line");
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1/ 2 3\n"),
              "t.obj:4: corner '1/' is not v, v/vt, v//vn or v/vt/vn");
    EXPECT_EQ(obj_refusal(kObjTriangle + "f /1 2 3\n"),
              "t.obj:4: corner '/1' is not v, v/vt, v//vn or v/vt/vn");
    EXPECT_EQ(obj_refusal(kObjTriangle + "vn 0 0 1\nf 1//1 2 3//\n"),
              "t.obj:5: corner '3//' is not v, v/vt, v//vn or v/vt/vn");
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1/1/1/1 2 3\n"),
              "t.obj:4: corner '1/1/1/1' has more than two slashes");
}

TEST(ObjReader, AFaceMayNotUseAVertexTwice) {
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1 2 -2\n"), "t.obj:4: face 1 uses vertex 2 twice");
}

TEST(ObjReader, LineNumbersCountCommentsBlankLinesAndCrlf) {
    const std::string text =
        "# a comment\r\n\r\nv 0 0 0\r\n   \t\r\nv 1 0 0 # the second\r\nv 0 1 0\r\n"
        "o thing\r\n# f 1 2 3\r\nf 1 2 3\r\nf 1 2 x\r\n";
    EXPECT_EQ(obj_refusal(text), "t.obj:10: vertex index 'x' is not a whole number");
    // A file with only '\n' numbers its lines the same way.
    std::string unix_text = text;
    std::erase(unix_text, '\r');
    EXPECT_EQ(obj_refusal(unix_text), "t.obj:10: vertex index 'x' is not a whole number");
}

TEST(ObjReader, ContinuationLinesJoinAndReportTheirFirstLine) {
    const ObjMesh m = read_obj("v 0 0 \\\n0\nv 1 0 0\nv 0 1 0\nf 1 \\\n 2 \\\r\n3\n", "t.obj");
    EXPECT_EQ(m.vertices.size(), 3u);
    ASSERT_EQ(m.faces.size(), 1u);
    EXPECT_EQ(m.faces[0].line, 5u);
    EXPECT_EQ(m.faces[0].count, 3u);
    EXPECT_EQ(obj_refusal(kObjTriangle + "f 1 2 \\\nnan\nf 1 2 3\n"),
              "t.obj:4: vertex index 'nan' is not a whole number");
    EXPECT_EQ(obj_refusal("v 0 0 0\nv 1 \\\n"),
              "t.obj:2: a vertex is v x y z, v x y z w or v x y z r g b, got 1 number");
}

TEST(ObjReader, StatementsLenslabDoesNotUseAreIgnored) {
    const ObjMesh m = read_obj("\xEF\xBB\xBFmtllib m.mtl\no thing\ng a b\ns off\nusemtl glass\n" +
                                   kObjTriangle + "l 1 2\np 1\nvp 0.5\nf 1 2 3\n",
                               "t.obj");
    EXPECT_EQ(m.faces.size(), 1u);
}

TEST(ObjReader, UnknownStatementsAndFreeFormGeometryAreRefused) {
    EXPECT_EQ(obj_refusal(kObjTriangle + "vv 1 2 3\n"),
              "t.obj:4: unknown statement 'vv' (lenslab reads v, vt, vn and f, and ignores o, g, "
              "s, usemtl, mtllib, l and p)");
    EXPECT_EQ(obj_refusal("cstype bspline\n"),
              "t.obj:1: free-form geometry ('cstype') is not supported: export the model as "
              "polygons (f lines)");
}

TEST(ObjReader, MessagesQuoteBoundedPrintableText) {
    const std::string what = obj_refusal("v \x01" + std::string(100, 'a') + " 0 0\n");
    EXPECT_EQ(what,
              "t.obj:1: vertex coordinate '\\x01" + std::string(39, 'a') + "...' is not a number");
}

TEST(ObjReader, LimitsStopTheReadAtTheLineThatPassesThem) {
    ObjLimits limits;
    limits.max_vertices = 3;
    EXPECT_EQ(obj_refusal(kObjSquare, limits), "t.obj:4: more than the 3 vertices allowed");
    limits = {};
    limits.max_triangles = 2;
    EXPECT_EQ(obj_refusal(kObjSquare + "f 1 2 3\nf 1 2 3 4\n", limits),
              "t.obj:6: more than the 2 triangles allowed (faces fan-split)");
    EXPECT_EQ(obj_refusal(kObjSquare + "f 1 2 3 4\n", limits), "read");
    limits = {};
    limits.max_face_corners = 3;
    EXPECT_EQ(obj_refusal(kObjSquare + "f 1 2 3 4\n", limits),
              "t.obj:5: face 1 has 4 corners, more than the 3 allowed");
}

TEST(ObjReader, AFaceOfTooManyCornersIsRefusedByItsCount) {
    std::string face = "f";
    for (int k = 0; k < 100000; ++k) face += " 1";
    EXPECT_EQ(obj_refusal(kObjTriangle + face + "\n"),
              "t.obj:4: face 1 has 100000 corners, more than the 255 allowed");
}

TEST(ObjReader, TheErrorCarriesItsLineAndReason) {
    try {
        (void)read_obj(kObjTriangle + "\n# x\nf 1 2\n", "dir/m.obj");
        FAIL() << "a two-corner face was read";
    } catch (const ObjError& e) {
        EXPECT_EQ(e.line(), 6u);
        EXPECT_EQ(e.reason(), "a face needs at least 3 corners, got 2");
        EXPECT_STREQ(e.what(), "dir/m.obj:6: a face needs at least 3 corners, got 2");
    }
}

TEST(ObjReader, AnEmptyFileHasNoFaces) {
    const ObjMesh m = read_obj("", "t.obj");
    EXPECT_TRUE(m.vertices.empty());
    EXPECT_TRUE(m.faces.empty());
}

}  // namespace
}  // namespace lenslab
