#pragma once
// Every polynomial piece of a curve in the matrix form of the lectures:
//   P(u) = [u^p ... u 1] . M . G          (lectures 000, 003, 004; C = M G)
//   Q(t) = G^T . M^T . [t^p ... t 1]^T    (lecture 001 writes G as a row of points and the
//                                          transposed matrix; the same numbers)
// For the cubic families M is exactly the slide's matrix (basis_matrix.h), the very matrix
// the evaluator multiplies with.
#include "wingspline/curves/basis_matrix.h"
#include "wingspline/curves/curve.h"

#include <string>
#include <vector>

namespace wingspline::curves {

struct SegmentMatrices {
    int segment = 0;
    int segment_count = 1;
    int degree = 3;
    int columns = 2;                   // columns of G and C: dim (dim+1 when homogeneous)
    std::vector<double> M;             // (p+1)x(p+1) row-major, rows multiply u^p .. 1
    std::vector<double> G;             // (p+1) x columns: G[columns*r + k]
    std::vector<double> C;             // M G: row r holds the coefficient of u^(p-r)
    std::vector<int> control_indices;  // which point (or tangent) each row of G is
    std::vector<std::string> labels;   // the slide's names of the rows, e.g. "p_k", "t_k+1"
    double start = 0, end = 1;         // the segment's range of the curve parameter
    // true: u = (t - start)/(end - start) in [0,1]; false (interpolation): u is t itself.
    bool local_parameter = true;
    bool homogeneous = false;          // rational curves: G holds (w x, w y, [w z,] w)
    std::string basis;                 // "hermite", "bezier", "bspline", "catmull-rom", ...
};

int segment_count(const Curve& curve);
// The index of the polynomial segment that holds the parameter t (segment_matrices numbers
// them): B-splines and NURBS count the non-empty knot spans t_l <= t < t_l+1 from l = p;
// the other families split their domain into segment_count equal parts [i, i+1). The end of
// the domain belongs to the last segment (the left-sided rule of the evaluator). Refuses t
// outside the domain ('parameter-out-of-range') and a non-finite t ('non-finite-input').
int segment_at(const Curve& curve, double t);
// Throws 'segment-out-of-range' naming the valid indices.
SegmentMatrices segment_matrices(const Curve& curve, int segment);

// A segment's M, G and C as a lecture writes them (basis_matrix.h, MatrixForm):
// descending M, G, C as above; ascending (002) M and C with their rows reversed, G as is
// (p(u) = u^T C, C = M g); transposed (001) M^T, G^T (a row of points) and C^T = G^T M^T.
struct SegmentForm {
    MatrixForm form = MatrixForm::Descending;
    std::vector<double> M, G, C;  // row-major, sizes below
    int m_size = 4;               // M is m_size x m_size
    int g_rows = 4, g_cols = 2;   // G and C have the same shape
};
SegmentForm segment_in_form(const SegmentMatrices& s, MatrixForm form);

// Lecture 002, basis conversion: the geometry q in basis `to` that gives the same cubic as
// P in basis `from`: q = M_to^-1 M_from P. P and q are 4 x dim, flat.
std::vector<double> convert_basis(const std::vector<double>& G, int dim, BasisKind from, BasisKind to);

} // namespace wingspline::curves
