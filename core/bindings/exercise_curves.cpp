// Exercise bindings for curves (kinds 3, 4 and 5): joints, values, properties.
// Curves cross as curve_spec.h's normalised specs; the JS layer
// (web/js/core/exercise-curves-api.js) has checked every type, so optional fields arrive as
// a flag plus a value. Results leave as plain objects (boundary.h).
#include "boundary.h"
#include "curve_spec.h"

#include "wingspline/curves/exercise.h"

namespace wingspline::bindings {
namespace {

using namespace wingspline::curves;

val strings(const std::vector<std::string>& v) {
    val a = val::array();
    for (std::size_t i = 0; i < v.size(); ++i) a.set(i, v[i]);
    return a;
}

std::vector<std::string> strings_from(const val& array) {
    std::vector<std::string> out;
    const std::size_t n = array["length"].as<std::size_t>();
    for (std::size_t i = 0; i < n; ++i) out.push_back(array[i].as<std::string>());
    return out;
}

std::optional<int> optional_int(bool has, int value) { return has ? std::optional<int>(value) : std::nullopt; }

val joint_reasons_value() {
    return guarded([] {
        val list = val::array();
        const auto& reasons = joint_reasons();
        for (std::size_t i = 0; i < reasons.size(); ++i) {
            val o = val::object();
            o.set("id", reasons[i].id);
            o.set("statement", reasons[i].statement);
            list.set(i, o);
        }
        val r = val::object();
        r.set("reasons", list);
        return r;
    });
}

val class_list(const std::vector<JointClass>& classes) {
    val list = val::array();
    for (std::size_t i = 0; i < classes.size(); ++i) {
        val o = val::object();
        o.set("k", classes[i].k);
        o.set("label", classes[i].label);
        o.set("requires", strings(classes[i].requires_reasons));
        list.set(i, o);
    }
    return list;
}

val joint_classes_value() {
    return guarded([] {
        val r = val::object();
        r.set("parametric", class_list(joint_classes().parametric));
        r.set("geometric", class_list(joint_classes().geometric));
        return r;
    });
}

val check_joint(const val& a, const val& b, double tolerance, bool has_p, int p, bool has_g, int g, bool has_why, const val& why) {
    return guarded([&] {
        JointAnswer answer{optional_int(has_p, p), optional_int(has_g, g), std::nullopt};
        if (has_why) answer.why = strings_from(why);
        const JointCheck c = check_joint_answer(curve_from(a), curve_from(b), answer, tolerance);
        val findings = val::array();
        for (std::size_t i = 0; i < c.findings.size(); ++i) {
            const JointFinding& f = c.findings[i];
            val o = val::object();
            o.set("field", f.field);
            if (f.is_reason) {
                o.set("given", f.given != 0);
                o.set("expected", f.expected != 0);
            } else {
                o.set("given", f.given);
                o.set("expected", f.expected);
            }
            o.set("reason", f.reason);
            o.set("message", f.message);
            o.set("hint", f.hint);
            findings.set(i, o);
        }
        val worked = val::object();
        worked.set("parametric", c.worked.parametric);
        worked.set("geometric", c.worked.geometric);
        worked.set("why", strings(c.worked.why));
        worked.set("explanation", strings(c.worked.explanation));
        val r = val::object();
        r.set("correct", c.correct);
        r.set("findings", findings);
        r.set("worked", worked);
        return r;
    });
}

// subject: {isPatch, curve (normalised spec, when !isPatch), patchKind, patchPoints};
// ask: {quantity, i, segment, row, col, index, u, v} with absent fields null.
ValueSubject subject_from(const val& s) {
    ValueSubject subject;
    subject.is_patch = s["isPatch"].as<bool>();
    if (subject.is_patch) {
        subject.patch_kind = parse_basis_kind(s["patchKind"].as<std::string>());
        subject.patch_points = to_doubles(s["patchPoints"]);
    } else {
        subject.curve = curve_from(s["curve"]);
    }
    return subject;
}

ValueAsk ask_from(const val& a) {
    ValueAsk ask;
    ask.quantity = a["quantity"].as<std::string>();
    auto int_field = [&](const char* name) {
        const val v = a[name];
        return v.isNull() || v.isUndefined() ? std::nullopt : std::optional<int>(v.as<int>());
    };
    auto number_field = [&](const char* name) {
        const val v = a[name];
        return v.isNull() || v.isUndefined() ? std::nullopt : std::optional<double>(v.as<double>());
    };
    ask.i = int_field("i");
    ask.segment = int_field("segment");
    ask.row = int_field("row");
    ask.col = int_field("col");
    ask.index = int_field("index");
    ask.u = number_field("u");
    ask.v = number_field("v");
    return ask;
}

val worked_fields(const WorkedValue& w) {
    val r = val::object();
    r.set("expected", to_typed_array(w.expected));
    r.set("label", w.label);
    r.set("working", strings(w.working));
    return r;
}

val worked_value_value(const val& subject, const val& ask) {
    return guarded([&] { return worked_fields(worked_value(subject_from(subject), ask_from(ask))); });
}

val check_value(const val& subject, const val& ask, const val& given, double tolerance) {
    return guarded([&] {
        const ValueCheck c = check_value_answer(subject_from(subject), ask_from(ask), to_doubles(given), tolerance);
        val r = worked_fields(c.worked);
        r.set("correct", c.correct);
        r.set("distance", c.distance);
        r.set("reason", c.reason);
        r.set("code", c.code);
        r.set("message", c.message);
        r.set("hint", c.hint);
        return r;
    });
}

val joint_class_property(const val& a, const val& b, double tolerance, bool has_p, int p, bool has_g, int g) {
    return guarded([&] {
        const PropertyCheck c = check_joint_class(curve_from(a), curve_from(b), optional_int(has_p, p), optional_int(has_g, g), tolerance);
        val r = val::object();
        r.set("holds", c.holds);
        r.set("reason", c.reason);
        r.set("parametric", c.parametric);
        r.set("geometric", c.geometric);
        r.set("why", strings(c.why));
        return r;
    });
}

val passes_through_property(const val& curve, const val& point, double tolerance) {
    return guarded([&] {
        const PropertyCheck c = check_passes_through(curve_from(curve), to_doubles(point), tolerance);
        val r = val::object();
        r.set("holds", c.holds);
        r.set("reason", c.reason);
        r.set("distance", c.distance);
        r.set("relativeDistance", c.relative_distance);
        r.set("size", c.size);
        r.set("u", c.u);
        r.set("closest", to_typed_array(c.closest));
        return r;
    });
}

} // namespace
} // namespace wingspline::bindings

EMSCRIPTEN_BINDINGS(wingspline_exercise_curves) {
    emscripten::function("exerciseJointReasons", &wingspline::bindings::joint_reasons_value);
    emscripten::function("exerciseJointClasses", &wingspline::bindings::joint_classes_value);
    emscripten::function("exerciseCheckJoint", &wingspline::bindings::check_joint);
    emscripten::function("exerciseWorkedValue", &wingspline::bindings::worked_value_value);
    emscripten::function("exerciseCheckValue", &wingspline::bindings::check_value);
    emscripten::function("exerciseJointClass", &wingspline::bindings::joint_class_property);
    emscripten::function("exercisePassesThrough", &wingspline::bindings::passes_through_property);
}
