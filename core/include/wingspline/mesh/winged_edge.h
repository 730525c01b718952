#pragma once
// Baumgart's winged-edge structure exactly as in lecture 000: a vertex table (coordinates
// and one incident edge), an edge table (S, E, L, R and the four wings) and a face table
// (one incident edge). Nothing else is kept, so its storage is the slide's storage.
//
// Conventions (decoded from the slide's table and checked against it in the tests):
//  * L is the face that traverses the edge from S to E (faces are counter-clockwise),
//    R the face that traverses it from E to S; a boundary side is kNone.
//  * Wing "X-Y" is the other edge at vertex X of the face on side Y. On a boundary side
//    the boundary loop is treated as a face (the slide: "wing edges are defined as though
//    the boundary was also a face").
//  * CCW around v: from e, if v is e's Start the next edge is start_left, else end_right.
//  * Along face f: from e, if f is e's Left the next edge is end_left, else start_right.
#include "wingspline/mesh/indexed_mesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

// An empty asm statement on one arm of a walk's two-way choice keeps the compiler from
// turning it into a select. With a select, the address of the next edge waits for the
// load of this edge's S (the walk is serialised on memory); with a predicted branch the
// processor walks ahead. Measured on the 1M-face sphere: the ring walk in wasm 8.4 -> 3.5
// ns per edge, natively 3.0 -> 2.9 (clang makes a select for wasm, gcc a branch).
#if defined(__GNUC__) || defined(__clang__)
#define WINGSPLINE_KEEP_BRANCH() __asm__ volatile("")
#else
#define WINGSPLINE_KEEP_BRANCH() ((void)0)
#endif

