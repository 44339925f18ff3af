#pragma once
// Every bound class refuses an instance made by `Class.__new__(Class)` without __init__ (issue 14, item 7).
// pybind11 2.10 gives such an instance no C++ value; its generic caster then allocates raw memory on first
// use ("lazy allocation" in type_caster_generic::load_value), so `ratbez.Mesh.__new__(ratbez.Mesh).volume()`
// read garbage or crashed. The casters below raise TypeError instead, wherever the object is used: as self
// of a method or property, or as an argument of any function. Objects pybind11 hands out itself (return
// values, references into a Solid) always have a value. Included by convert.hpp and numpy_arrays.hpp, so
// that every binding source sees these specialisations before its first use of a class.

#include <pybind11/pybind11.h>

#include <string>
#include <utility>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"

namespace ratbez::python {

// type_caster_base<T> that raises TypeError for an instance whose C++ value was never constructed.
template <class T>
class initialised_caster : public pybind11::detail::type_caster_base<T> {
public:
    bool load(pybind11::handle source, bool convert) {
        return this->template load_impl<initialised_caster<T>>(source, convert);
    }
    // Called by load_impl with the instance's value slot (a null pointer until __init__ has run).
    void load_value(pybind11::detail::value_and_holder&& slot) {
        if (slot.value_ptr() == nullptr) {
            // The slot names its type only when it is not the instance's own; else the caster's type it is.
            const std::string name = (slot.type ? slot.type : this->typeinfo)->type->tp_name;  // "ratbez.Mesh"
            throw pybind11::type_error(name + " object is not initialised: it was made by " + name +
                                       ".__new__ without __init__; construct it as " + name + "(...)");
        }
        pybind11::detail::type_caster_base<T>::load_value(std::move(slot));
    }
};

}  // namespace ratbez::python

#define RATBEZ_INITIALISED_CASTER(T) \
    template <>                      \
    class pybind11::detail::type_caster<T> : public ratbez::python::initialised_caster<T> {}

RATBEZ_INITIALISED_CASTER(ratbez::BezierCurve);
RATBEZ_INITIALISED_CASTER(ratbez::BezierSurface);
RATBEZ_INITIALISED_CASTER(ratbez::NurbsCurve);
RATBEZ_INITIALISED_CASTER(ratbez::NurbsSurface);
RATBEZ_INITIALISED_CASTER(ratbez::Mesh);
RATBEZ_INITIALISED_CASTER(ratbez::Face);
RATBEZ_INITIALISED_CASTER(ratbez::Solid);

#undef RATBEZ_INITIALISED_CASTER
