#include "wingspline/error_codes.h"

namespace wingspline {

const std::vector<ErrorCodeInfo>& error_codes() {
    static const std::vector<ErrorCodeInfo> all = {
        // loading and arguments (every part)
        {"core-load-failed", "loading", "the wasm module could not be fetched, compiled or started (the message names the file and the reason)"},
        {"part-not-loaded", "loading", "the core module was loaded without the part this call needs (the subdivision lesson's module does not edit meshes); the message names the part to load"},
        {"internal-error", "loading", "a failure the core did not expect; the message says what it was (please report it)"},
        {"out-of-memory", "loading", "the input is too large for the memory available to the page"},
        {"invalid-argument", "arguments", "a value of the wrong type, count or range (the message names it)"},
        {"disposed", "arguments", "a mesh used after dispose() (or never built)"},
        // mesh files
        {"parse-error", "mesh files", "an OFF or OBJ file that cannot be read (names the line)"},
        {"truncated-file", "mesh files", "a file that ends before the counts its header promised"},
        {"line-too-long", "mesh files", "a line of a mesh file longer than the reader accepts"},
        {"unknown-format", "mesh files", "a format other than 'off' or 'obj'"},
        {"index-out-of-range", "mesh files", "a face that names a vertex the file does not have"},
        // the mesh limits
        {"face-too-large", "mesh limits", "a face with more corners than a face may have (meshLimits.maxFaceCorners), from a file, a face set or an edit"},
        {"too-large", "mesh limits", "more vertices, faces or points than the limits allow (names the count and the limit)"},
        {"coordinate-out-of-range", "mesh limits", "a coordinate beyond meshLimits.maxCoordinate"},
        // building a mesh
        {"empty-mesh", "building a mesh", "a mesh with no faces"},
        {"non-finite-coordinate", "building a mesh", "a vertex coordinate that is NaN or infinite (names the vertex)"},
        {"too-few-vertices", "building a mesh", "a face with fewer than three corners"},
        {"repeated-vertex", "building a mesh", "a face that passes the same vertex twice"},
        {"non-manifold-edge", "building a mesh", "an edge shared by more than two faces"},
        {"inconsistent-orientation", "building a mesh", "two faces that traverse their shared edge in the same direction"},
        {"duplicate-face", "building a mesh", "two faces with the same corners"},
        {"non-manifold-vertex", "building a mesh", "a vertex whose faces form more than one fan"},
        {"isolated-vertex", "building a mesh", "a vertex on no face (a warning: it is kept with no edge)"},
        {"invalid-edge-list", "building a mesh", "a given edge numbering that does not list the mesh's edges once each"},
        {"invalid-vertex-edge", "building a mesh", "a given vertex edge that does not touch its vertex"},
        {"invalid-face-edge", "building a mesh", "a given face edge that is not a side of its face"},
        {"face-first-corner-not-on-face", "building a mesh", "a face's first corner that is not one of its corners"},
        // structure invariants
        {"invalid-reference", "structure invariants", "a table entry naming a vertex, edge or face that does not exist"},
        {"edge-without-face", "structure invariants", "an edge with neither a left nor a right face"},
        {"wing-mismatch", "structure invariants", "a wing that is not the other edge of its face at its vertex"},
        {"face-edge-not-incident", "structure invariants", "a face table entry that is not a side of its face"},
        {"vertex-edge-not-incident", "structure invariants", "a vertex table entry that does not touch its vertex"},
        {"open-vertex-ring", "structure invariants", "a walk around a vertex that does not come back to its start"},
        {"open-face-loop", "structure invariants", "a walk along a face that does not come back to its start"},
        {"half-edge-broken", "structure invariants", "a half-edge row that breaks a rule of the half-edge structure"},
        // queries, tables, representations
        {"unknown-query", "queries and tables", "an adjacency or cost query by a name the core does not know"},
        {"invalid-element", "queries and tables", "an index that names no element (\"there is no e8: the mesh has edges e1 to e7\")"},
        {"deleted-element", "queries and tables", "an element an edit removed (its number stays a gap until compact())"},
        {"mismatched-face-set", "queries and tables", "representations built from a face set other than the winged edge's"},
        {"representations-not-built", "queries and tables", "a table of a representation that has not been derived yet"},
        {"unknown-representation", "queries and tables", "a representation name other than the six"},
        {"unknown-table", "queries and tables", "a table name the representation does not have"},
        {"unknown-column", "queries and tables", "a column name the table does not have"},
        {"unknown-mesh", "queries and tables", "a named example mesh the core does not have"},
        {"unknown-task", "queries and tables", "a benchmark task the bench module does not time"},
        // changing a mesh
        {"unknown-operation", "changing a mesh", "an operation name the registry does not have (the message lists the names)"},
        {"invalid-parameter", "changing a mesh", "t outside the range the operation allows"},
        {"same-vertex", "changing a mesh", "two vertices that must differ are the same"},
        {"not-a-corner", "changing a mesh", "split-face: a vertex that is not a corner of the face"},
        {"not-a-neighbour", "changing a mesh", "split-vertex: a vertex that is not joined to the vertex split"},
        {"adjacent-corners", "changing a mesh", "split-face: two corners already joined by a side of the face"},
        {"edge-exists", "changing a mesh", "the new edge would repeat an edge the mesh has"},
        {"edge-not-incident", "changing a mesh", "set-vertex-edge: an edge that does not touch the vertex"},
        {"edge-not-on-face", "changing a mesh", "set-face-edge: an edge that is not a side of the face"},
        {"boundary-edge", "changing a mesh", "an edge on the boundary where two faces are needed"},
        {"same-face", "changing a mesh", "join-faces: an edge with one face on both sides"},
        {"faces-touch-elsewhere", "changing a mesh", "join-faces: the two faces also share another corner"},
        {"would-duplicate-face", "changing a mesh", "the result would hold the same polygon twice"},
        {"not-triangles", "changing a mesh", "flip-edge: a face beside the edge is not a triangle"},
        {"would-pinch", "changing a mesh", "collapse-edge: both ends on the boundary but the edge is not"},
        {"hole-too-small", "changing a mesh", "collapse-edge: a three-corner hole beside the edge"},
        {"degenerate-vertex", "changing a mesh", "collapse-edge: a vertex would keep two edges between the same two triangles"},
        {"link-condition", "changing a mesh", "collapse-edge: a vertex joined to both ends but not across a triangle on the edge"},
        {"link-condition-face", "changing a mesh", "collapse-edge: another face holds both ends"},
        {"cannot-undo", "changing a mesh", "undo: the change is not the mesh's newest (another came after it, or there is none to take back)"},
        // subdivision
        {"unknown-scheme", "subdivision", "a scheme other than 'loop' or 'catmull-clark' (curves: 'chaikin' or 'cubic')"},
        {"not-a-triangle-mesh", "subdivision", "Loop's scheme on a mesh with a face that is not a triangle"},
        {"mesh-has-gaps", "subdivision", "a mesh with gaps an edit left (compact() it first)"},
        // exercises
        {"invalid-answer", "exercises", "a student's answer of the wrong shape (names the row or field)"},
        {"invalid-faces", "exercises", "an exercise mesh whose faces the checker cannot use"},
        {"invalid-step", "exercises", "a walk step that names no step of the walk"},
        {"no-walk", "exercises", "a walk question about an element with no walk (an isolated vertex)"},
        {"unknown-quantity", "exercises", "a curve exercise quantity the checker does not know"},
        {"unknown-property", "exercises", "a curve exercise property the checker does not know"},
        {"no-exact-mask", "exercises", "a subdivide question about a new point with no exact mask (a Loop face point, an isolated vertex, Loop's beta at a valence other than 3, 4 or 6)"},
        {"degenerate-curve", "exercises", "a curve exercise whose curve has no well-defined answer (zero length, zero tangent)"},
        // curves
        {"unknown-curve-kind", "curves", "a curve kind other than the seven"},
        {"unknown-basis", "curves", "a basis name other than hermite, bezier, bspline, catmull-rom"},
        {"unknown-form", "curves", "a matrix form name the core does not know"},
        {"unsupported-curve-kind", "curves", "a B-spline algorithm on a curve kind that has no knots"},
        {"invalid-dimension", "curves", "a dimension other than 2 or 3"},
        {"invalid-points", "curves", "a point list whose length is not a multiple of the dimension"},
        {"non-finite-input", "curves", "NaN or infinity in a point, knot, weight, tangent, node or parameter (names it)"},
        {"non-finite-result", "curves", "a result beyond the largest number (a projective map sending a point to infinity)"},
        {"too-few-points", "curves", "fewer points than the family needs (says how many)"},
        {"degree-out-of-range", "curves", "a degree outside 1 to 20"},
        {"wrong-knot-count", "curves", "a knot vector whose length is not K + p + 1"},
        {"decreasing-knots", "curves", "knots that decrease (names both)"},
        {"knot-multiplicity-exceeded", "curves", "a knot value more than p + 1 times"},
        {"empty-domain", "curves", "a B-spline whose domain t_p .. t_K is empty"},
        {"wrong-weight-count", "curves", "a weight list of another length than the points"},
        {"invalid-weight", "curves", "a weight that is not a positive finite number"},
        {"weight-ratio-out-of-range", "curves", "weights whose largest exceeds the smallest by more than 1e300"},
        {"wrong-tangent-count", "curves", "Hermite tangents of another count than the points"},
        {"wrong-node-count", "curves", "interpolation nodes of another count than the points"},
        {"nodes-not-increasing", "curves", "interpolation nodes that do not increase"},
        {"nodes-too-close", "curves", "two interpolation nodes closer than 1e-9 of their spread"},
        {"nodes-out-of-range", "curves", "interpolation nodes whose spread overflows"},
        {"vandermonde-out-of-range", "curves", "a Vandermonde matrix or its inverse beyond double range"},
        {"parameter-out-of-range", "curves", "a parameter outside the curve's domain (names it)"},
        {"segment-out-of-range", "curves", "a segment index outside the curve's segments"},
        {"dimension-mismatch", "curves", "two curves of different dimensions compared"},
        {"length-overflow", "curves", "an arc length beyond the largest double"},
        {"not-converged", "curves", "an adaptive quadrature that spent its budget before its accuracy"},
        {"wrong-point-count", "curves", "a patch or construction given another number of points than it needs"},
        {"singular-matrix", "curves", "a matrix that cannot be inverted"},
        {"perspective-behind-eye", "curves", "a perspective map of a point at or behind the eye"},
        {"overflow", "curves", "an exact fraction that grew beyond 64 bits"},
    };
    return all;
}

bool is_error_code(std::string_view code) {
    for (const ErrorCodeInfo& e : error_codes())
        if (code == e.code) return true;
    return false;
}

} // namespace wingspline
