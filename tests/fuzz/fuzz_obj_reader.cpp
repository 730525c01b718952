// libFuzzer target: the OBJ reader on any bytes (v, f with i, i/t, i//n, i/t/n, negative
// indices, comments). Property as for OFF: a mesh with in-range indices, or a ParseError
// naming a line of the file.
#include "fuzz_checks.h"

#include "wingspline/mesh/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const auto mesh = wingspline::mesh::parse_obj(text);
        fuzz_checks::check_indexed(mesh);
    } catch (const wingspline::mesh::ParseError& e) {
        fuzz_checks::check_parse_error(e, text);
    }
    return 0;
}
