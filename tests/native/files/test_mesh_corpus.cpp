// The malformed-mesh corpus, natively: every file of tests/corpus/mesh/ gives
// exactly the outcome tests/corpus/mesh/expected.txt names (code, severity, and a message
// naming the line or the elements), and nothing crashes or builds half a mesh. The same
// files go through wasm in tests/wasm/files/mesh-corpus.test.mjs. Also here: a 50 MB file
// generated at test time (never committed), and the regression tests of what fuzzing found.
#include <catch2/catch.hpp>

#include "corpus.h"

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/mesh_io.h"
#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/winged_edge.h"

#include <cmath>
#include <cstdio>
#include <string>

using namespace wingspline::mesh;
using hardening::MeshCase;

namespace {

IndexedMesh parse(const std::string& text, const std::string& format) {
    return format == "obj" ? parse_obj(text) : parse_off(text);
}

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

const Problem* find_problem(const ValidationReport& r, const std::string& code) {
    for (const auto& p : r.problems)
        if (p.code == code) return &p;
    return nullptr;
}

void check_built(const IndexedMesh& m) {
    const WingedEdgeMesh w = WingedEdgeMesh::build(m);
    const ValidationReport structure = w.validate();
    INFO((structure.first_error() ? structure.first_error()->message : std::string("valid")));
    CHECK(structure.ok());
    CHECK(w.vertex_count() == m.vertex_count());
    CHECK(w.face_count() == m.face_count());
    std::vector<double> normals;
    newell_normals(w, normals);
    for (double x : normals) CHECK(std::isfinite(x));
    for (const auto& plane : face_planes(w)) {
        for (int k = 0; k < 4; ++k) CHECK(std::isfinite(plane.cross[k]));
        for (int k = 0; k < 4; ++k) CHECK(std::isfinite(plane.newell[k]));
        CHECK(std::isfinite(plane.residual));
    }
}

void check_case(const MeshCase& c) {
    const std::string text = hardening::read_file(hardening::corpus_path("mesh/" + c.file));
    if (c.outcome == "parse-error") {
        try {
            parse(text, c.format);
            FAIL("the reader accepted " << c.file);
        } catch (const ParseError& e) {
            CHECK(e.code() == c.code);
            CHECK(e.line() == c.line);
            CHECK(std::string(e.what()).rfind("line " + std::to_string(c.line) + ": ", 0) == 0);
        }
        return;
    }
    const IndexedMesh m = parse(text, c.format);
    const ValidationReport report = validate_indexed(m);
    if (c.outcome == "valid") {
        CHECK(report.problems.empty());
        check_built(m);
        return;
    }
    const Problem* p = find_problem(report, c.code);
    REQUIRE(p != nullptr);
    CHECK(p->severity == (c.outcome == "warning" ? Severity::Warning : Severity::Error));
    for (const auto& name : c.names) {
        INFO(p->message);
        CHECK(contains(p->message, name));
    }
    if (c.outcome == "warning") {
        CHECK(report.ok());
        check_built(m);
        return;
    }
    CHECK_FALSE(report.ok());
    try {
        WingedEdgeMesh::build(m);
        FAIL("the winged edge accepted " << c.file);
    } catch (const InvalidMesh& e) {
        // Refused with the report: the first error's code, and every problem kept.
        CHECK(e.code() == e.report().first_error()->code);
        CHECK(find_problem(e.report(), c.code) != nullptr);
        CHECK(e.report().problems.size() == report.problems.size());
    }
}

// A valid OFF of at least `bytes` bytes: a docs/benchmarks.md-style height-field grid written with
// full precision, so parsing has real work on every line.
std::string large_off(std::size_t bytes, int32_t& nx_out, int32_t& ny_out) {
    // About 60 bytes per vertex line and 14 per face line, 2 faces per vertex.
    int32_t n = 64;
    while (static_cast<std::size_t>(n + 1) * (n + 1) * 60 + static_cast<std::size_t>(2) * n * n * 14 < bytes) n += 16;
    const IndexedMesh g = grid(n, n);
    std::string text = format_off(g);
    nx_out = n;
    ny_out = n;
    return text;
}

} // namespace

TEST_CASE("every file of the malformed-mesh corpus gives its expected outcome", "[hardening][mesh]") {
    const auto cases = hardening::mesh_cases();
    REQUIRE(cases.size() >= 19);
    for (const auto& c : cases) {
        SECTION(c.file + " as " + c.format + ": " + c.outcome + " " + c.code) { check_case(c); }
    }
}

TEST_CASE("a zero-area face builds, with a zero normal and no NaN anywhere", "[hardening][mesh]") {
    const IndexedMesh m = parse_off(hardening::read_file(hardening::corpus_path("mesh/zero-area-face.off")));
    const WingedEdgeMesh w = WingedEdgeMesh::build(m);
    std::vector<double> normals;
    newell_normals(w, normals);
    // F1 lies in z = 0, counter-clockwise seen from +z: the analytic normal is (0, 0, 1).
    CHECK(normals[0] == 0.0);
    CHECK(normals[1] == 0.0);
    CHECK(normals[2] == 1.0);
    // F2 has no area: documented as the zero vector rather than 0/0.
    CHECK(normals[3] == 0.0);
    CHECK(normals[4] == 0.0);
    CHECK(normals[5] == 0.0);
}

TEST_CASE("every problem of a mesh with several is reported, not only the first", "[hardening][mesh]") {
    // duplicate-face.off: F3 repeats F1, which also makes F1 and F3 run the same way along
    // v1-v2 and v2-v3 and puts v1-v3 under three faces.
    const IndexedMesh m = parse_off(hardening::read_file(hardening::corpus_path("mesh/duplicate-face.off")));
    const ValidationReport r = validate_indexed(m);
    CHECK(r.has("duplicate-face"));
    CHECK(r.has("inconsistent-orientation"));
    CHECK(r.has("non-manifold-edge"));
}

TEST_CASE("a 50 MB OFF file generated at test time reads and builds, and an error on its last line is named", "[hardening][mesh][large]") {
    constexpr std::size_t kFiftyMegabytes = 50u * 1024u * 1024u;
    int32_t nx = 0, ny = 0;
    std::string text = large_off(kFiftyMegabytes, nx, ny);
    REQUIRE(text.size() >= kFiftyMegabytes);
    // Far more elements than a page imports (kFileLimits): read with the counts lifted.
    const IndexedMesh m = parse_off(text, kUnlimitedCounts);
    CHECK(m.vertex_count() == (nx + 1) * (ny + 1));
    CHECK(m.face_count() == 2 * nx * ny);
    CHECK(validate_indexed(m).problems.empty());
    const WingedEdgeMesh w = WingedEdgeMesh::build(m);
    const MeshCounts counts = w.counts();
    CHECK(counts.euler() == 1); // an open disc: V - E + F = 1
    CHECK(counts.boundary_loops == 1);

    // The same file with a word in place of the last face's last index.
    const std::size_t last_line_start = text.rfind('\n', text.size() - 2) + 1;
    const std::size_t last_space = text.rfind(' ');
    std::size_t lines = 0;
    for (char ch : text) lines += ch == '\n';
    text.replace(last_space + 1, text.size() - last_space - 2, "oops");
    REQUIRE(last_space > last_line_start);
    try {
        parse_off(text, kUnlimitedCounts);
        FAIL("the damaged 50 MB file was accepted");
    } catch (const ParseError& e) {
        CHECK(e.code() == "parse-error");
        CHECK(e.line() == static_cast<int>(lines));
        CHECK(contains(e.what(), "'oops'"));
    }
}
