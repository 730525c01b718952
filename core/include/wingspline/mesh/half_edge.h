#pragma once
// The half-edge structure (OpenMesh, pmp-library, CGAL's Surface_mesh, geometry-central),
// derived from the winged edge (winged_edge.h) and kept in step with its edits: the
// structure a student meets after lecture 000, taught from the one they know.
//
// Numbering (the only place it is stated; the API uses it, the page shows it from 1):
//  * edge e gives two half-edges, 2e = S -> E (its face is e's L) and 2e+1 = E -> S (its
//    face is e's R); on screen, e1 gives h1 = S -> E and h2 = E -> S.
//  * twin(h) = h ^ 1: implicit in the numbering, not stored.
//
// Stored, one flat int32 array per column, kNone (-1) for none:
//  * per half-edge: origin, face (kNone on the boundary), next, prev. The target is not
//    stored: target(h) = origin(twin(h)).
//  * per vertex one outgoing half-edge: on the boundary the outgoing boundary half-edge
//    (face kNone), as pmp and OpenMesh choose it, so a CCW walk from it meets the whole fan
//    (the winged edge refuses a vertex with two boundary gaps, non-manifold-vertex; were there
//    two, the first met walking CCW from its winged-edge edge). kNone for an isolated vertex.
//  * per face one half-edge: the side of its winged-edge face edge that runs along it.
// Boundary half-edges are explicit: their next/prev follow the boundary loop (the slide's
// "as though the boundary was also a face", read off the wings like any face's).
// Gaps: an edge, vertex or face an edit removed (WingedEdgeMesh::is_deleted) keeps its
// numbers, and its rows here are all kNone until the winged edge is compacted.
//
// From the wings (winged_edge.h's conventions), for edge e = (S, E, L, R):
//   next(2e)   = the half-edge of end_left leaving E     prev(2e)   = start_left's arriving at S
//   next(2e+1) = the half-edge of start_right leaving S  prev(2e+1) = end_right's arriving at E
#include "wingspline/mesh/indexed_mesh.h"
#include "wingspline/mesh/queries.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/winged_edge.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace wingspline::mesh {

inline constexpr int32_t twin(int32_t h) { return h ^ 1; }
inline constexpr int32_t edge_of_half_edge(int32_t h) { return h >> 1; }

// One step of a half-edge walk: the half-edge reached, the field read there (prev around a
// vertex, next along a face) with the value read, and the half-edge the step goes to.
struct HalfEdgeStep {
    int32_t halfedge = kNone;
    int32_t read = kNone; // prev[halfedge] around a vertex, next[halfedge] along a face
    int32_t next = kNone; // twin(read) around a vertex, read along a face
};
static_assert(sizeof(HalfEdgeStep) == 3 * sizeof(int32_t), "a walk crosses the boundary as 3 int32 per step");

// One entry of the half-edge tables an edit changed, shaped as the winged edge's
// AssignmentStep: table[row].field went from before to after (kNone for a gap or a row the
// edit added). The twin is not a field: it is h ^ 1 whatever the edit.
enum class HalfEdgeTable : int32_t { HalfEdge, Vertex, Face };
enum class HalfEdgeField : int32_t { Origin, Face, Next, Prev, HalfEdge }; // HalfEdge: a vertex's or face's one
struct HalfEdgeAssignment {
    HalfEdgeTable table = HalfEdgeTable::HalfEdge;
    int32_t row = kNone;
    HalfEdgeField field = HalfEdgeField::Origin;
    int32_t before = kNone;
    int32_t after = kNone;
    // The winged-edge record's step (index into ChangeRecord::steps) that first names the
    // row's edge, vertex or face; kNone when no step names it (a row that reads a changed
    // neighbour: a wing's next or prev, the half-edge of a vertex at a changed edge's end).
    int32_t step = kNone;
};
static_assert(sizeof(HalfEdgeAssignment) == 6 * sizeof(int32_t), "a half-edge record crosses the boundary as 6 int32 per entry");

class HalfEdgeMesh {
public:
    // The view of `w` as it is now, O(V + E + F).
    static HalfEdgeMesh build(const WingedEdgeMesh& w);
    // After `w` changed by `change` (an apply's record or an undo's) from the state this view
    // shows: rewrites only the rows the change can reach (both half-edges of every edge it
    // names and of their wings, the ends of those edges, the faces on their sides, the
    // vertices and faces it names), grows the arrays for new elements and shrinks them when
    // an undo removed the last rows: O(the edit). The result equals build(w).
    // `written` (if given) receives every entry whose value changed, each once with its
    // first before and last after, in an order a student can follow: per step of the
    // winged-edge record, the first time it names an element, that element's rows (an edge:
    // origin, face, next, prev of 2e, then of 2e + 1); then the rows reached through a
    // neighbour; rows an undo dropped from the end go to kNone. Replayed on the view
    // before, it gives the view after.
    void update(const WingedEdgeMesh& w, const ChangeRecord& change, std::vector<HalfEdgeAssignment>* written = nullptr);

