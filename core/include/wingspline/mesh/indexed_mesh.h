#pragma once
// The indexed face set every representation is built from (lecture 000, "vertex and face
// tables"; lecture 001, "pointers to a vertex list"), and the validation report that says,
// in a student's words, everything that keeps it from being a winged-edge mesh.
#include "wingspline/error.h"
#include "wingspline/mesh/limits.h"

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace wingspline::mesh {

// The invalid sentinel of every element index ("-1 = none").
constexpr int32_t kNone = -1;

struct IndexedMesh {
    std::vector<double> positions;     // positions[3*v + k], k = 0,1,2 for x,y,z
    std::vector<int32_t> face_offsets; // face f's corners are face_vertices[face_offsets[f] .. face_offsets[f+1])
    std::vector<int32_t> face_vertices;

    IndexedMesh() : face_offsets{0} {}
    int32_t vertex_count() const { return static_cast<int32_t>(positions.size() / 3); }
    int32_t face_count() const { return static_cast<int32_t>(face_offsets.size()) - 1; }
    int32_t face_size(int32_t f) const { return face_offsets[f + 1] - face_offsets[f]; }
    int32_t corner(int32_t f, int32_t i) const { return face_vertices[face_offsets[f] + i]; }
    int32_t add_vertex(double x, double y, double z);
    void add_face(std::initializer_list<int32_t> vertices);
    void add_face(const int32_t* vertices, int32_t count);
};

enum class Severity { Error, Warning };

// One thing wrong with a mesh. `code` is stable (tests and programs switch on it);
// `message` uses the slides' 1-based labels (v3, e5, F2); the element lists are 0-based.
struct Problem {
    std::string code;
    Severity severity = Severity::Error;
    std::string message;
    std::vector<int32_t> vertices;
    std::vector<int32_t> edges;
    std::vector<int32_t> faces;
};

struct ValidationReport {
    std::vector<Problem> problems;
    bool ok() const; // true when no problem is an error (warnings allowed)
    const Problem* first_error() const;
    bool has(const std::string& code) const;
};

// Every problem of an indexed face set that keeps it from being held by a winged-edge
// structure (errors), plus warnings (isolated vertices). Never throws on bad input.
ValidationReport validate_indexed(const IndexedMesh& mesh);

// A mesh refused by the winged edge: code and message of the first error, and the report.
class InvalidMesh : public Error {
public:
    explicit InvalidMesh(ValidationReport report);
    const ValidationReport& report() const noexcept { return report_; }

private:
    ValidationReport report_;
};

// Slide labels: vertex_label(2) == "v3", face_label(1) == "F2", edge_label(4) == "e5".
std::string vertex_label(int32_t v);
std::string face_label(int32_t f);
std::string edge_label(int32_t e);

// The elements of a table of `count` rows as messages list them: "vertices v1 to v5",
// "only v1", "no vertices" (label: vertex_label, edge_label or face_label).
std::string elements_text(std::string (*label)(int32_t), const char* plural, int32_t count);

// face-too-large, as files and face sets are refused: "F3 has 1001 corners; a face may
// have at most 1000" (kMaxFaceCorners, limits.h).
std::string face_too_large_message(int32_t f, int64_t corners);

} // namespace wingspline::mesh
