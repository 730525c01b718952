// libFuzzer target: validation and the winged-edge build on arbitrary indexed face sets
// (any face sizes, any indices including negative and out of range, duplicate and
// reversed faces, NaN coordinates). Properties:
//  * validate_indexed never throws;
//  * build succeeds exactly when the report has no error, and then the structure passes
//    its own invariant checker (validate()), every CCW ring and face loop is finite and
//    returns to its start, and the counts match the input;
//  * otherwise build throws InvalidMesh whose code is the report's first error.
#include "fuzz_checks.h"

#include <fuzzer/FuzzedDataProvider.h>

#include "wingspline/mesh/planes.h"
#include "wingspline/mesh/winged_edge.h"

#include <algorithm>
#include <cmath>

using namespace wingspline::mesh;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider in(data, size);
    IndexedMesh mesh;
    // Small meshes: the interesting topology (bow-ties, hinges, flips) needs few vertices,
    // and small index ranges make shared edges likely.
    const int32_t vertices = in.ConsumeIntegralInRange<int32_t>(0, 12);
    for (int32_t v = 0; v < vertices; ++v) {
        const bool odd = in.ConsumeBool() && in.ConsumeBool() && in.ConsumeBool();
        const double x = odd ? in.ConsumeFloatingPoint<double>() : in.ConsumeIntegralInRange<int>(-4, 4);
        mesh.add_vertex(x, in.ConsumeIntegralInRange<int>(-4, 4), in.ConsumeIntegralInRange<int>(-1, 1));
    }
    const int32_t faces = in.ConsumeIntegralInRange<int32_t>(0, 16);
    for (int32_t f = 0; f < faces && in.remaining_bytes() > 0; ++f) {
        const int32_t n = in.ConsumeIntegralInRange<int32_t>(0, 6);
        std::vector<int32_t> corners;
        for (int32_t i = 0; i < n; ++i) corners.push_back(in.ConsumeIntegralInRange<int32_t>(-1, vertices));
        mesh.add_face(corners.data(), n);
    }
    const ValidationReport report = validate_indexed(mesh);
    try {
        const WingedEdgeMesh w = WingedEdgeMesh::build(mesh);
        FUZZ_REQUIRE(report.ok());
        FUZZ_REQUIRE(w.validate().ok());
        FUZZ_REQUIRE(w.vertex_count() == mesh.vertex_count() && w.face_count() == mesh.face_count());
        for (int32_t v = 0; v < w.vertex_count(); ++v) {
            const auto ring = w.edges_around_vertex(v);
            FUZZ_REQUIRE(ring.size() <= static_cast<std::size_t>(w.edge_count()));
        }
        for (int32_t f = 0; f < w.face_count(); ++f) {
            FUZZ_REQUIRE(static_cast<int32_t>(w.edges_of_face(f).size()) == mesh.face_size(f));
        }
        // Unit normals or the zero vector, never NaN: validation refuses coordinates whose
        // Newell sums could overflow (coordinate-out-of-range, |x| > 1e100), which this
        // target once found with 1e200 (corpus: regression-huge-coordinates-nan-normal).
        std::vector<double> normals;
        newell_normals(w, normals);
        for (double x : normals) FUZZ_REQUIRE(std::isfinite(x));
    } catch (const InvalidMesh& e) {
        FUZZ_REQUIRE(!report.ok());
        FUZZ_REQUIRE(e.code() == report.first_error()->code);
    }
    return 0;
}