namespace wingspline::mesh {

// 32 bytes, aligned to 32 so that no record straddles two cache lines: a walk reads one
// line per edge. Unaligned (malloc gives 16), every other record spans two lines, and the
// 1M-face walks measured up to 1.6x slower natively and 1.5x in wasm, depending on where
// the table happened to land.
struct alignas(32) EdgeRecord {
    int32_t start = kNone, end = kNone;  // S, E
    int32_t left = kNone, right = kNone; // L, R faces
    int32_t start_left = kNone, start_right = kNone, end_left = kNone, end_right = kNone;
};

struct BuildOptions {
    // Optional: fixes the edge numbering and orientation, one [start, end] per edge.
    std::vector<std::array<int32_t, 2>> edges;
    // Optional: the edge stored for each vertex / face (each must be incident).
    std::vector<int32_t> vertex_edges;
    std::vector<int32_t> face_edges;
};

struct MeshCounts {
    int32_t vertices = 0, edges = 0, faces = 0, boundary_edges = 0, boundary_loops = 0;
    int32_t isolated_vertices = 0;
    int32_t euler() const { return vertices - edges + faces; }
};

struct TraversalStep {
    int32_t edge = kNone;
    bool at_start = false; // v (or the face's walk) met the edge at its Start
    int32_t next = kNone;  // read from start_left (at_start) or end_right
};

// Every vertex's ring walked once (docs/benchmarks.md mesh_ring): edges visited (2E on a mesh
// without isolated vertices) and the sum of the neighbour indices met.
static_assert(sizeof(EdgeRecord) == 8 * sizeof(int32_t), "the edge table crosses the boundary as 8 int32 per edge");

struct RingWalkTotals {
    double visited = 0;
    double neighbour_sum = 0;
};

struct FaceStep {
    int32_t edge = kNone;
    bool face_is_left = false; // next read from end_left (left) or start_right (right)
    int32_t next = kNone;
};

// ------------------------------------------------------------------ the change model
// Element ids that say what they are (pmp-library's typed handles): a Vertex, an Edge and a
// Face are distinct types around one int32 index, so a mutator cannot be handed a face
// where it wants an edge. kNone (-1) is the invalid sentinel. The tables and the wire
// format stay flat int32 arrays; handles are used where an id crosses an API in the core
// (the change model below; older accessors still take plain indices and move over as
// they are touched).
template <class Tag> struct Handle {
    int32_t idx = kNone;
    constexpr Handle() = default;
    constexpr explicit Handle(int32_t i) : idx(i) {}
    constexpr bool is_valid() const { return idx >= 0; }
    constexpr bool operator==(Handle o) const { return idx == o.idx; }
    constexpr bool operator!=(Handle o) const { return idx != o.idx; }
};
using Vertex = Handle<struct VertexTag>;
using Edge = Handle<struct EdgeTag>;
using Face = Handle<struct FaceTag>;

// Two counters that say which state of a mesh a cache was derived from. topology moves on
// with every change of the connectivity tables (vertex edge, edge table, face edge),
// geometry with every change of a position, each to the next number the mesh never used
// (one more than the last, unless an undo came between), never when a call changed nothing
// or was refused. Two equal versions of one mesh are the same tables: undo gives back the
// version of the state it restores (the geometry too when no position moved since the
// change), so a cache of that state is right again, and a new change never reuses a number.
struct MeshVersion {
    uint32_t topology = 0;
    uint32_t geometry = 0;
    bool operator==(const MeshVersion& o) const { return topology == o.topology && geometry == o.geometry; }
    bool operator!=(const MeshVersion& o) const { return !(*this == o); }
};

// What check_<op>() says: ok, or a stable code and a message naming the elements.
struct CheckResult {
    bool ok = true;
    std::string code;
    std::string message;
    static CheckResult accept() { return {}; }
    static CheckResult refuse(std::string code, std::string message) { return {false, std::move(code), std::move(message)}; }
};
// Throws the refusal as Error(code, message); nothing when c accepted.
inline void require_ok(const CheckResult& c) {
    if (!c.ok) throw Error(c.code, c.message);
}

// The three connectivity tables of lecture 000.
enum class MeshTable { Vertex, Edge, Face };
const char* table_name(MeshTable t); // "vertex", "edge", "face"

// How every message names a row of table t: the slides' 1-based label (v3, e5, F2), as the
// lesson tables show it, although indices are 0-based.
std::string element_label(MeshTable t, int32_t i);
// invalid-element: index names no row of a table of `count` rows. "there is no F6: the mesh
// has faces F1 to F4"; "-1 names no edge (it stands for none): the mesh has edges e1 to e7".
std::string missing_element_message(MeshTable t, int32_t index, int32_t count);
// deleted-element: "e4 was removed by an edit (its number stays a gap until the mesh is compacted)".
std::string removed_element_message(MeshTable t, int32_t index);

// One field of one table row, before and after (an edge index, a face index, ...).
struct FieldChange {
    std::string field; // the column as the docs and the JS rows name it: "edge", "start", "startLeft", ...
    int32_t before = kNone;
    int32_t after = kNone;
};
struct RowChange {
    MeshTable table = MeshTable::Vertex;
    int32_t row = kNone;
    std::vector<FieldChange> fields;
};
// One pointer assignment as the algorithm makes it (the Euler operations record every one,
// in order, for step-by-step playback): table[row].field goes from before to after. The
// face table's "firstCorner" field is the corner face_set() lists the face from (kept only
// once a face edge was chosen; see WingedEdgeMesh::face_set()).
struct AssignmentStep {
    MeshTable table = MeshTable::Vertex;
    int32_t row = kNone;
    std::string field;
    int32_t before = kNone;
    int32_t after = kNone;
    int32_t phase = kNone; // which of ChangeRecord::phases (the algorithm's line) made it
};
// A vertex position set by an operation: a new vertex (before = its coordinates too, as it
// had none) or a moved one (collapse). `step` = how many assignment steps came before it.
struct PositionChange {
    int32_t vertex = kNone;
    glm::dvec3 before{0.0}, after{0.0};
    std::size_t step = 0;
};

// What one operation did: the elements it added and removed (removed ones stay as marked
// gaps, see is_deleted()), and every table row it changed with its fields before and after
// (enough to show the change and to undo it). Empty when the operation changed nothing.
struct ChangeRecord {
    std::string op; // "set-vertex-edge", ...
    std::vector<Vertex> added_vertices, removed_vertices;
    std::vector<Edge> added_edges, removed_edges;
    std::vector<Face> added_faces, removed_faces;
    std::vector<RowChange> rows;      // per changed row, each changed field's first before and last after
    std::vector<AssignmentStep> steps; // every assignment in the algorithm's order (Euler operations)
    std::vector<PositionChange> positions;
    // The algorithm's lines in the order it runs them, as its source comments read ("the new
    // edge's row: S, E, L, R and its four wings"); each step names the line that made it.
    std::vector<std::string> phases;
    MeshVersion before, after;
    // The change began the list of faces' first corners (set-face-edge on a mesh whose faces
    // were all listed from their walks' starts): undo ends it.
    bool began_first_corners = false;
    bool changed() const { return before != after; }
};

// How compact() moved the elements: old index -> new index (kNone for a removed one).
struct Renumbering {
    std::vector<int32_t> vertices, edges, faces;
};

// Removes repeats from v, keeping each element where it first appears (n log n).
void keep_first_appearance(std::vector<int32_t>& v);

class WingedEdgeMesh;

// An operation as a value (operations.h): which entry of the registry, and its arguments in
// the entry's order (element indices as numbers, then a parameter such as t).
struct OperationEntry;
struct Operation {
    const OperationEntry* entry = nullptr;
    std::array<double, 4> args{kNone, kNone, kNone, kNone};
};

// Building in steps: exactly the phases of WingedEdgeMesh::build (which runs them
// through this class in one go), one phase per step(), so a page can build a million-face
// mesh without holding its main thread for the whole build (about 110 ms in wasm here).
class WingedEdgeBuild {
public:
    explicit WingedEdgeBuild(IndexedMesh mesh, BuildOptions options = {});
    ~WingedEdgeBuild();
    WingedEdgeBuild(WingedEdgeBuild&&) noexcept;
    WingedEdgeBuild& operator=(WingedEdgeBuild&&) noexcept;
    // Runs the next phase; true once the mesh is complete. Throws exactly what build() throws
    // (InvalidMesh, Error) in the phase that finds the problem; the build is then over.
    bool step();
    // The phase step() runs next ("done" once complete).
    const char* phase() const;
    // The mesh, once step() returned true (the build is then empty).
    WingedEdgeMesh take();

private:
    friend class WingedEdgeMesh;
    struct State;
    WingedEdgeBuild(const IndexedMesh* mesh, const BuildOptions* options, std::vector<double>* positions_to_take, bool fast);
    std::unique_ptr<State> s_;
};

class WingedEdgeMesh {
public:
    // Builds the structure. Without options.edges, edges are numbered in order of first
    // appearance walking the faces and oriented as first traversed. Default vertex edge:
    // at a boundary vertex the edge that follows the boundary gap counter-clockwise (so the
    // CCW walk meets all faces before the gap); elsewhere the lowest-numbered incident
    // edge. Default face edge: the edge along the face's first side (its first two corners),
    // so that face_set() reads the faces back with their corners in the order given.
    // Throws InvalidMesh (with the full report) when the winged edge cannot hold the mesh,
    // Error("invalid-edge-list" / "invalid-vertex-edge" / "invalid-face-edge") for bad options.
    static WingedEdgeMesh build(const IndexedMesh& mesh, const BuildOptions& options = {});
    // The same, taking the positions over instead of copying them (a caller that made the
    // face set only to build from it, as the wasm binding does). On refusal `mesh` is intact.
    static WingedEdgeMesh build(IndexedMesh&& mesh, const BuildOptions& options = {});
    // The same tables by the lecture's path alone, without the fixed-degree kernels
    // (fast_kernels.cpp); the tests check build() against it on random meshes.
    static WingedEdgeMesh build_reference(const IndexedMesh& mesh, const BuildOptions& options = {});

