#pragma once
// Basis matrices of the cubic families, exactly as on the slides (lectures 000, 002, 003):
//   P(u) = [u^3 u^2 u 1] . M . G        (000, 003, 004: row-vector convention)
//   Q(t) = G . M^T . T,  T = [t^3 t^2 t 1]^T  (001: the same matrix, transposed)
// Matrices are row-major: m[4*row + col].
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace wingspline::curves {

using Mat4 = std::array<double, 16>;

enum class BasisKind { Hermite, Bezier, BSpline, CatmullRom };

// Parses 'hermite' | 'bezier' | 'bspline' | 'catmull-rom'; throws Error("unknown-basis").
BasisKind parse_basis_kind(const std::string& name);
const char* basis_kind_name(BasisKind kind);

// The slide's matrix for P(u) = [u^3 u^2 u 1] M G.
Mat4 basis_matrix(BasisKind kind);

// The cardinal spline with tension c (Catmull-Rom is c = 0): the tangents are
// (1-c)(P_i+1 - P_i-1)/2, so with s = (1-c)/2 the matrix for G = [P_i-1 P_i P_i+1 P_i+2] is
//   [-s 2-s s-2 s; 2s s-3 3-2s -s; -s 0 s 0; 0 1 0 0]   (s = 1/2 gives lecture 003's M_CR).
Mat4 cardinal_matrix(double tension);

// Lecture 000, Hermite derivation: the rows [u^3 u^2 u 1] at u = 0 and u = 1 and their
// derivatives [3u^2 2u 1 0] at u = 0 and u = 1. M_Hermite is the inverse of this matrix.
Mat4 hermite_constraint_matrix();

// The lectures' notation: a matrix as the slides write it, one fraction in front
// of integers, values[i] = numerators[i] / denominator (1/6 [...] for the uniform B-spline,
// 1/2 [...] for Catmull-Rom). The denominator is the smallest one up to max_denominator
// for which every entry times it is an integer within kRationalTolerance relative to
// max(1, |entry| * denominator) (unitless: matrix entries carry no unit); nullopt when there
// is none (an irrational or non-finite entry, a non-uniform knot vector's matrix).
struct RationalForm {
    long long denominator = 1;
    std::vector<long long> numerators;
};
constexpr double kRationalTolerance = 1e-9;
constexpr int kMaxNotationDenominator = 1000;
std::optional<RationalForm> rational_form(const std::vector<double>& values,
                                          int max_denominator = kMaxNotationDenominator);

// The three ways the lectures write a basis matrix M of P(u) = [u^p .. u 1] M G.
//   Descending (000, 003, 004): M itself, rows multiply u^p .. u 1.
//   Ascending  (002): p(u) = u^T C, u = (1, u, .., u^p), C = M g: M's rows in reverse order.
//   Transposed (001): Q(t) = G M T, T = [t^p .. t 1]^T a column: M^T.
enum class MatrixForm { Descending, Ascending, Transposed };
// Parses 'descending' | 'ascending' | 'transposed'; throws Error("unknown-form").
MatrixForm parse_matrix_form(const std::string& name);
const char* matrix_form_name(MatrixForm form);
// A rows x cols row-major matrix of the descending form (M, or the coefficients C = M G)
// written in `form`: rows reversed (ascending) or transposed (cols x rows). Throws
// Error("invalid-argument") when values.size() != rows * cols.
std::vector<double> matrix_in_form(const std::vector<double>& values, int rows, int cols, MatrixForm form);
// The slide's matrix in `form` (lecture 002's M_H, M_B, M_s; lecture 001's M_H, M_B).
Mat4 basis_matrix(BasisKind kind, MatrixForm form);

Mat4 multiply(const Mat4& a, const Mat4& b);
Mat4 transpose(const Mat4& m);
// Throws Error("singular-matrix") when the matrix has no inverse.
Mat4 inverse(const Mat4& m);

} // namespace wingspline::curves
