#pragma once
// The mesh operations, described once. Every operation that changes a winged-edge mesh's
// connectivity is one entry of operations(): its name, what the edit panel calls it, its
// arguments (which element each names, or a number with its default), and its check,
// change and refusal wording, held behind `impl` (euler_ops.cpp). Everything else reads
// this list: WingedEdgeMesh::check / apply, the one binding (meshEdit), the JS API
// (mesh.check(op) / mesh.apply(op) with the {op, ...} objects a lesson state stores), the
// edit panel's buttons, the declarations' operation union and the tests.
//
// Adding an operation (docs/architecture.md, "Adding an operation"): its change and check
// in euler_ops.cpp (the change written against the recorder, as the others) and one entry
// in the list at the end of that file.
#include "wingspline/mesh/tables.h"
#include "wingspline/mesh/winged_edge.h"

#include <string_view>
#include <vector>

namespace wingspline::mesh {

struct OperationArgument {
    const char* name;            // the key in an operation record, e.g. "e", "t"
    ElementKind kind;            // the element it names; None: a number
    double default_value = 0;    // for an optional number
    bool optional = false;
    // For an element argument after the first: the adjacency query of the first argument
    // that lists the elements it may name ("vertices-of-face": the corners of face f), so a
    // page can offer them as choices. nullptr for the first argument and for numbers.
    const char* choices = nullptr;
    const char* label = "";      // what it is, for a choice or a message ("first corner of the new edge")
};

struct OperationImpl; // the check, the change (recorded or not) and the wording: euler_ops.cpp

// What an operation must find before it changes anything (edit_costs.h counts what each
// representation reads to find it): the queries of queries.h it asks of its first element.
enum class Locate {
    EdgeSides,        // faces-of-edge e, then edges-of-face of each face found
    EdgeSidesAndEnds, // as EdgeSides, plus edges-around-vertex of both ends of e
    FaceSides,        // edges-of-face f
    VertexStar,       // edges-around-vertex v
};

struct OperationEntry {
    const char* name;     // "split-edge", ...
    const char* title;    // "Split edge"
    const char* counts;   // what it does to V, E, F: "V+1, E+1"
    const char* shortcut; // one key the edit panel binds to it
    // One line describing an operation of this kind, {name} standing for an argument's
    // value: "split {e} at t = {t}" (elements are written as the slides label them).
    const char* describe;
    std::vector<OperationArgument> arguments; // the first names the element it starts from
    const OperationImpl* impl;
    Locate locate;
};

// Every operation, in the order the edit panel shows them.
const std::vector<OperationEntry>& operations();
// The entry named `name`, or nullptr.
const OperationEntry* find_operation(std::string_view name);
// An operation value: operation("flip-edge", Edge(3)), operation("split-edge", Edge(2), 0.25),
// operation("split-face", Face(0), Vertex(5), Vertex(0)). Throws Error("unknown-operation")
// for a name no entry has and Error("invalid-argument") for more arguments than it takes.
// Arguments left out take the entry's defaults (an element left out is kNone, which its
// check refuses).
Operation operation_from(std::string_view name, const double* args, std::size_t count);
inline double operation_argument(double x) { return x; }
template <class Tag> double operation_argument(Handle<Tag> h) { return h.idx; }
template <class... T> Operation operation(std::string_view name, T... args) {
    const double values[] = {0.0, operation_argument(args)...};
    return operation_from(name, values + 1, sizeof...(T));
}

// The steps of a change record cross as flat int32 arrays: a table indexes change_tables()
// ("vertex", "edge", "face"), a field indexes change_fields() (the tables' column names,
// plus "firstCorner": the corner face_set() lists a face from).
const std::vector<const char*>& change_tables();
const std::vector<const char*>& change_fields();
int change_field_index(const std::string& field); // -1 if unknown

} // namespace wingspline::mesh