    int32_t halfedge_count() const { return static_cast<int32_t>(origin_.size()); }
    int32_t vertex_count() const { return static_cast<int32_t>(vertex_halfedge_.size()); }
    int32_t face_count() const { return static_cast<int32_t>(face_halfedge_.size()); }

    int32_t origin(int32_t h) const { return origin_[h]; }
    int32_t target(int32_t h) const { return origin_[twin(h)]; }
    int32_t face(int32_t h) const { return face_[h]; }
    int32_t next(int32_t h) const { return next_[h]; }
    int32_t prev(int32_t h) const { return prev_[h]; }
    int32_t vertex_halfedge(int32_t v) const { return vertex_halfedge_[v]; }
    int32_t face_halfedge(int32_t f) const { return face_halfedge_[f]; }
    bool is_boundary(int32_t h) const { return face_[h] == kNone; }

    const std::vector<int32_t>& origins() const { return origin_; }
    const std::vector<int32_t>& faces() const { return face_; }
    const std::vector<int32_t>& nexts() const { return next_; }
    const std::vector<int32_t>& prevs() const { return prev_; }
    const std::vector<int32_t>& vertex_halfedges() const { return vertex_halfedge_; }
    const std::vector<int32_t>& face_halfedges() const { return face_halfedge_; }

    // Around vertex v, counter-clockwise (seen with the faces CCW): h -> twin(prev(h)), from
    // `start` (an outgoing half-edge of v; kNone = v's own half-edge). The other way,
    // h -> next(twin(h)), turns clockwise. Empty for an isolated vertex.
    std::vector<HalfEdgeStep> vertex_walk(int32_t v, int32_t start = kNone) const;
    // Along face f (CCW): h -> next(h) from the face's half-edge.
    std::vector<HalfEdgeStep> face_walk(int32_t f) const;

    // Every broken half-edge invariant: twin(twin(h)) = h and twin(h) != h, next(prev(h)) = h
    // and prev(next(h)) = h, origin(next(h)) = target(h), face(next(h)) = face(h), a vertex's
    // half-edge starts at it (and is a boundary one when the vertex is on the boundary), a
    // face's half-edge lies on it and its next-loop has as many sides as the face has corners
    // (`w`: the winged edge it was derived from, for the corner counts and the gaps).
    // Codes: "half-edge-broken" (one per broken rule, naming h1.. as the page does).
    ValidationReport validate(const WingedEdgeMesh& w) const;

    // The arrays as they are held: origin, face, next, prev (4 int32 per half-edge), vertex
    // half-edge, face half-edge. Vertex coordinates are not here (they are the winged edge's;
    // half_edge_storage below adds them for a comparison with the other representations).
    Storage storage() const;

    bool operator==(const HalfEdgeMesh& o) const {
        return origin_ == o.origin_ && face_ == o.face_ && next_ == o.next_ && prev_ == o.prev_ &&
               vertex_halfedge_ == o.vertex_halfedge_ && face_halfedge_ == o.face_halfedge_;
    }
    bool operator!=(const HalfEdgeMesh& o) const { return !(*this == o); }

private:
    void write_edge(const WingedEdgeMesh& w, int32_t e);
    void write_vertex(const WingedEdgeMesh& w, int32_t v);
    void write_face(const WingedEdgeMesh& w, int32_t f);
    void resize(const WingedEdgeMesh& w);

    std::vector<int32_t> origin_, face_, next_, prev_; // per half-edge h
    std::vector<int32_t> vertex_halfedge_;             // per vertex
    std::vector<int32_t> face_halfedge_;               // per face
};

// The half-edge structure as the lessons compare it with the winged edge: vertex coordinates
// (3 doubles per vertex, as winged_edge_storage counts them) plus the arrays of storage().
Storage half_edge_storage(const HalfEdgeMesh& h, const WingedEdgeMesh& w);

// A lecture query (queries.h) answered on the half-edge arrays alone, counting every entry
// read as queries.cpp counts them for the six representations (twin and the edge of a
// half-edge are arithmetic on the numbering: no read). Answers: around a vertex CCW from
// its half-edge (faces skipping the boundary), a face's edges from its half-edge, the faces
// of an edge (face of 2e then of 2e+1, no -1), a face's neighbours first met first.
// Throws as winged_edge_answer does (invalid-element, deleted-element).
QueryAnswer half_edge_answer(QueryKind kind, int32_t element, const HalfEdgeMesh& h, const WingedEdgeMesh& w);

} // namespace wingspline::mesh