    int32_t vertex_count() const { return static_cast<int32_t>(vertex_edge_.size()); }
    int32_t edge_count() const { return static_cast<int32_t>(edges_.size()); }
    int32_t face_count() const { return static_cast<int32_t>(face_edge_.size()); }

    const EdgeRecord& edge(int32_t e) const { return edges_[e]; }
    int32_t vertex_edge(int32_t v) const { return vertex_edge_[v]; }
    int32_t face_edge(int32_t f) const { return face_edge_[f]; }
    glm::dvec3 position(int32_t v) const {
        return {positions_[3 * v], positions_[3 * v + 1], positions_[3 * v + 2]};
    }
    const std::vector<double>& positions() const { return positions_; }
    const std::vector<EdgeRecord>& edges() const { return edges_; }
    const std::vector<int32_t>& vertex_edges() const { return vertex_edge_; } // the vertex table's edge column
    const std::vector<int32_t>& face_edges() const { return face_edge_; }     // the face table
    // Throws Error("non-finite-coordinate" / "coordinate-out-of-range") beyond kMaxCoordinate
    // (limits.h) and then changes nothing. Moves the geometry version on when p differs.
    void set_position(int32_t v, const glm::dvec3& p);

    // ---------------------------------------------------------------- change model
    // Which state of the mesh this is (see MeshVersion); a freshly built mesh is {0, 0}.
    MeshVersion version() const { return version_; }

