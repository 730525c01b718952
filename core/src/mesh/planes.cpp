#include "wingspline/mesh/planes.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace wingspline::mesh {

glm::dvec3 newell_vector(const double* p, const int32_t* corners, int32_t n) {
    glm::dvec3 s(0.0);
    for (int32_t i = 0; i < n; ++i) {
        const double* a = p + 3 * corners[i];
        const double* b = p + 3 * corners[i + 1 == n ? 0 : i + 1];
        s.x += (a[2] + b[2]) * (a[1] - b[1]);
        s.y += (a[0] + b[0]) * (a[2] - b[2]);
        s.z += (a[1] + b[1]) * (a[0] - b[0]);
    }
    return 0.5 * s;
}

// The planes of one face from its corners c[0..n) (n >= 3).
static FacePlane plane_of(const WingedEdgeMesh& mesh, const int32_t* c, int32_t n) {
    const glm::dvec3 p1 = mesh.position(c[0]), p2 = mesh.position(c[1]), p3 = mesh.position(c[2]);
    const glm::dvec3 cross = glm::cross(p2 - p1, p3 - p1);
    const glm::dvec3 nn = newell_vector(mesh.positions().data(), c, n);
    glm::dvec3 centroid(0.0);
    for (int32_t i = 0; i < n; ++i) centroid += mesh.position(c[i]);
    centroid /= static_cast<double>(n);
    const double dn = -glm::dot(nn, centroid);
    double residual = 0;
    const double len = glm::length(nn);
    if (len > 0)
        for (int32_t i = 0; i < n; ++i) residual = std::max(residual, std::abs(glm::dot(nn, mesh.position(c[i])) + dn) / len);
    return {glm::dvec4(cross, -glm::dot(cross, p1)), {c[0], c[1], c[2]}, glm::dvec4(nn, dn), residual};
}

std::vector<FacePlane> face_planes(const WingedEdgeMesh& mesh, const std::vector<int32_t>& face_offsets,
                                   const std::vector<int32_t>& face_vertices) {
    require(face_offsets.size() == static_cast<std::size_t>(mesh.face_count()) + 1, "mismatched-face-set",
            "the face set has " + std::to_string(static_cast<long>(face_offsets.size()) - 1) + " faces but the mesh has " +
                std::to_string(mesh.face_count()));
    std::vector<FacePlane> out(mesh.face_count());
    for (int32_t f = 0; f < mesh.face_count(); ++f) {
        const int32_t* c = face_vertices.data() + face_offsets[f];
        const int32_t n = face_offsets[f + 1] - face_offsets[f];
        if (n == 0 && mesh.is_deleted(Face(f))) continue; // a gap left by an edit: a zero plane
        // The message is built only when it is needed (built for every face it cost most of
        // the time of planes() on a 100,000-face mesh, as the planes tab asks for).
        if (n < 3) require(false, "mismatched-face-set", "face " + face_label(f) + " of the face set has fewer than three corners");
        out[f] = plane_of(mesh, c, n);
    }
    return out;
}

std::vector<FacePlane> face_planes(const WingedEdgeMesh& mesh, int32_t first, int32_t count) {
    require(first >= 0 && count >= 0 && first <= mesh.face_count() - count, "invalid-element",
            "faces " + std::to_string(first + 1) + " to " + std::to_string(first + count) + " are not all faces of the mesh (it has " +
                std::to_string(mesh.face_count()) + ")");
    std::vector<FacePlane> out(count);
    for (int32_t k = 0; k < count; ++k) {
        const std::vector<int32_t> c = mesh.face_corners(first + k);
        if (c.size() >= 3) out[k] = plane_of(mesh, c.data(), static_cast<int32_t>(c.size())); // a gap: a zero plane
    }
    return out;
}

std::vector<FacePlane> face_planes(const WingedEdgeMesh& mesh) {
    const IndexedMesh faces = mesh.face_set();
    return face_planes(mesh, faces.face_offsets, faces.face_vertices);
}

void newell_normals(const WingedEdgeMesh& mesh, std::vector<double>& normals) {
    normals.resize(3 * static_cast<std::size_t>(mesh.face_count()));
    newell_normals(mesh, normals.data());
}

void newell_normals_reference(const WingedEdgeMesh& mesh, std::vector<double>& normals) {
    normals.assign(3 * static_cast<std::size_t>(mesh.face_count()), 0.0);
    for (int32_t f = 0; f < mesh.face_count(); ++f) {
        if (mesh.is_deleted(Face(f))) continue;
        const std::vector<int32_t> corners = mesh.vertices_of_face(f);
        const glm::dvec3 n = newell_vector(mesh.positions().data(), corners.data(), static_cast<int32_t>(corners.size()));
        const double len = glm::length(n);
        if (len > 0)
            for (int k = 0; k < 3; ++k) normals[3 * f + k] = n[k] / len;
    }
}

} // namespace wingspline::mesh
