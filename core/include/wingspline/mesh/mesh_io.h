#pragma once
// OFF and OBJ readers and writers (positions and polygonal faces). Readers throw
// ParseError with the 1-based line number and what was expected; writers use %.17g so a
// mesh written and read back is equal bit for bit.
#include "wingspline/mesh/indexed_mesh.h"

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

IndexedMesh parse_off(std::string_view text);
// OBJ: v x y z [w]; f with i, i/t, i//n, i/t/n and negative (relative) indices; vt, vn,
// vp, o, g, s, usemtl, mtllib are read past; any other statement is an error.
IndexedMesh parse_obj(std::string_view text);
std::string format_off(const IndexedMesh& mesh);
std::string format_obj(const IndexedMesh& mesh);

} // namespace wingspline::mesh
