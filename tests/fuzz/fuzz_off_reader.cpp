// libFuzzer target: the OFF reader on any bytes. Property: it returns an indexed mesh whose
// every face index is inside the vertex table, or throws ParseError with a line number
// inside the file; nothing else (no crash, no other exception, no out-of-bounds read).
#include "fuzz_checks.h"

#include "wingspline/mesh/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const auto mesh = wingspline::mesh::parse_off(text);
        fuzz_checks::check_indexed(mesh);
    } catch (const wingspline::mesh::ParseError& e) {
        fuzz_checks::check_parse_error(e, text);
    }
    return 0;
}
