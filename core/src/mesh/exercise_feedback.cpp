// Value-free feedback for the table exercises (exercise_feedback.h): the row and column a
// finding is about, as the grid heads them, the definition to re-read, and a nudge. Built from
// the finding's place and code alone, so no right value can slip in.
#include "wingspline/mesh/exercise_feedback.h"

#include <array>

namespace wingspline::mesh {
namespace {

struct Words {
    std::string message;
    std::string hint;
};

// The grids' row names: the slides' v1, e1, F1; lecture 001's edge list writes E1 and P1.
std::string row_name(const std::string& table, MeshTable t, int32_t row) {
    const bool edge_list = table == "edge-list";
    const std::string n = std::to_string(row + 1);
    if (t == MeshTable::Vertex) return (edge_list ? "V" : "v") + n;
    if (t == MeshTable::Edge) return (edge_list ? "E" : "e") + n;
    return (edge_list ? "P" : "F") + n;
}

// The winged edge's columns as the slide heads them, the definition of each, and a nudge.
struct Column {
    const char* field;
    const char* head;
    const char* rule;
    const char* hint;
};
const std::array<Column, 8> kWingedColumns = {{
    {"start", "S", "S and E are the edge's two ends, its Start and its End: together they must be an edge of the mesh (two corners next to each other on a face), one row per edge",
     "pick two corners that sit next to each other on a face, and an edge no other row describes"},
    {"end", "E", "S and E are the edge's two ends, its Start and its End: together they must be an edge of the mesh (two corners next to each other on a face), one row per edge",
     "pick two corners that sit next to each other on a face, and an edge no other row describes"},
    {"left", "L", "L is the face whose corners run from S to E (faces go counter-clockwise); none where no face does (the boundary)",
     "walk along the edge from S to E: the face on your left is L"},
    {"right", "R", "R is the face whose corners run from E to S (faces go counter-clockwise); none where no face does (the boundary)",
     "walk along the edge from S to E: the face on your right is R"},
    {"startLeft", "S:L", "S:L is the other edge at S of the face on the Left, the boundary counting as a face: the next edge counter-clockwise around S",
     "stand at S inside the face on the Left (outside the mesh if that side is the boundary) and follow that face's other side at S"},
    {"startRight", "S:R", "S:R is the other edge at S of the face on the Right, the boundary counting as a face: the next edge clockwise around S",
     "stand at S inside the face on the Right (outside the mesh if that side is the boundary) and follow that face's other side at S"},
    {"endLeft", "E:L", "E:L is the other edge at E of the face on the Left, the boundary counting as a face: the next edge clockwise around E",
     "stand at E inside the face on the Left (outside the mesh if that side is the boundary) and follow that face's other side at E"},
    {"endRight", "E:R", "E:R is the other edge at E of the face on the Right, the boundary counting as a face: the next edge counter-clockwise around E",
     "stand at E inside the face on the Right (outside the mesh if that side is the boundary) and follow that face's other side at E"},
}};

const Column* winged_column(const std::string& field) {
    for (const Column& c : kWingedColumns)
        if (field == c.field) return &c;
    return nullptr;
}

// What is wrong with the cell, in words that hold no value.
std::string what_is_wrong(const std::string& code) {
    if (code == "blank") return "it is blank";
    if (code == "unknown-label") return "it names something the mesh (or the table) does not have";
    if (code == "not-an-edge") return "these two vertices are not the ends of one edge of the mesh";
    if (code == "duplicate-edge") return "another row already describes this edge";
    if (code == "swapped-ends") return "S and E are the other way round for the L, R and wings of this row";
    if (code == "wrong-face") return "this is not the face on that side";
    if (code == "wrong-wing") return "this is not that wing";
    if (code == "not-incident") return "this is not an edge at this vertex";
    if (code == "not-on-face") return "this is not a side of this face";
    if (code == "clockwise") return "the corners run clockwise";
    if (code == "wrong-vertex") return "this is not the corner at this place";
    if (code == "wrong-order") return "the right corners, not in the face's order";
    if (code == "missing-vertex") return "an entry is missing";
    if (code == "extra-vertex") return "this entry does not belong here (or is listed twice)";
    if (code == "not-adjacent") return "this is not a neighbour (or it is listed twice)";
    return "it is not right";
}

std::string capitalised(std::string s) {
    if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
    return s;
}

Words winged_edge_words(const AnswerFinding& f) {
    if (f.code == "missing-edge")
        return {"The edge table: an edge of the mesh has no row. Re-read: the edge table has one row for every edge (each side of "
                "each face; a side two faces share is one edge).",
                "Go round each face and tick off the row of each of its sides: the side you cannot tick has no row."};
    if (f.table == MeshTable::Vertex) {
        const std::string v = row_name("winged-edge", MeshTable::Vertex, f.row);
        return {"The vertex table, row " + v + ": " + what_is_wrong(f.code) + ". Re-read: the vertex table stores one edge that has " + v +
                    " as its S or its E (none only for a vertex of no face).",
                "Any edge of the edge table whose S or E is " + v + " will do."};
    }
    if (f.table == MeshTable::Face) {
        const std::string face = row_name("winged-edge", MeshTable::Face, f.row);
        return {"The face table, row " + face + ": " + what_is_wrong(f.code) + ". Re-read: the face table stores one side of " + face + ".",
                "Any edge of the edge table whose L or R is " + face + " will do."};
    }
    const std::string row = "Row " + row_name("winged-edge", MeshTable::Edge, f.row);
    if (f.code == "swapped-ends")
        return {row + ", columns S and E: " + what_is_wrong(f.code) + ". Re-read: L is the face whose corners run from S to E "
                    "(faces go counter-clockwise), R the one that runs from E to S.",
                "Walk the edge from S to E: is the face this row calls L on your left?"};
    const Column* c = winged_column(f.field);
    if (!c) return {row + ": " + what_is_wrong(f.code) + ".", ""};
    return {row + ", column " + c->head + ": " + what_is_wrong(f.code) + ". Re-read: " + c->rule + ".", capitalised(c->hint) + "."};
}

std::string item_words(const AnswerFinding& f) { return f.index >= 0 ? ", the " + ordinal_words(f.index) + " entry" : ""; }

Words faces_words(const AnswerFinding& f) {
    const std::string face = row_name("faces", MeshTable::Face, f.row);
    return {"Row " + face + item_words(f) + ": " + what_is_wrong(f.code) +
                ". Re-read: a face lists its corners in order counter-clockwise, seen from the front, starting at any corner, each once.",
            "Trace the face's boundary counter-clockwise in the drawing and write each corner as you pass it."};
}

Words edge_list_words(const AnswerFinding& f) {
    if (f.table == MeshTable::Face) {
        const std::string p = row_name("edge-list", MeshTable::Face, f.row);
        return {"The polygon table, row " + p + item_words(f) + ": " +
                    (f.code == "missing-edge" ? std::string("a side is missing") : what_is_wrong(f.code)) + ". Re-read: a polygon lists the "
                    "edges (rows of the edge list) that are its sides, each once, in any order.",
                "Go round " + p + " in the drawing and find the row of each side you pass."};
    }
    if (f.code == "missing-edge")
        return {"The edge list: an edge of the mesh has no row. Re-read: the edge list has one row for every edge (each side of each "
                "polygon; a side two polygons share is one edge).",
                "Go round each polygon and tick off the row of each of its sides: the side you cannot tick has no row."};
    const std::string row = "Row " + row_name("edge-list", MeshTable::Edge, f.row);
    const bool ends = f.field == "v1" || f.field == "v2";
    const std::string head = f.field == "v1" ? "V1" : f.field == "v2" ? "V2" : f.field == "p1" ? "P1" : f.field == "p2" ? "P2" : f.field;
    if (ends)
        return {row + ", column " + head + ": " + what_is_wrong(f.code) + ". Re-read: the first two columns are the edge's two ends; "
                    "together they must be an edge of the mesh, one row per edge.",
                "Pick two corners next to each other on a polygon, an edge no other row describes."};
    return {row + ", column " + head + ": " + what_is_wrong(f.code) + ". Re-read: the last two columns hold the two polygons on the "
                "edge's sides, in either order; λ where no polygon lies on a side.",
            "Look at the edge in the drawing: which polygons touch it along its length?"};
}

Words adjacency_words(const AnswerFinding& f) {
    const std::string v = row_name("adjacency", MeshTable::Vertex, f.row);
    return {"Row " + v + item_words(f) + ": " + what_is_wrong(f.code) + ". Re-read: the adjacency list of " + v +
                " holds every vertex joined to " + v + " by an edge, each once, in any order.",
            "Follow each edge that leaves " + v + " in the drawing and write the vertex at its other end."};
}

} // namespace

std::string ordinal_words(int32_t index0) {
    static const char* const kWords[] = {"first", "second", "third",  "fourth",   "fifth",    "sixth",
                                         "seventh", "eighth", "ninth", "tenth", "eleventh", "twelfth"};
    if (index0 >= 0 && index0 < 12) return kWords[index0];
    return "item " + std::to_string(index0 + 1) + " (counting from 1)";
}

void word_table_findings(const std::string& table, std::vector<AnswerFinding>& findings) {
    for (AnswerFinding& f : findings) {
        const Words w = table == "winged-edge" ? winged_edge_words(f)
                        : table == "faces"     ? faces_words(f)
                        : table == "edge-list" ? edge_list_words(f)
                                               : adjacency_words(f);
        f.message = w.message;
        f.hint = w.hint;
    }
}

} // namespace wingspline::mesh