    // Checked operations, in pmp-library's manner (is_flip_ok before flip), one generic
    // pair for every operation of the registry (operations.h): check(op) changes nothing and
    // says whether op may run; apply(op) calls it first and, if refused, throws
    // Error(code, message) with the structure bit-identical. A successful apply returns the
    // ChangeRecord (every assignment in order, per-row before/after, the elements added at
    // the next free numbers and removed as marked gaps) and leaves validate() clean; the
    // topology version moves on by one when anything changed (geometry too when a position
    // was set). docs/api-mesh.md, "Changing a mesh", lists the operations and refusals.
    CheckResult check(const Operation& op) const;
    ChangeRecord apply(const Operation& op);

    // Takes back the newest change, from the record apply() returned for it: every row it
    // rewrote gets its values from before the change, the elements it added go (the tables
    // end where they ended before it, so the same change made again gives the same numbers),
    // those it removed are live again, the vertices it moved go back. The mesh is then the
    // one before the change row for row, its gaps included (validate() clean), in O(the
    // change), where building the mesh again and replaying every other change was O(mesh).
    // check_undo(change) refuses "cannot-undo" when the record is not the newest change: the
    // topology is not the one it left (change.after.topology), a field it wrote or a
    // position it set holds something else now, or its new elements are not the last rows.
    // The version is the one before the change again (MeshVersion); the geometry is a new
    // number instead when a position moved since the change. Returns the undo's own
    // record: op "undo", rows with each field as the change left it (before) and as it is
    // again (after), added = the elements live again, removed = the elements gone (rows that
    // no longer exist, not gaps), positions = the vertices moved back; no steps.
    CheckResult check_undo(const ChangeRecord& change) const;
    ChangeRecord undo(const ChangeRecord& change);

    // Room for this many elements in all, so that a run of operations does not reallocate.
    void reserve(int32_t vertices, int32_t edges, int32_t faces);

    // Removes the gaps the operations left: every table is renumbered keeping the order of
    // the elements that remain. Returns old -> new per kind. Moves the topology version on
    // when there was something to remove.
    Renumbering compact();
    // The mark vectors (empty = nothing deleted): 1 where the row is a gap.
    const std::vector<char>& deleted_vertices() const { return vertex_deleted_; }
    const std::vector<char>& deleted_edges() const { return edge_deleted_; }
    const std::vector<char>& deleted_faces() const { return face_deleted_; }

    // Removed elements (join-faces, collapse-edge) are not compacted away: their rows stay,
    // unchanged but marked deleted, so every index a student is looking at keeps its
    // meaning, until compact() (an explicit step, as pmp's garbage_collection()) renumbers
    // and says how the indices moved. The marks are held only once something is removed
    // (empty vectors = nothing deleted).
    bool is_deleted(Vertex v) const { return !vertex_deleted_.empty() && vertex_deleted_[v.idx]; }
    bool is_deleted(Edge e) const { return !edge_deleted_.empty() && edge_deleted_[e.idx]; }
    bool is_deleted(Face f) const { return !face_deleted_.empty() && face_deleted_[f.idx]; }
    bool has_garbage() const { return !vertex_deleted_.empty() || !edge_deleted_.empty() || !face_deleted_.empty(); }

    // The lecture's rule, one step: the edge after e counter-clockwise around v.
    int32_t next_ccw(int32_t e, int32_t v) const {
        const EdgeRecord& r = edges_[e];
        if (r.start == v) return r.start_left;
        WINGSPLINE_KEEP_BRANCH();
        return r.end_right;
    }
    // The edge after e along face f (counter-clockwise).
    int32_t next_in_face(int32_t e, int32_t f) const {
        const EdgeRecord& r = edges_[e];
        if (r.left == f) return r.end_left;
        WINGSPLINE_KEEP_BRANCH();
        return r.start_right;
    }
    int32_t other_vertex(int32_t e, int32_t v) const {
        return edges_[e].start == v ? edges_[e].end : edges_[e].start;
    }

