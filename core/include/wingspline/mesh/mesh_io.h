#pragma once
// OFF and OBJ readers and writers (positions and polygonal faces). Readers throw
// ParseError with the 1-based line number and what was expected; writers use %.17g so a
// mesh written and read back is equal bit for bit.
#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/limits.h"

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace wingspline::mesh {

class ParseError : public Error {
public:
    ParseError(const std::string& code, int line, const std::string& message)
        : Error(code, "line " + std::to_string(line) + ": " + message), line_(line) {}
    int line() const noexcept { return line_; }

private:
    int line_;
};

// A text read in pieces: writes up to `capacity` bytes from byte `offset` on into `out`
// and returns how many; 0 = the end. (Random access, so OBJ can be pre-scanned.) The readers then hold one piece (64 KB) plus the line it cuts, so a file
// over the limits is refused having copied only its first pieces (the wasm binding pulls
// the file from JS this way and never copies it whole into the module's memory).
using TextSource = std::function<std::size_t(char* out, std::size_t capacity, std::size_t offset)>;

// Both readers skip a UTF-8 byte-order mark at the start and accept LF, CRLF and CR line
// ends. Limits (limits.h), each refused with the line that breaks it: a finite coordinate
// beyond limits.max_coordinate (coordinate-out-of-range; non-finite ones are read and named
// by validation), a face with more than kMaxFaceCorners corners (face-too-large), more
// vertices or faces than max_vertices / max_faces (too-large; OFF from its header, before
// anything else is read; OBJ by a pre-scan that stores nothing, at the first statement over). A line over 1 MB: line-too-long.
IndexedMesh parse_off(std::string_view text, const MeshLimits& limits = kFileLimits);
IndexedMesh parse_off(const TextSource& source, const MeshLimits& limits = kFileLimits);
// OBJ: v x y z [w]; f with i, i/t, i//n, i/t/n and negative (relative) indices; vt, vn,
// vp, o, g, s, usemtl, mtllib are read past; any other statement is an error.
IndexedMesh parse_obj(std::string_view text, const MeshLimits& limits = kFileLimits);
IndexedMesh parse_obj(const TextSource& source, const MeshLimits& limits = kFileLimits);
std::string format_off(const IndexedMesh& mesh);
std::string format_obj(const IndexedMesh& mesh);

} // namespace wingspline::mesh
