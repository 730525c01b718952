#pragma once
// Every table of the six representations (lectures 000 and 001), described once.
//
// A table has one row per vertex, edge or face. Its data are flat arrays; its columns say
// where in those arrays each cell lies:
//  * a "rows" array holds `stride` numbers per row (the winged edge's edge table: 8 per
//    edge); a column takes `width` of them starting at `first` (S = number 0, width 1;
//    a position = numbers 0..2, width 3);
//  * a CSR column has a list array cut into rows by an offsets array (rows + 1 entries,
//    starting at 0, never decreasing); each list item is `width` numbers (a face's vertex
//    references: 1; independent faces' corner coordinates: 3). Several lists may share one
//    offsets array (the adjacency lists' FV, FE and FF).
// A column's `refers` says what its numbers name (a vertex, an edge, a face; -1 = none) or
// None for coordinates. The generic binding (core/bindings/tables.cpp) turns any table into a
// plain JS value and the generic reader (web/js/core/tables.js) reads rows by index and
// cells by column name; docs/api-mesh.md lists the same descriptors (checked by a test).
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/winged_edge.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace wingspline::mesh {

enum class ElementKind : int { None, Vertex, Edge, Face };
const char* element_kind_name(ElementKind k); // "vertex", "edge", "face"; "" for None

enum class ScalarType : int { Float64, Int32 };
enum class ArrayRole : int { Rows, Offsets, List };

struct ArrayDescriptor {
    const char* name;        // the JS key of its typed array, e.g. "edges"
    ScalarType type;
    ArrayRole role;
    int stride = 1;          // Rows: numbers per row; List: numbers per item; Offsets: 1
    const char* offsets = ""; // List: the name of the offsets array that cuts it into rows
};

struct ColumnDescriptor {
    const char* name;   // the key of the cell in a row object, e.g. "startLeft"
    const char* label;  // the header as the slide writes it, e.g. "L"
    const char* group;  // the header above it ("S": the two wings at the Start), "" if none
    ElementKind refers; // what its numbers name; None: coordinates
    const char* array;  // the array that holds the cell
    int first = 0;      // Rows: the cell's first number within the row; List: 0
    int width = 1;      // numbers in one cell (Rows) or one list item (List)
};

struct TableDescriptor {
    Representation representation;
    const char* name;  // the JS key, e.g. "edges"
    const char* title; // the caption, e.g. "EDGE TABLE"
    ElementKind rows;  // one row per vertex, edge or face
    std::vector<ArrayDescriptor> arrays;
    std::vector<ColumnDescriptor> columns;

    const ArrayDescriptor& array(const std::string& name) const; // throws std::out_of_range
};

// Every table, in Representation order and within one representation in the order the
// lesson shows them (vertices, edges, faces).
const std::vector<TableDescriptor>& table_descriptors();

// One array's live data (a view: valid until the mesh or its representations change).
struct ArrayData {
    const double* f64 = nullptr;
    const int32_t* i32 = nullptr;
    std::size_t size = 0; // numbers
    int32_t at(std::size_t i) const { return i32 != nullptr ? i32[i] : static_cast<int32_t>(f64[i]); }
};

struct TableData {
    const TableDescriptor* descriptor = nullptr;
    std::vector<ArrayData> arrays; // in descriptor->arrays order
    int32_t rows = 0;              // from the first array (rows: size / stride; offsets: size - 1)
};

// The tables of representation r over the live arrays. The winged edge's need only
// `winged`; the others need `reps` (throws Error("representations-not-built") when null).
std::vector<TableData> representation_tables(Representation r, const Representations* reps, const WingedEdgeMesh& winged);

// What is wrong with a table's layout, one sentence each (empty: consistent): a rows array
// holding stride * rows numbers, offsets of rows + 1 entries from 0 never decreasing, a list
// of width * (last offset) numbers, columns inside their array's stride, references in range.
std::vector<std::string> table_layout_problems(const TableData& table, int32_t vertices, int32_t edges, int32_t faces);

// What an edit made each representation rewrite (lecture 000's cost argument): the
// stored entries (one number: a coordinate or an index) that differ between two states of a
// mesh, in Representation order. Every table is compared row by row by element number and
// column by column as its descriptor lays it out; a list that grew or shrank counts the
// entries only one state has, and a row only one state has counts whole. A removed
// element's row keeps its old contents (a gap), so removing it rewrites nothing there.
std::array<int64_t, kRepresentationCount> rewritten_entries(const WingedEdgeMesh& before, const Representations& before_reps,
                                                            const WingedEdgeMesh& after, const Representations& after_reps);

// The same for one operation, without the state before it: the winged edge's count read
// from the operation's change record (the fields it rewrote, the coordinates it moved, the
// whole rows it added; a removed row keeps its contents), the others compared as above
// between their derivations before and after (O(mesh): they hold no change record).
std::array<int64_t, kRepresentationCount> rewritten_entries(const ChangeRecord& change, const Representations& before_reps,
                                                            const WingedEdgeMesh& after, const Representations& after_reps);

} // namespace wingspline::mesh
