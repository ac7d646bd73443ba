#pragma once
// lenslab's own Wavefront OBJ reader (docs/scene-format.md, "OBJ files"): one pass over the
// text, line by line, in time linear in its length. It is strict where a lenient reader
// guesses: `v nan 0 0`, `f 1.7 2 3`, an index beyond the vertices defined so far or a face of
// two corners are refused with the file name, the line and the reason, never read as zeros,
// rounded, or dropped.
//
// Read: `v x y z [w]` (also `v x y z r g b`, the colour ignored), `vn`, `vt` (checked, then
// ignored), `f` with corners `v`, `v/vt`, `v//vn`, `v/vt/vn`, numbered from 1 or counted
// back from the last one defined (-1). Comments (`#` to the end of the line), blank lines,
// CRLF endings and `\` line continuations are allowed. Ignored: the statements lenslab has
// no use for (`o`, `g`, `s`, `usemtl`, `mtllib`, `l`, `p`, ...). Refused: free-form curves
// and surfaces, and any statement OBJ does not define (a typo such as `vv` would otherwise
// lose geometry without a word).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "math/vec3.h"
#include "scene/limits.h"
#include "util/error.h"

namespace lenslab {

// A problem at one line of an OBJ file: "NAME:LINE: REASON".
class ObjError : public Error {
public:
    ObjError(const std::string& name, size_t line, const std::string& reason)
        : Error(name + ":" + std::to_string(line) + ": " + reason),
          m_line(line),
          m_reason(reason) {}
    size_t line() const { return m_line; }
    const std::string& reason() const { return m_reason; }

private:
    size_t m_line;
    std::string m_reason;
};

// An `f` line: its corners are corners[first .. first + count).
struct ObjFace {
    size_t first = 0;
    size_t count = 0;
    size_t line = 0;  // where the f statement starts, for messages
};

struct ObjMesh {
    std::vector<Vec3> vertices;    // the v lines in order; the file numbers them from 1
    std::vector<int32_t> corners;  // vertex indices from 0, face after face
    std::vector<ObjFace> faces;
};

// What the caller accepts; the reader stops at the first line past a limit, so a huge file
// costs no more memory than the limit.
struct ObjLimits {
    double max_coordinate = 1e15;              // |x|, |y|, |z| (kMaxSceneNumber)
    size_t max_vertices = kMaxMeshTriangles;   // v lines
    size_t max_triangles = kMaxMeshTriangles;  // after fan-splitting: n corners make n - 2
    size_t max_face_corners = 255;             // keeps the repeated-corner check linear
};

// Reads `text`, an OBJ file called `name` in messages. Throws ObjError at the first problem.
ObjMesh read_obj(std::string_view text, const std::string& name, const ObjLimits& limits = {});

}  // namespace lenslab
