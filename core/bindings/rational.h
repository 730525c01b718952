#pragma once
// The lectures' notation: a matrix's rational form (basis_matrix.h) for JS as
// {denominator, numerators: Float64Array of integers}, or null when the matrix has none.
#include "boundary.h"

#include "wingspline/curves/basis_matrix.h"

#include <vector>

namespace wingspline::bindings {

inline val rational_value(const std::vector<double>& values) {
    const auto form = curves::rational_form(values);
    if (!form) return val::null();
    std::vector<double> numerators(form->numerators.begin(), form->numerators.end());
    val r = val::object();
    r.set("denominator", static_cast<double>(form->denominator));
    r.set("numerators", to_typed_array(numerators));
    return r;
}

} // namespace wingspline::bindings
