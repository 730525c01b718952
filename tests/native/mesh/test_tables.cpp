// The table descriptors: every table's data is consistent with its description,
// and read only through the descriptors (a small reader below that knows no table), the
// lecture mesh gives lecture 000's tables entry for entry (the slide's text, copied from
// /work/shared/lectures/000_*.txt into the strings below) and lecture 001's edge list.
#include <catch2/catch.hpp>

#include "wingspline/mesh/generators.h"
#include "wingspline/mesh/tables.h"

#include <set>
#include <sstream>
#include <string>

using namespace wingspline::mesh;

namespace {

struct Built {
    WingedEdgeMesh winged;
    Representations reps;
};

Built build_all(const IndexedMesh& faces, const BuildOptions& options = {}) {
    WingedEdgeMesh w = WingedEdgeMesh::build(faces, options);
    REQUIRE(w.validate().ok());
    Representations reps = build_representations(faces, w);
    return {std::move(w), std::move(reps)};
}

std::vector<TableData> all_tables(const Built& b) {
    std::vector<TableData> out;
    for (int r = 0; r < kRepresentationCount; ++r) {
        auto some = representation_tables(static_cast<Representation>(r), &b.reps, b.winged);
        out.insert(out.end(), some.begin(), some.end());
    }
    return out;
}

const TableData& find(const std::vector<TableData>& tables, Representation r, const std::string& name) {
    for (const TableData& t : tables)
        if (t.descriptor->representation == r && name == t.descriptor->name) return t;
    FAIL("no table " << name);
    throw 0;
}

// The numbers of one cell, found from the descriptor alone.
std::vector<double> cell(const TableData& t, int32_t row, const std::string& column) {
    const TableDescriptor& d = *t.descriptor;
    const ColumnDescriptor* c = nullptr;
    for (const ColumnDescriptor& x : d.columns)
        if (column == x.name) c = &x;
    REQUIRE(c != nullptr);
    const auto index_of = [&](const std::string& name) { return &d.array(name) - d.arrays.data(); };
    const ArrayDescriptor& a = d.array(c->array);
    const ArrayData& data = t.arrays[index_of(c->array)];
    const auto number = [&](std::size_t i) { return data.f64 != nullptr ? data.f64[i] : static_cast<double>(data.i32[i]); };
    std::vector<double> out;
    if (a.role == ArrayRole::Rows) {
        for (int k = 0; k < c->width; ++k) out.push_back(number(static_cast<std::size_t>(a.stride) * row + c->first + k));
    } else {
        const ArrayData& off = t.arrays[index_of(a.offsets)];
        for (int32_t i = off.at(row) * a.stride; i < off.at(row + 1) * a.stride; ++i) out.push_back(number(i));
    }
    return out;
}

// A cell as the slide writes it: references as v1 / e1 / F1 ('' for none, as the slide's
// empty boundary cells), coordinates as (x, y, z), several items separated by spaces.
std::string slide_cell(const TableData& t, int32_t row, const std::string& column) {
    const ColumnDescriptor* c = nullptr;
    for (const ColumnDescriptor& x : t.descriptor->columns)
        if (column == x.name) c = &x;
    const std::vector<double> v = cell(t, row, column);
    std::ostringstream s;
    if (c->refers == ElementKind::None) {
        for (std::size_t i = 0; i < v.size(); i += c->width) {
            if (i) s << ' ';
            if (c->width == 1) { s << v[i]; continue; }
            s << '(';
            for (int k = 0; k < c->width; ++k) s << (k ? ", " : "") << v[i + k];
            s << ')';
        }
        return s.str();
    }
    const char* letter = c->refers == ElementKind::Vertex ? "v" : c->refers == ElementKind::Edge ? "e" : "F";
    bool first = true;
    for (double x : v) {
        if (x < 0) continue;
        s << (first ? "" : " ") << letter << static_cast<int>(x) + 1;
        first = false;
    }
    return s.str();
}

// One row of a table, every column as slide_cell, joined by '|'.
std::string slide_row(const TableData& t, int32_t row) {
    std::string out;
    for (const ColumnDescriptor& c : t.descriptor->columns) out += (out.empty() ? "" : "|") + slide_cell(t, row, c.name);
    return out;
}

} // namespace

TEST_CASE("tables: every descriptor names its arrays, and column names are unique", "[mesh][tables]") {
    std::set<std::string> seen;
    for (const TableDescriptor& d : table_descriptors()) {
        const std::string id = std::string(representation_key(d.representation)) + "/" + d.name;
        INFO(id);
        CHECK(seen.insert(id).second);
        std::set<std::string> names;
        for (const ColumnDescriptor& c : d.columns) {
            CHECK(names.insert(c.name).second);
            CHECK_NOTHROW(d.array(c.array));
            CHECK(d.array(c.array).role != ArrayRole::Offsets);
        }
        for (const ArrayDescriptor& a : d.arrays)
            if (a.role == ArrayRole::List) CHECK(d.array(a.offsets).role == ArrayRole::Offsets);
    }
    // Six representations: 3 + 1 + 2 + 3 + 3 + 3 tables.
    CHECK(seen.size() == 15);
}

