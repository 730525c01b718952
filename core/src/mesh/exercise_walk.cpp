// Checking a predicted step of the counter-clockwise walk (exercise kind 2): the
// expected edge is the core's own walk's, and the reason spells out the lecture's rule for it.
#include "wingspline/mesh/exercise_walk.h"

#include "wingspline/error.h"

namespace wingspline::mesh {

WalkStepCheck check_walk_step(const WingedEdgeMesh& mesh, bool around_face, int32_t element, int32_t step, int32_t given) {
    const int32_t count = around_face ? mesh.face_count() : mesh.vertex_count();
    const std::string name = element >= 0 && element < count ? (around_face ? face_label(element) : vertex_label(element)) : "";
    require(element >= 0 && element < count, "index-out-of-range",
            missing_element_message(around_face ? MeshTable::Face : MeshTable::Vertex, element, count));
    require(around_face || mesh.vertex_edge(element) != kNone, "no-walk",
            name + " belongs to no face: it has no edge to walk around");
    // The walk's edges, and per edge the column the rule reads there and what it says.
    std::vector<int32_t> edges;
    std::vector<int32_t> next;
    std::vector<bool> first_case; // around v: v is the Start; along f: f is the Left face
    if (around_face) {
        for (const FaceStep& s : mesh.face_edge_steps(element)) edges.push_back(s.edge), next.push_back(s.next), first_case.push_back(s.face_is_left);
    } else {
        for (const TraversalStep& s : mesh.traversal_steps(element)) edges.push_back(s.edge), next.push_back(s.next), first_case.push_back(s.at_start);
    }
    const int32_t n = static_cast<int32_t>(edges.size());
    require(step >= 1 && step <= n, "invalid-step",
            "the walk " + std::string(around_face ? "along " : "around ") + name + " has " + std::to_string(n) +
                " edges, so a step is 1 to " + std::to_string(n) + " (step " + std::to_string(n) + " closes it), not " +
                std::to_string(step));
    const int32_t from = edges[step - 1];
    WalkStepCheck out;
    out.from = from;
    out.expected = next[step - 1];
    out.done = out.expected == edges[0];
    out.correct = given == out.expected;
    const bool first = first_case[step - 1];
    std::string why;
    if (around_face)
        why = name + " is the " + (first ? "Left" : "Right") + " face of " + edge_label(from) + ", so the walk along " + name +
              " reads its " + (first ? "E:L" : "S:R") + " column";
    else
        why = name + " is the " + (first ? "Start" : "End") + " of " + edge_label(from) + ", so the CCW walk around " + name +
              " reads its " + (first ? "S:L" : "E:R") + " column";
    const std::string closed = out.done ? "; that is the first edge again, so the walk is closed" : "";
    if (out.correct) out.reason = edge_label(out.expected) + ": " + why + ", " + edge_label(out.expected) + closed;
    else {
        const std::string wrong = given == -2                                   ? std::string("no edge given")
                                  : given >= 0 && given < mesh.edge_count() ? "not " + edge_label(given)
                                  : given >= 0                               ? "not " + edge_label(given) + " (the mesh has no such edge)"
                                                                             : "not " + std::to_string(given) + " (that names no edge)";
        out.reason = wrong + ": " + why + ", which is " + edge_label(out.expected) + closed;
        const std::string rule = around_face ? "the walk along " + name + " reads E:L from an edge whose Left face is " + name +
                                                   " and S:R from one whose Right face is " + name
                                             : "the counter-clockwise walk around " + name + " reads S:L from an edge whose Start is " +
                                                   name + " and E:R from one whose End is " + name;
        out.message = "Step " + std::to_string(step) + ", from " + edge_label(from) +
                      (given == -2 ? std::string(": no edge is picked") : ": that is not the edge the walk reads next") +
                      ". Re-read the rule (lecture 000): " + rule + "; the walk ends when it comes back to the edge it started from.";
        out.hint = name + " is the " + (around_face ? (first ? "Left" : "Right") + std::string(" face") : (first ? "Start" : "End")) +
                   " of " + edge_label(from) + ": find the edge its " + (around_face ? (first ? "E:L" : "S:R") : (first ? "S:L" : "E:R")) +
                   " wing names in the drawing (the other side, at that end, of the face on that side).";
    }
    return out;
}

} // namespace wingspline::mesh
