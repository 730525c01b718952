#pragma once
// The mesh limits, one set: the core enforces them where a value enters (reading
// a file, building, moving a vertex) and the JS API exposes them (api.meshLimits), so the
// page and the state format read these numbers instead of copying them.
#include <cstdint>
#include <limits>

namespace wingspline::mesh {

// The largest coordinate magnitude a mesh may have (build, import, setVertexPosition:
// code coordinate-out-of-range beyond it). It is the state format's bound on any number
// (docs/state-format.md, |x| <= 1e9), so a mesh the page accepts is one it can reload; and
// squares and pair products (<= 1e18) stay far from overflow in every plane and normal
// computation, where the former bound of 1e100 was only the overflow margin.
inline constexpr double kMaxCoordinate = 1e9;

// The most corners one face may have, wherever a face comes from: a file (parse_off /
// parse_obj), a face set (build, validate_indexed) or an edit (join-faces, split-edge), all
// refused with code face-too-large. One limit, so a mesh the page holds is one its own
// export can be read back from (web/js/app/limits.js repeats it for the state format).
inline constexpr int32_t kMaxFaceCorners = 1000;

// What a mesh file may hold (parse_off / parse_obj; the state format keeps the same).
struct MeshLimits {
    double max_coordinate; // |x|, |y|, |z|; finite values beyond it: coordinate-out-of-range
    int32_t max_vertices;  // vertices of the file: too-large
    int32_t max_faces;     // faces of the file: too-large
};

// The page's import limits: 2,000,000 vertices and faces (the reason below); edits keep a mesh within
// them (too-large), so its export can be imported again.
// The largest mesh a school laptop (4 GB RAM, the wasm heap at most 2 GB) holds through the
// whole import pipeline, about 600 bytes per face at its peak (docs/api-mesh.md, "Import
// limits and memory"): 2M faces peak near 1.2 GB, in a worker that gives it back.
inline constexpr MeshLimits kFileLimits{kMaxCoordinate, 2000000, 2000000};
// What subdivision may produce (api.subdivide, subdivisionSteps): 200,000 vertices and faces,
// the former import limit. A level is a chain of phases, masks and tables the subdivision
// lesson shows interactively; the import limit was raised for viewing big meshes, not this.
inline constexpr MeshLimits kSubdivisionLimits{kMaxCoordinate, 200000, 200000};
// The same with the element counts lifted (benchmarks and large-file tests): coordinates
// are still limited (and corners per face always are, kMaxFaceCorners).
inline constexpr MeshLimits kUnlimitedCounts{kMaxCoordinate, std::numeric_limits<int32_t>::max(),
                                             std::numeric_limits<int32_t>::max()};

} // namespace wingspline::mesh