TEST_CASE("tables: stride x rows and CSR offsets agree with the data on every mesh", "[mesh][tables]") {
    const NamedMesh lecture = lecture_example();
    const NamedMesh foley = foley_example();
    const std::vector<std::pair<std::string, Built>> meshes = [&] {
        std::vector<std::pair<std::string, Built>> m;
        m.emplace_back("lecture", build_all(lecture.mesh, lecture.options));
        m.emplace_back("foley", build_all(foley.mesh, foley.options));
        m.emplace_back("tetrahedron", build_all(tetrahedron()));
        m.emplace_back("cube", build_all(cube()));
        m.emplace_back("fan", build_all(open_fan(5)));
        m.emplace_back("grid", build_all(grid(7, 4)));
        m.emplace_back("sphere", build_all(uv_sphere(9, 6)));
        return m;
    }();
    for (const auto& [name, b] : meshes) {
        INFO(name);
        const std::vector<TableData> tables = all_tables(b);
        REQUIRE(tables.size() == table_descriptors().size());
        for (const TableData& t : tables) {
            const auto problems = table_layout_problems(t, b.winged.vertex_count(), b.winged.edge_count(), b.winged.face_count());
            INFO(representation_key(t.descriptor->representation) << "/" << t.descriptor->name << ": " << (problems.empty() ? "" : problems.front()));
            CHECK(problems.empty());
        }
        // The CSR lists of one table with shared offsets have as many items per row as the
        // element has corners or neighbours: FV, FE, FF of face f all have |f| items.
        const TableData& faces = find(tables, Representation::AdjacencyLists, "faces");
        for (int32_t f = 0; f < faces.rows; ++f) {
            const auto n = b.winged.edges_of_face(f).size();
            CHECK(cell(faces, f, "vertices").size() == n);
            CHECK(cell(faces, f, "edges").size() == n);
            CHECK(cell(faces, f, "faces").size() == n);
        }
    }
}

TEST_CASE("tables: the layout check fails on data that breaks its descriptor", "[mesh][tables]") {
    const NamedMesh lecture = lecture_example();
    const Built b = build_all(lecture.mesh, lecture.options);
    std::vector<TableData> tables = all_tables(b);
    TableData edges = find(tables, Representation::WingedEdge, "edges");
    edges.arrays[0].size -= 1; // one number short of 8 per edge
    CHECK_FALSE(table_layout_problems(edges, 5, 7, 3).empty());
    TableData faces = find(tables, Representation::VertexFaceTables, "faces");
    // A face vertex the offsets do not cover (a real, longer array: the check may read it all).
    std::vector<int32_t> longer(faces.arrays[1].i32, faces.arrays[1].i32 + faces.arrays[1].size);
    longer.push_back(0);
    faces.arrays[1].i32 = longer.data();
    faces.arrays[1].size = longer.size();
    CHECK_FALSE(table_layout_problems(faces, 5, 7, 3).empty());
    const TableData& we = find(tables, Representation::WingedEdge, "edges");
    CHECK_FALSE(table_layout_problems(we, 5, 6, 3).empty()); // e7 names an edge out of range
    CHECK(table_layout_problems(we, 5, 7, 3).empty());
}

