// The mesh operations' registry (operations.h) as data: read by the mesh lesson's edit panel
// and by the edit exercise's checker, so this file is linked into the modules that edit
// meshes and the exercises module (CMakeLists.txt, WINGSPLINE_BINDINGS_operations). Not
// into the subdivision lesson's: the registry holds every operation's check and change, and
// a module that names it carries them all. How a change record's steps cross (the tables and
// fields they index) is mesh_representations.cpp's meshChangeFormat, in every mesh module.
#include "boundary.h"

#include "wingspline/mesh/edit_costs.h"
#include "wingspline/mesh/operations.h"

namespace wingspline::bindings {
namespace {

using namespace wingspline::mesh;

// Read once by mesh-api.js: {operations: [{name, title, counts, shortcut, describe, finds
// (what it must find before it writes, edit_costs.h),
// arguments: [{name, kind (null for a number), optional, default, choices, label}]}]}: the
// registry (operations.h) as data.
val mesh_operation_descriptors() {
    return guarded([] {
        val ops = val::array();
        const auto& all = operations();
        for (std::size_t k = 0; k < all.size(); ++k) {
            val args = val::array();
            for (std::size_t j = 0; j < all[k].arguments.size(); ++j) {
                const OperationArgument& a = all[k].arguments[j];
                val one = val::object();
                one.set("name", std::string(a.name));
                one.set("kind", a.kind == ElementKind::None ? val::null() : val(std::string(element_kind_name(a.kind))));
                one.set("optional", a.optional);
                one.set("default", a.default_value);
                one.set("choices", a.choices == nullptr ? val::null() : val(std::string(a.choices)));
                one.set("label", std::string(a.label));
                args.set(j, one);
            }
            val op = val::object();
            op.set("name", std::string(all[k].name));
            op.set("title", std::string(all[k].title));
            op.set("counts", std::string(all[k].counts));
            op.set("shortcut", std::string(all[k].shortcut));
            op.set("describe", std::string(all[k].describe));
            op.set("finds", std::string(locate_description(all[k].locate)));
            op.set("arguments", args);
            ops.set(k, op);
        }
        val r = val::object();
        r.set("operations", ops);
        return r;
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_operations) {
    using namespace wingspline::bindings;
    emscripten::function("meshOperationDescriptors", &mesh_operation_descriptors);
}
