// Changing a mesh: every operation of the core's registry through one binding (meshEdit), its
// change record as flat arrays, undo of the newest edits, the cost of an edit against mesh
// size, and compact(). The
// binding group `edit`, in the mesh lesson's module and not the subdivision lesson's, which
// never edits (docs/architecture.md, "Module size"). The registry itself as data is
// operations.cpp; the version and the gaps, which every mesh has, are mesh_representations.cpp.
#include "boundary.h"
#include "mesh_access.h"
#include "mesh_entry.h"

#include "wingspline/mesh/edit_costs.h"
#include "wingspline/mesh/half_edge.h"
#include "wingspline/mesh/queries.h"
#include "wingspline/mesh/operations.h"
#include "wingspline/mesh/representations.h"
#include "wingspline/mesh/tables.h"
#include "wingspline/mesh/winged_edge.h"

#include <memory>

namespace wingspline::bindings {

namespace {

using namespace wingspline::mesh;

// Keeps the half-edge view in step with `change` when it showed the state the change started
// from (O(the change)); otherwise it stays stale and is made again when next asked for.
// What it changed there is kept for meshHalfEdge's "change" (mesh_entry.h).
void follow_half_edge(MeshEntry& me, const ChangeRecord& change) {
    HalfEdgeChange& kept = me.half_edge_change;
    kept.entries.clear();
    kept.winged_assignments = 0;
    for (const AssignmentStep& s : change.steps) kept.winged_assignments += s.field != "firstCorner";
    const bool current = me.half_edge && me.half_edge_topology == change.before.topology;
    kept.followed = current || !change.changed();
    if (!current || !change.changed()) return;
    me.half_edge->update(me.winged, change, &kept.entries);
    me.half_edge_topology = me.winged.version().topology;
}

val element_list(const std::vector<Vertex>& vs, const std::vector<Edge>& es, const std::vector<Face>& fs) {
    const auto ints = [](const auto& hs) {
        std::vector<int32_t> out;
        for (const auto& h : hs) out.push_back(h.idx);
        return int_array(out);
    };
    val r = val::object();
    r.set("vertices", ints(vs));
    r.set("edges", ints(es));
    r.set("faces", ints(fs));
    return r;
}

// {op, added, removed: {vertices, edges, faces}, rows: [{table, row, fields: [{field,
// before, after}]}], before, after: {topology, geometry}}
val change_value(const ChangeRecord& c) {
    val rows = val::array();
    for (std::size_t i = 0; i < c.rows.size(); ++i) {
        val fields = val::array();
        for (std::size_t k = 0; k < c.rows[i].fields.size(); ++k) {
            val field = val::object();
            field.set("field", c.rows[i].fields[k].field);
            field.set("before", c.rows[i].fields[k].before);
            field.set("after", c.rows[i].fields[k].after);
            fields.set(k, field);
        }
        val row = val::object();
        row.set("table", std::string(table_name(c.rows[i].table)));
        row.set("row", c.rows[i].row);
        row.set("fields", fields);
        rows.set(i, row);
    }
    // Euler operations: every assignment in order, six int32 per step [table, row, field,
    // before, after, phase] (indices into meshOperationDescriptors().tables / .fields, and
    // into this record's phases), and the positions set, eight numbers each [vertex, before
    // xyz, after xyz, step].
    val phases = val::array();
    for (std::size_t k = 0; k < c.phases.size(); ++k) phases.set(k, c.phases[k]);
    std::vector<double> positions;
    for (const PositionChange& p : c.positions)
        positions.insert(positions.end(), {static_cast<double>(p.vertex), p.before.x, p.before.y, p.before.z, p.after.x, p.after.y,
                                           p.after.z, static_cast<double>(p.step)});
    val r = val::object();
    r.set("op", c.op);
    r.set("steps", assignment_steps_array(c.steps));
    r.set("phases", phases);
    r.set("positions", to_typed_array(positions));
    r.set("added", element_list(c.added_vertices, c.added_edges, c.added_faces));
    r.set("removed", element_list(c.removed_vertices, c.removed_edges, c.removed_faces));
    r.set("rows", rows);
    r.set("before", version_value(c.before));
    r.set("after", version_value(c.after));
    return r;
}

// {[representation]: {reads, writes}}
val cost_value(const EditCost& cost) {
    val one = val::object();
    one.set("reads", static_cast<double>(cost.reads));
    one.set("writes", static_cast<double>(cost.writes));
    return one;
}

val costs_value(const EditCosts& costs) {
    val out = val::object();
    for (int k = 0; k < kRepresentationCount; ++k) out.set(representation_key(static_cast<Representation>(k)), cost_value(costs[k]));
    return out;
}

// {sizes: [{n, faces}], reads: [{[key]: entries}]}: a query's reads against mesh size
// (queries.h, query_cost_growth), on grids of n x n quads for each n in `sizes`.
val mesh_query_cost_growth(const std::string& kind, const val& sizes) {
    return guarded([&] {
        const QueryKind k = query_kind(kind);
        std::vector<int32_t> n;
        for (const double x : to_doubles(sizes)) n.push_back(static_cast<int32_t>(x));
        const QueryCostGrowth g = query_cost_growth(k, n);
        val list = val::array();
        val reads = val::array();
        for (std::size_t i = 0; i < g.n.size(); ++i) {
            val size = val::object();
            size.set("n", g.n[i]);
            size.set("faces", static_cast<double>(g.faces[i]));
            list.set(i, size);
            val one = val::object();
            for (int r = 0; r < kRepresentationCount; ++r)
                one.set(representation_key(static_cast<Representation>(r)), static_cast<double>(g.reads[i][r]));
            one.set("half-edge", static_cast<double>(g.half_edge_reads[i]));
            reads.set(i, one);
        }
        val out = val::object();
        out.set("sizes", list);
        out.set("reads", reads);
        return out;
    });
}

// The operation `name` on grids of n x n quads, one per size (edit_cost_growth):
// {sizes: [{n, faces}], costs: [{[representation]: {reads, writes}}]}.
val mesh_edit_cost_growth(const std::string& name, const val& sizes) {
    return guarded([&] {
        const OperationEntry* entry = find_operation(name);
        if (entry == nullptr) throw Error("unknown-operation", "unknown mesh operation '" + name.substr(0, 40) + "'");
        std::vector<int32_t> n;
        for (const double x : to_doubles(sizes)) n.push_back(static_cast<int32_t>(x));
        const EditCostGrowth g = edit_cost_growth(*entry, n);
        val out = val::object();
        val list = val::array();
        val costs = val::array();
        for (std::size_t i = 0; i < g.n.size(); ++i) {
            val size = val::object();
            size.set("n", g.n[i]);
            size.set("faces", static_cast<double>(g.faces[i]));
            list.set(i, size);
            costs.set(i, costs_value(g.costs[i]));
        }
        out.set("sizes", list);
        out.set("costs", costs);
        return out;
    });
}

// Any operation of the registry (operations.h) by name, its arguments in the entry's order.
// check = true only asks the check ({allowed, code, message}, nothing changed); otherwise
// runs the operation and returns its change record, or the refusal as {ok: false, code,
// message} with the mesh unchanged. cost: also say what the edit cost each representation
// (edit_costs.h: the entries read to find what to change, counted before the change, and the
// entries written: the winged edge's from the change record, the others by comparing their
// derivations before and after, which the cache hands over rather than copies; the lesson
// asks it only for the edit a person just made).
// cost: 0 none; 1 every representation (the others derived before and after: O(mesh));
// 2 the winged edge alone (reads from its queries, writes from the record: O(the edit)).
val mesh_edit(int32_t handle, const std::string& name, const val& args, bool check, int32_t cost) {
    return guarded([&] {
        MeshEntry& me = entry(handle);
        WingedEdgeMesh& w = me.winged;
        const std::vector<double> a = to_doubles(args);
        const Operation op = operation_from(name, a.data(), a.size());
        if (check) {
            const CheckResult verdict = w.check(op);
            val r = val::object();
            r.set("allowed", verdict.ok);
            r.set("code", verdict.code);
            r.set("message", verdict.message);
            return r;
        }
        require(cost >= 0 && cost <= 2, "invalid-argument", "cost must be 0 (none), 1 (every representation) or 2 (the winged edge)");
        std::unique_ptr<Representations> before_reps;
        std::array<int64_t, kRepresentationCount> reads{};
        int64_t winged_reads = -1;
        if (cost == 1 && w.check(op).ok) {
            reads = edit_reads(op, w, me.representations.of(w));
            before_reps = me.representations.take(w);
        }
        if (cost == 2 && w.check(op).ok) winged_reads = winged_edit_reads(op, w);
        ChangeRecord c = w.apply(op);
        follow_half_edge(me, c);
        val r = change_value(c);
        if (before_reps) r.set("costs", costs_value(edit_costs(reads, c, *before_reps, w, me.representations.of(w))));
        if (winged_reads >= 0) {
            val costs = val::object();
            costs.set(representation_key(Representation::WingedEdge), cost_value({winged_reads, playback_writes(c)}));
            r.set("costs", costs);
        }
        if (c.changed()) {
            if (me.undoable.size() == kUndoRecords) me.undoable.clear(); // older edits: undone by building again
            me.undoable.push_back(std::make_unique<ChangeRecord>(std::move(c)));
        }
        return r;
    });
}

// Takes back the newest edit meshEdit made (WingedEdgeMesh::undo) and returns the undo's
// record, shaped as meshEdit's; refuses "cannot-undo" (nothing changed) when there is none
// or something else changed the mesh since.
val mesh_undo(int32_t handle) {
    return guarded([&] {
        MeshEntry& me = entry(handle);
        if (me.undoable.empty()) throw Error("cannot-undo", "there is no edit to take back: the mesh is as it was built (or compacted)");
        const ChangeRecord u = me.winged.undo(*me.undoable.back());
        me.undoable.pop_back();
        follow_half_edge(me, u);
        return change_value(u);
    });
}

// {renumbering: {vertices, edges, faces} (old -> new, -1 = removed), version}
val mesh_compact(int32_t handle) {
    return guarded([&] {
        MeshEntry& me = entry(handle);
        WingedEdgeMesh& w = me.winged;
        me.undoable.clear(); // every number moved: no record names the mesh's rows any more
        const Renumbering map = w.compact();
        val renumbering = val::object();
        renumbering.set("vertices", int_array(map.vertices));
        renumbering.set("edges", int_array(map.edges));
        renumbering.set("faces", int_array(map.faces));
        val r = val::object();
        r.set("renumbering", renumbering);
        r.set("version", version_value(w.version()));
        return r;
    });
}



} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_mesh_edit) {
    using namespace wingspline::bindings;
    emscripten::function("meshEdit", &mesh_edit);
    emscripten::function("meshEditCostGrowth", &mesh_edit_cost_growth);
    emscripten::function("meshQueryCostGrowth", &mesh_query_cost_growth);
    emscripten::function("meshCompact", &mesh_compact);
    emscripten::function("meshUndo", &mesh_undo);
}
