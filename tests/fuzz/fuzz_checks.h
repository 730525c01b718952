#pragma once
// Property checks shared by the fuzz targets. A broken property aborts, so libFuzzer keeps
// the input as a crash reproducer (test-results/fuzz/<target>/).
#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/mesh_io.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#define FUZZ_REQUIRE(condition)                                                             \
    do {                                                                                    \
        if (!(condition)) {                                                                 \
            std::fprintf(stderr, "property broken: %s (%s:%d)\n", #condition, __FILE__, __LINE__); \
            std::abort();                                                                   \
        }                                                                                   \
    } while (0)

namespace fuzz_checks {

// A parsed mesh: well-formed CSR and every index a vertex of the mesh.
inline void check_indexed(const wingspline::mesh::IndexedMesh& m) {
    FUZZ_REQUIRE(m.positions.size() % 3 == 0);
    FUZZ_REQUIRE(!m.face_offsets.empty() && m.face_offsets.front() == 0);
    FUZZ_REQUIRE(m.face_offsets.back() == static_cast<int32_t>(m.face_vertices.size()));
    for (std::size_t f = 0; f + 1 < m.face_offsets.size(); ++f) FUZZ_REQUIRE(m.face_offsets[f] <= m.face_offsets[f + 1]);
    for (int32_t v : m.face_vertices) FUZZ_REQUIRE(v >= 0 && v < m.vertex_count());
}

// A reader's error: a stable code, a line inside the file (or the one after its end), and
// the message starting with that line.
inline void check_parse_error(const wingspline::mesh::ParseError& e, const std::string& text) {
    // Lines end at LF, CRLF or a lone CR, as the readers count them (mesh_io.cpp).
    int lines = 1;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) ++lines;
    }
    FUZZ_REQUIRE(!e.code().empty());
    FUZZ_REQUIRE(e.line() >= 1 && e.line() <= lines + 1);
    const std::string prefix = "line " + std::to_string(e.line()) + ": ";
    FUZZ_REQUIRE(std::string(e.what()).compare(0, prefix.size(), prefix) == 0);
}

} // namespace fuzz_checks