    std::vector<int32_t> edges_around_vertex(int32_t v) const;
    // For every vertex in index order, the CCW walk by the lecture's rule (no lists built).
    RingWalkTotals walk_every_ring() const;
    std::vector<TraversalStep> traversal_steps(int32_t v) const;
    std::vector<int32_t> faces_around_vertex(int32_t v) const;    // CCW, boundary gaps skipped
    std::vector<int32_t> vertices_around_vertex(int32_t v) const; // CCW
    std::vector<int32_t> edges_of_face(int32_t f) const;          // CCW from the face's edge
    std::vector<FaceStep> face_edge_steps(int32_t f) const;
    std::vector<int32_t> vertices_of_face(int32_t f) const;       // CCW, first = S-side of face edge walk
    std::array<int32_t, 2> faces_of_edge(int32_t e) const { return {edges_[e].left, edges_[e].right}; }
    std::vector<int32_t> face_neighbours(int32_t f) const;        // distinct faces across f's edges, first met first

    // The indexed face set read back from the structure: each face's corners in walk order,
    // listed from the face's first corner as the mesh was built (so a face edge chosen at
    // build time or by set_face_edge changes where the walk starts, not the face set). The
    // other representations are derived from this (representations.h, RepresentationCache).
    IndexedMesh face_set() const;
    // One face of face_set(): its corners from its first corner; none for a removed face.
    // O(the face's sides): what a page reads again for the faces an edit changed.
    std::vector<int32_t> face_corners(int32_t f) const;
    // The face set without the gaps an edit left (face_set() lists a removed face with no
    // corners and keeps a removed vertex's position): live vertices and faces numbered in
    // order, as compact() would number them. What a file gets (OFF/OBJ have no room for gaps).
    IndexedMesh live_face_set() const;

    MeshCounts counts() const;
    // Bytes of the vertex, edge and face tables (capacity actually held).
    std::size_t bytes() const;
    // Every broken connectivity invariant (wings, rings, face loops, table references).
    ValidationReport validate() const;
    // Whether an index names a live element: invalid-element (no such row) or deleted-element
    // (a gap), with missing_element_message / removed_element_message; what every call that
    // takes an element checks first.
    CheckResult check_element(Vertex v) const;
    CheckResult check_element(Edge e) const;
    CheckResult check_element(Face f) const;

private:
    static WingedEdgeMesh build_impl(const IndexedMesh& mesh, const BuildOptions& options,
                                     std::vector<double>* positions_to_take, bool fast_kernels);

    std::vector<double> positions_;    // positions_[3*v + k]
    std::vector<int32_t> vertex_edge_; // one incident edge per vertex (kNone if isolated)
    std::vector<EdgeRecord> edges_;
    std::vector<int32_t> face_edge_;   // one edge per face
    // The corner each face is listed from in face_set() (the first corner of the face as
    // given). Empty while every face's stored edge starts at its first corner, which is
    // the default build; filled when the caller chose face edges or set_face_edge moved
    // one. Not one of the slide's tables, so not counted in bytes().
    std::vector<int32_t> face_first_corner_;
    MeshVersion version_;
    std::vector<char> vertex_deleted_, edge_deleted_, face_deleted_; // see is_deleted()
    // How many marks each of those holds (vertex, edge, face): undo() drops a mark vector
    // whose last mark it took back, so a mesh whose gaps were all undone has none, as before.
    std::array<int32_t, 3> deleted_count_{};
    MeshVersion used_; // the highest numbers version_ has had (a change takes the next)

    friend class WingedEdgeBuild;
    friend struct EulerAccess;  // euler_ops.cpp: the operations' checks,
    friend struct EulerChanges; // their changes,
    friend struct EulerRows;    // and the bookkeeping they share
    friend struct SubdivisionAccess; // subdivision.cpp builds a result's tables directly

    int32_t walk_start_corner(int32_t f) const {
        const EdgeRecord& r = edges_[face_edge_[f]];
        return r.left == f ? r.start : r.end;
    }
};

} // namespace wingspline::mesh
