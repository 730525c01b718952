#pragma once
// The one generic binding of the mesh tables: any described table (tables.h)
// becomes a plain JS value, so no table is written out field by field here or in JS.
#include "boundary.h"

#include "wingspline/mesh/tables.h"

#include <vector>

namespace wingspline::bindings {

// Rows [first, first + rows) of each table (cut at its end):
// [{representation, name, rows (the table's full row count), first, arrays: {name: TypedArray}}].
// A rows array gives stride numbers per row, an offsets array its (rows + 1) absolute
// offsets, a list the items those offsets cover (so item k of the window is list
// entry k - offsets[0], times the item width).
val tables_value(const std::vector<mesh::TableData>& tables, int32_t first, int32_t rows);

// Which representation a JS key names; throws Error("unknown-representation").
mesh::Representation representation_named(const std::string& key);

} // namespace wingspline::bindings