TEST_CASE("tables: the lecture mesh read through the descriptors is lecture 000's slide", "[mesh][tables]") {
    const NamedMesh lecture = lecture_example();
    const Built b = build_all(lecture.mesh, lecture.options);
    const std::vector<TableData> tables = all_tables(b);

    // "Winged Edge", EDGE TABLE: S E L R, then L R under S and L R under E (the wings).
    const TableData& edges = find(tables, Representation::WingedEdge, "edges");
    std::vector<std::string> head;
    for (const ColumnDescriptor& c : edges.descriptor->columns) head.push_back(std::string(c.group) + (*c.group ? ":" : "") + c.label);
    CHECK(head == std::vector<std::string>{"S", "E", "L", "R", "S:L", "S:R", "E:L", "E:R"});
    const std::vector<std::string> slide_edges = {
        "v1|v3||F1|e2|e2|e4|e3", "v1|v2|F1||e1|e1|e3|e6", "v2|v3|F1|F2|e2|e5|e1|e4", "v3|v4||F2|e1|e3|e7|e5",
        "v2|v4|F2|F3|e3|e6|e4|e7", "v2|v5|F3||e5|e2|e7|e7", "v4|v5||F3|e4|e5|e6|e6",
    };
    REQUIRE(edges.rows == 7);
    for (int32_t e = 0; e < 7; ++e) CHECK(slide_row(edges, e) == slide_edges[e]);
    CHECK(edges.descriptor->rows == ElementKind::Edge);

    // VERTEX TABLE: x y z and the edge e1 e6 e3 e5 e6 (lecture_example's positions, as
    // generators.h states them: (0,1) (1,0) (1,2) (2,1) (2,-1), z = 0).
    const TableData& vertices = find(tables, Representation::WingedEdge, "vertices");
    const std::vector<std::string> slide_vertices = {"0|1|0|e1", "1|0|0|e6", "1|2|0|e3", "2|1|0|e5", "2|-1|0|e6"};
    REQUIRE(vertices.rows == 5);
    for (int32_t v = 0; v < 5; ++v) CHECK(slide_row(vertices, v) == slide_vertices[v]);
    // FACE TABLE: F1 e1, F2 e3, F3 e5.
    const TableData& faces = find(tables, Representation::WingedEdge, "faces");
    REQUIRE(faces.rows == 3);
    CHECK(slide_row(faces, 0) == "e1");
    CHECK(slide_row(faces, 1) == "e3");
    CHECK(slide_row(faces, 2) == "e5");

    // "Vertex and Face Tables": F1 V1 V2 V3, F2 V2 V4 V3, F3 V2 V5 V4; vertex table X Y Z.
    const TableData& vf = find(tables, Representation::VertexFaceTables, "faces");
    CHECK(slide_row(vf, 0) == "v1 v2 v3");
    CHECK(slide_row(vf, 1) == "v2 v4 v3");
    CHECK(slide_row(vf, 2) == "v2 v5 v4");
    const TableData& vv = find(tables, Representation::VertexFaceTables, "vertices");
    CHECK(vv.descriptor->columns.size() == 3);
    CHECK(std::string(vv.descriptor->columns[0].label) == "X");
    CHECK(slide_row(vv, 4) == "2|-1|0");

    // "Independent Faces": F1 (x1)(x2)(x3), F2 (x2)(x4)(x3), F3 (x2)(x5)(x4).
    const TableData& ind = find(tables, Representation::IndependentFaces, "faces");
    CHECK(slide_row(ind, 0) == "(0, 1, 0) (1, 0, 0) (1, 2, 0)");
    CHECK(slide_row(ind, 1) == "(1, 0, 0) (2, 1, 0) (1, 2, 0)");
    CHECK(slide_row(ind, 2) == "(1, 0, 0) (2, -1, 0) (2, 1, 0)");

    // The adjacency lists of v2 (counted on the slide's picture): edges e2 e3 e5 e6, faces F1 F2 F3.
    const TableData& adj = find(tables, Representation::AdjacencyLists, "vertices");
    CHECK(slide_cell(adj, 1, "edges") == "e2 e3 e5 e6");
    CHECK(slide_cell(adj, 1, "faces") == "F1 F2 F3");
    const TableData& adjEdges = find(tables, Representation::AdjacencyLists, "edges");
    CHECK(slide_cell(adjEdges, 2, "vertices") == "v2 v3"); // e3 = (S, E) = (v2, v3)
    CHECK(slide_cell(adjEdges, 2, "faces") == "F1 F2");    // L = F1, R = F2
}

TEST_CASE("tables: Foley's edge list (lecture 001) through the descriptors", "[mesh][tables]") {
    const NamedMesh foley = foley_example();
    const Built b = build_all(foley.mesh, foley.options);
    const std::vector<TableData> tables = all_tables(b);
    // E1 = (V1, V2, P1, λ) ... E4 = (V4, V2, P1, P2), E5 = (V4, V1, P1, λ); written v/F here.
    const TableData& edges = find(tables, Representation::EdgeList, "edges");
    const std::vector<std::string> expected = {"v1|v2|F1|", "v2|v3|F2|", "v3|v4|F2|", "v4|v2|F1|F2", "v4|v1|F1|"};
    REQUIRE(edges.rows == 5);
    for (int32_t e = 0; e < 5; ++e) CHECK(slide_row(edges, e) == expected[e]);
    const TableData& polygons = find(tables, Representation::EdgeList, "polygons");
    CHECK(slide_row(polygons, 0) == "e1 e4 e5"); // P1 = (E1, E4, E5)
    CHECK(slide_row(polygons, 1) == "e2 e3 e4"); // P2 = (E2, E3, E4)
}

TEST_CASE("tables: the other representations are asked for before they exist", "[mesh][tables]") {
    const WingedEdgeMesh w = WingedEdgeMesh::build(cube());
    CHECK(representation_tables(Representation::WingedEdge, nullptr, w).size() == 3);
    CHECK_THROWS_AS(representation_tables(Representation::EdgeList, nullptr, w), wingspline::Error);
}
