// What an edit costs each representation: reads through the queries' counting reader,
// writes from the change record (winged edge) or by comparing tables (the others).
#include "wingspline/mesh/edit_costs.h"

#include "cost_grids.h"

#include "wingspline/error.h"
#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/queries.h"
#include "wingspline/mesh/tables.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace wingspline::mesh {

const char* locate_description(Locate locate) {
    switch (locate) {
    case Locate::EdgeSides: return "the faces on both sides of {e} and their sides";
    case Locate::EdgeSidesAndEnds: return "the faces on both sides of {e}, their sides and the edges at both its ends";
    case Locate::FaceSides: return "the sides of {f}";
    case Locate::VertexStar: return "the edges around {v}";
    }
    return "";
}

namespace {

// The queries `op` asks to find what it rewrites (its entry's Locate), each through `ask`,
// which answers as the winged edge does and counts what it read.
template <class Ask> void locate(const Operation& op, const WingedEdgeMesh& winged, Ask&& ask) {
    const auto element = static_cast<int32_t>(op.args[0]);
    switch (op.entry->locate) {
    case Locate::EdgeSides:
    case Locate::EdgeSidesAndEnds:
        for (const int32_t f : ask(QueryKind::FacesOfEdge, element)) ask(QueryKind::EdgesOfFace, f);
        if (op.entry->locate == Locate::EdgeSidesAndEnds) {
            ask(QueryKind::EdgesAroundVertex, winged.edge(element).start);
            ask(QueryKind::EdgesAroundVertex, winged.edge(element).end);
        }
        break;
    case Locate::FaceSides: ask(QueryKind::EdgesOfFace, element); break;
    case Locate::VertexStar: ask(QueryKind::EdgesAroundVertex, element); break;
    }
}

} // namespace

std::array<int64_t, kRepresentationCount> edit_reads(const Operation& op, const WingedEdgeMesh& winged, const Representations& reps) {
    std::array<int64_t, kRepresentationCount> reads{};
    // Each representation answers with its own reader; the answers agree (test_representations),
    // so the winged edge's answer says which elements to ask about next.
    locate(op, winged, [&](QueryKind kind, int32_t element) {
        const auto answers = answer_query(kind, element, reps, winged);
        for (int r = 0; r < kRepresentationCount; ++r) reads[r] += static_cast<int64_t>(answers[r].entries_read);
        return answers[static_cast<int>(Representation::WingedEdge)].answer;
    });
    return reads;
}

int64_t winged_edit_reads(const Operation& op, const WingedEdgeMesh& winged) {
    int64_t reads = 0;
    locate(op, winged, [&](QueryKind kind, int32_t element) {
        const QueryAnswer a = winged_edge_answer(kind, element, winged);
        reads += static_cast<int64_t>(a.entries_read);
        return a.answer;
    });
    return reads;
}

int64_t playback_writes(const ChangeRecord& change) {
    int64_t writes = 0;
    for (const AssignmentStep& s : change.steps) writes += s.field != "firstCorner";
    const auto added = [&](int32_t v) {
        return std::any_of(change.added_vertices.begin(), change.added_vertices.end(), [v](Vertex a) { return a.idx == v; });
    };
    for (const PositionChange& p : change.positions)
        for (int k = 0; k < 3; ++k) writes += added(p.vertex) || p.before[k] != p.after[k];
    return writes;
}

EditCosts edit_costs(const std::array<int64_t, kRepresentationCount>& reads, const ChangeRecord& change,
                     const Representations& before_reps, const WingedEdgeMesh& after, const Representations& after_reps) {
    const auto differing = rewritten_entries(change, before_reps, after, after_reps);
    EditCosts out{};
    for (int r = 0; r < kRepresentationCount; ++r) out[r] = {reads[r], differing[r]};
    out[static_cast<int>(Representation::WingedEdge)].writes = playback_writes(change);
    return out;
}

EditCosts measure_edit(WingedEdgeMesh& winged, const Operation& op) {
    require_ok(winged.check(op));
    RepresentationCache cache;
    const auto reads = edit_reads(op, winged, cache.of(winged));
    const std::unique_ptr<Representations> before = cache.take(winged);
    const ChangeRecord change = winged.apply(op);
    return edit_costs(reads, change, *before, winged, cache.of(winged));
}

// ---------------------------------------------------------------- cost against mesh size

namespace {

std::vector<int32_t> choices_of(const WingedEdgeMesh& w, const char* query, int32_t element) {
    const std::string q = query;
    if (q == "vertices-of-face") return w.vertices_of_face(element);
    if (q == "vertices-around-vertex") return w.vertices_around_vertex(element);
    if (q == "edges-around-vertex") return w.edges_around_vertex(element);
    if (q == "edges-of-face") return w.edges_of_face(element);
    throw Error("unknown-query", "no choices query '" + q + "'");
}

} // namespace

Operation grid_operation(const OperationEntry& entry, const WingedEdgeMesh& grid, int32_t n) {
    cost_grids::require_even(n);
    Operation op{&entry, {kNone, kNone, kNone, kNone}};
    std::size_t chosen = 0;
    for (std::size_t k = 0; k < entry.arguments.size(); ++k) {
        const OperationArgument& a = entry.arguments[k];
        if (k == 0) {
            op.args[0] = cost_grids::middle(a.kind, grid, n);
        } else if (a.kind == ElementKind::None) {
            op.args[k] = 0.5;
        } else {
            const std::vector<int32_t> list = choices_of(grid, a.choices, static_cast<int32_t>(op.args[0]));
            op.args[k] = list.empty() ? kNone : list[std::min<std::size_t>(2 * chosen, list.size() - 1)];
            ++chosen;
        }
    }
    return op;
}

EditCosts measure_on_grid(const OperationEntry& entry, int32_t n) {
    cost_grids::require_even(n);
    WingedEdgeMesh w = WingedEdgeMesh::build(grid(n, n));
    return measure_edit(w, grid_operation(entry, w, n));
}

EditCostGrowth edit_cost_growth(const OperationEntry& entry, const std::vector<int32_t>& sizes) {
    using cost_grids::kCheck;
    std::array<EditCosts, 3> measured;
    for (std::size_t i = 0; i < cost_grids::kFit.size(); ++i) measured[i] = measure_on_grid(entry, cost_grids::kFit[i]);
    const auto evaluate = [&](int32_t n) {
        EditCosts c{};
        for (int r = 0; r < kRepresentationCount; ++r) {
            c[r].reads = cost_grids::quadratic_at({measured[0][r].reads, measured[1][r].reads, measured[2][r].reads}, n);
            c[r].writes = cost_grids::quadratic_at({measured[0][r].writes, measured[1][r].writes, measured[2][r].writes}, n);
        }
        return c;
    };
    if (!(evaluate(kCheck) == measure_on_grid(entry, kCheck)))
        throw Error("internal-error", std::string(entry.name) + ": the counts on a 32 x 32 grid differ from the quadratic through 8, 16 and 24");
    EditCostGrowth out;
    for (const int32_t n : sizes) {
        cost_grids::require_even(n);
        out.n.push_back(n);
        out.faces.push_back(2 * static_cast<int64_t>(n) * n);
        out.costs.push_back(evaluate(n));
    }
    return out;
}

} // namespace wingspline::mesh
