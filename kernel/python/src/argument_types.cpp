#include "argument_types.hpp"

#include <optional>
#include <string>
#include <vector>

namespace ratbez::python {

namespace {

namespace py = pybind11;

PyCFunctionWithKeywords pybind_dispatcher = nullptr;
void (*raise_error)(std::string_view, std::string_view) = nullptr;

struct Parameter {
    std::string name, type;
};

// The parameters of a pybind11 signature "(name: type = default, ...) -> result", split at the commas
// outside brackets and quotes.
std::vector<Parameter> parameters_of(std::string_view signature) {
    std::vector<Parameter> result;
    const std::size_t open = signature.find('(');
    const std::size_t close = signature.rfind(") -> ");
    if (open == std::string_view::npos || close == std::string_view::npos || close <= open) return result;
    const std::string_view inside = signature.substr(open + 1, close - open - 1);
    int depth = 0;
    char quote = 0;
    std::size_t start = 0;
    auto add = [&](std::string_view item) {
        const std::size_t colon = item.find(": ");
        if (colon == std::string_view::npos) return;
        std::string_view type = item.substr(colon + 2);
        // The type ends at " = " outside brackets (the default follows).
        int d = 0;
        for (std::size_t k = 0; k < type.size(); ++k) {
            const char c = type[k];
            if (c == '[' || c == '(') ++d;
            if (c == ']' || c == ')') --d;
            if (d == 0 && type.substr(k, 3) == " = ") {
                type = type.substr(0, k);
                break;
            }
        }
        result.push_back({std::string(item.substr(0, colon)), std::string(type)});
    };
    for (std::size_t k = 0; k < inside.size(); ++k) {
        const char c = inside[k];
        if (quote) {
            if (c == quote) quote = 0;
        } else if (c == '\'' || c == '"') {
            quote = c;
        } else if (c == '(' || c == '[' || c == '{') {
            ++depth;
        } else if (c == ')' || c == ']' || c == '}') {
            --depth;
        } else if (depth == 0 && c == ',' && k + 1 < inside.size() && inside[k + 1] == ' ') {
            add(inside.substr(start, k - start));
            start = k + 2;
        }
    }
    if (start < inside.size()) add(inside.substr(start));
    return result;
}

template <class T>
bool loads(py::handle value) {
    return py::detail::make_caster<T>().load(value, true);
}

// What a value of `type` must be, in words, when `value` is not one; nothing when it is one or when the
// type is not one this check knows (then the caller reports nothing about this argument).
std::optional<std::string> mismatch(const std::string& type, py::handle value, py::handle module) {
    if (type.rfind("Optional[", 0) == 0 && type.back() == ']') {
        if (value.is_none()) return std::nullopt;
        auto inner = mismatch(type.substr(9, type.size() - 10), value, module);
        if (inner) *inner += " or None";
        return inner;
    }
    if (type == "float") return loads<double>(value) ? std::nullopt : std::optional<std::string>("a number");
    if (type == "int") return loads<long long>(value) ? std::nullopt : std::optional<std::string>("an integer");
    if (type == "bool") return loads<bool>(value) ? std::nullopt : std::optional<std::string>("True or False");
    if (type == "str") return loads<std::string>(value) ? std::nullopt : std::optional<std::string>("a string");
    const std::string prefix = py::str(module.attr("__name__")).cast<std::string>() + ".";
    if (type.rfind(prefix, 0) == 0 && py::hasattr(module, type.substr(prefix.size()).c_str())) {
        const py::object cls = module.attr(type.substr(prefix.size()).c_str());
        if (PyType_Check(cls.ptr()) && !py::isinstance(value, cls)) return "a " + type;
    }
    return std::nullopt;
}

std::string described(py::handle value) {
    std::string repr = py::repr(value).cast<std::string>();
    if (repr.size() > 40) repr = repr.substr(0, 37) + "...";
    return std::string(Py_TYPE(value.ptr())->tp_name) + " " + repr;
}

// After pybind11 refused the arguments: the first argument whose value its declared type cannot take,
// as ratbez.Error; false when none is found (a wrong number or name of arguments).
bool raise_for_argument(PyObject* capsule, PyObject* args, PyObject* kwargs) {
    const auto* record = static_cast<const py::detail::function_record*>(
        PyCapsule_GetPointer(capsule, py::detail::get_function_record_capsule_name()));
    if (record == nullptr) {
        PyErr_Clear();
        return false;
    }
    const std::vector<Parameter> parameters = parameters_of(record->signature);
    const py::handle module = py::module_::import("ratbez");
    auto check = [&](const Parameter& parameter, py::handle value) {
        if (auto expected = mismatch(parameter.type, value, module)) {
            raise_error(parameter.name, "expected " + *expected + ", got " + described(value));
            return true;
        }
        return false;
    };
    const Py_ssize_t positional = args ? PyTuple_GET_SIZE(args) : 0;
    for (Py_ssize_t k = 0; k < positional && static_cast<std::size_t>(k) < parameters.size(); ++k)
        if (check(parameters[static_cast<std::size_t>(k)], PyTuple_GET_ITEM(args, k))) return true;
    if (kwargs != nullptr)
        for (const Parameter& parameter : parameters)
            if (PyObject* value = PyDict_GetItemString(kwargs, parameter.name.c_str()))
                if (check(parameter, value)) return true;
    return false;
}

PyObject* checked_dispatcher(PyObject* self, PyObject* args, PyObject* kwargs) {
    PyObject* result = pybind_dispatcher(self, args, kwargs);
    if (result != nullptr || !PyErr_ExceptionMatches(PyExc_TypeError)) return result;
    PyObject *type = nullptr, *value = nullptr, *traceback = nullptr;
    PyErr_Fetch(&type, &value, &traceback);
    bool replaced = false;
    if (value != nullptr && PyUnicode_Check(value)) {
        // pybind11's own refusal sets the message as a str; a TypeError raised from inside the call
        // (normalized, an instance) is left alone.
        const char* text = PyUnicode_AsUTF8(value);
        if (text != nullptr && std::string_view(text).find("incompatible function arguments") != std::string_view::npos) {
            try {
                replaced = raise_for_argument(self, args, kwargs);
            } catch (py::error_already_set& e) {
                e.restore();
                replaced = true;
            }
        }
    }
    if (replaced) {
        Py_XDECREF(type);
        Py_XDECREF(value);
        Py_XDECREF(traceback);
    } else {
        PyErr_Restore(type, value, traceback);
    }
    return nullptr;
}

// Points the PyMethodDef of a pybind11 function object at checked_dispatcher.
void wrap(py::handle function) {
    if (PyInstanceMethod_Check(function.ptr())) function = PyInstanceMethod_GET_FUNCTION(function.ptr());
    if (!PyCFunction_Check(function.ptr())) return;
    py::handle self = PyCFunction_GET_SELF(function.ptr());
    if (!self || !py::detail::is_function_record_capsule(py::reinterpret_borrow<py::capsule>(self))) return;
    PyMethodDef* def = reinterpret_cast<PyCFunctionObject*>(function.ptr())->m_ml;
    const auto dispatcher = reinterpret_cast<PyCFunctionWithKeywords>(reinterpret_cast<void (*)()>(def->ml_meth));
    if (dispatcher == &checked_dispatcher) return;
    if (pybind_dispatcher == nullptr) pybind_dispatcher = dispatcher;
    if (dispatcher != pybind_dispatcher) return;
    def->ml_meth = reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&checked_dispatcher));
}

}  // namespace

void name_argument_type_errors(py::module_& module, void (*raise)(std::string_view, std::string_view)) {
    raise_error = raise;
    for (auto item : py::reinterpret_borrow<py::dict>(module.attr("__dict__"))) {
        const py::handle value = item.second;
        if (PyType_Check(value.ptr())) {
            for (py::handle member : value.attr("__dict__").attr("values")()) {
                py::handle m = member;
                if (Py_TYPE(m.ptr()) == &PyStaticMethod_Type) m = m.attr("__func__");
                wrap(m);
            }
        } else {
            wrap(value);
        }
    }
}

}  // namespace ratbez::python
