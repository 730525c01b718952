#pragma once
// Exercise kind 2: predicting the next edge of lecture 000's counter-clockwise walk
// around a vertex, or along a face, step after step. The walk is the core's own
// (WingedEdgeMesh::traversal_steps / face_edge_steps): it starts at the edge the vertex (face)
// table stores and reads, from each edge, the column the lecture's rule names:
//  * around v: S:L when v is the edge's Start, E:R when it is its End;
//  * along f: E:L when f is the edge's Left face, S:R when it is its Right face.
// Step k (k >= 1) asks for the walk's edge k, edges 0 .. k-1 being shown; the last step, k = n
// for a walk of n edges, is the first edge again (the walk closes).
#include "wingspline/mesh/winged_edge.h"

#include <cstdint>
#include <string>

namespace wingspline::mesh {

struct WalkStepCheck {
    bool correct = false;
    int32_t from = kNone;     // the edge the step starts from (the walk's edge k-1), shown to the student
    int32_t expected = kNone; // the edge the rule reads (0-based mesh edge)
    bool done = false;        // expected is the walk's first edge: the walk is closed
    std::string reason;       // the rule applied to this step, with 1-based labels (v2, e5, F1)
    // Value-free (feedback levels "check" and "hint"): the step and the edge it starts from,
    // the rule to re-read; the hint names the column to read. Never the expected edge.
    std::string message;
    std::string hint;
};

// around_face: false = around vertex `element`, true = along face `element`. `given` is the
// student's edge (any number: one that names no edge, -1 or -2 for blank, is simply wrong).
// Throws Error "index-out-of-range" (no such vertex or face), "no-walk" (a vertex with no edge),
// "invalid-step" (step < 1 or past the step that closes the walk).
WalkStepCheck check_walk_step(const WingedEdgeMesh& mesh, bool around_face, int32_t element, int32_t step, int32_t given);

} // namespace wingspline::mesh
