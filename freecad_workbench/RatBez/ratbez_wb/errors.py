"""Failed recomputes, told once, in the words of the property editor.

The kernel names its arguments as the Python API does ("minor_radius", "weights", "holes[1]") and counts
from 0 ("weight 1" is the second). property_message() turns a kernel error's (argument, reason) into
what a FreeCAD user reads in the property editor: "MinorRadius: must be less than MajorRadius",
"Weights: weight 2 of 4 is 0 but must be > 0", "Profile: Edge3 crosses the axis". It is the one place
that knows the kernel's argument names (kernel.error_parts reads the error).

fail() prints one line "RatBez: <Label>: <message>" to the report view (not again while the same
failure repeats at later recomputes; not at all while the object's task panel shows it), and ends the
recompute as failed: FreeCAD marks the object invalid and keeps its last shape, without printing the
Python traceback FreeCAD 0.20 prints for an exception raised from execute() (see _raise_reported).
With the preference "Debug tracebacks" on, the exception goes to FreeCAD unchanged, traceback included.
"""

import ctypes
import re

import FreeCAD as App

from . import preferences
from .text import one_line

# Kernel argument -> property name (every feature uses the same words for the same thing).
_PROPERTY_OF = {
    "radius": "Radius", "radius1": "Radius1", "radius2": "Radius2", "height": "Height", "center": "Center",
    "axis": "Axis", "major_radius": "MajorRadius", "minor_radius": "MinorRadius", "axis_point": "AxisPoint",
    "axis_dir": "AxisDirection", "angle": "Angle", "angle_deg": "Angle", "direction": "Direction",
    "distance": "Distance", "profile": "Profile", "holes": "Profile", "points": "Poles", "net": "Poles",
    "weights": "Weights", "curve": "Poles", "surface": "Poles", "solid": "Shape", "profiles": "Sections",
    "degree": "Degree", "path": "Path", "tolerance": "Tolerance",
}
# Kernel names that may appear inside a reason ("must be less than major_radius"); plain words such as
# "radius" or "axis" there are prose and stay.
_NAMES_IN_REASONS = re.compile(r"\b(major_radius|minor_radius|radius1|radius2|axis_point|axis_dir|angle_deg)\b")
# std::to_string prints six decimals: 0.000000, 2.500000.
_FIXED_DECIMALS = re.compile(r"-?\d+\.\d{6}\b")


class Failure(ValueError):
    """A failure already in property words: the property concerned (may be "") and the reason."""

    def __init__(self, prop, reason):
        super().__init__("{}: {}".format(prop, reason) if prop else reason)
        self.prop, self.reason = prop, reason


class MessageContext:
    """What a feature knows to say a kernel error in its terms.

    counts: property name -> number of entries ("Weights": 4), for "weight 2 of 4";
    net_columns: columns of a Bézier surface's net, to number "weight [i][j]" in the flat Weights list;
    loops: the names of the profile's edges, loops[0] the outer loop and loops[h + 1] hole h, in the
    order the kernel numbers its pieces;
    sections: for the kernel's profiles[k] (a loft's), (property, words): ("Profile2", "") or ("Sections",
    "section 2 (Circle001)"), and section_loops[k] that profile's loops (as loops)."""

    def __init__(self, counts=None, net_columns=None, loops=None, sections=None, section_loops=None):
        self.counts = counts or {}
        self.net_columns = net_columns
        self.loops = loops or []
        self.sections = sections or []
        self.section_loops = section_loops or []

    def section(self, index):
        """The words for the kernel's profiles[index]: "section 2 (Circle001)" or "Profile2"."""
        if index < len(self.sections):
            prop, words = self.sections[index]
            return words or prop
        return "section {}".format(index + 1)

    def for_section(self, index):
        """The context of one section's own message (its pieces named as its edges)."""
        loops = self.section_loops[index] if index < len(self.section_loops) else []
        return MessageContext(self.counts, self.net_columns, loops)

    def piece(self, piece, loop=0):
        names = self.loops[loop] if loop < len(self.loops) else []
        if piece < len(names):
            return names[piece]
        return "piece {}".format(piece + 1) if loop == 0 else "piece {} of hole {}".format(piece + 1, loop)

    def of(self, prop, index):
        """'3 of 5' for 0-based index 2 of the property's 5 entries ('3' when the count is unknown)."""
        count = self.counts.get(prop)
        return "{} of {}".format(index + 1, count) if count else str(index + 1)


def _readable_number(match):
    return "{:.6g}".format(float(match.group(0)))


def _reason_in_property_words(reason, context):
    text = _NAMES_IN_REASONS.sub(lambda m: _PROPERTY_OF[m.group(1)], reason)
    def pole(match):  # the kernel counts control points from 0, the pole table from 1 (P1, P2, ...)
        if match.group(1) is not None:
            i, j = int(match.group(1)), int(match.group(2))
            if context.net_columns:
                return "pole {} (row {}, column {})".format(context.of("Poles", i * context.net_columns + j), i + 1, j + 1)
            return "pole (row {}, column {})".format(i + 1, j + 1)
        return "pole " + context.of("Poles", int(match.group(3)))

    text = re.sub(r"\bcontrol point (?:\[(\d+)\]\[(\d+)\]|(\d+)\b)", pole, text)
    text = text.replace("control points", "poles").replace("control point", "pole")

    def flat_weight(match):
        i, j = int(match.group(1)), int(match.group(2))  # the kernel's net indices, from 0
        if context.net_columns:
            return "weight {} (row {}, column {})".format(
                context.of("Weights", i * context.net_columns + j), i + 1, j + 1)
        return "weight (row {}, column {})".format(i + 1, j + 1)

    def weight(match):
        if match.group(1) is not None:
            return flat_weight(match)
        return "weight " + context.of("Weights", int(match.group(3)))

    # One pass for both forms, so that a rewritten "weight 16 of 16" is not numbered again.
    text = re.sub(r"\bweight (?:\[(\d+)\]\[(\d+)\]|(\d+)\b)", weight, text)
    text = re.sub(r"\bpiece (\d+) of the profile\b", lambda m: context.piece(int(m.group(1))), text)
    text = re.sub(r"\bpiece (\d+) of hole (\d+)\b",
                  lambda m: context.piece(int(m.group(1)), int(m.group(2)) + 1), text)
    text = re.sub(r"\bpieces (\d+) and (\d+)\b",
                  lambda m: "{} and {}".format(context.piece(int(m.group(1))), context.piece(int(m.group(2)))),
                  text)
    text = re.sub(r"\bpiece (\d+)\b", lambda m: context.piece(int(m.group(1))), text)
    return _FIXED_DECIMALS.sub(_readable_number, text)


def property_message(argument, reason, context=None):
    """The kernel's (argument, reason) in the property editor's words (see the module docstring)."""
    context = context or MessageContext()
    match = re.fullmatch(r"([a-z_0-9]+)((?:\[\d+\])*)", argument or "")
    name, indices = (match.group(1), [int(k) for k in re.findall(r"\d+", match.group(2))]) if match else ("", [])
    if name == "profiles" and context.sections:
        # A loft's section: its own pieces named as its edges, the other sections it mentions by their words.
        reason = _reason_in_property_words(reason, context.for_section(indices[0]) if indices else context)
        reason = re.sub(r"\bprofiles\[(\d+)\]", lambda m: context.section(int(m.group(1))), reason)
        if not indices:
            return "{}: {}".format(context.sections[0][0], reason)
        prop, words = context.sections[indices[0]] if indices[0] < len(context.sections) else ("Sections", "")
        return "{}: {}{}".format(prop, words + ": " if words else "", reason)
    reason = _reason_in_property_words(reason, context)
    if not match:
        return "{}: {}".format(argument, reason) if argument else reason
    prop = _PROPERTY_OF.get(name, name)
    if name == "holes" and indices:
        loop = indices[0] + 1
        first = context.loops[loop][0] if loop < len(context.loops) and context.loops[loop] else ""
        where = "hole {}{}".format(indices[0] + 1, " (the loop of {})".format(first) if first else "")
        return "{}: {} {}".format(prop, where, reason)
    if indices:
        singular = {"Poles": "pole", "Weights": "weight"}.get(prop, "entry")
        return "{}: {} {}: {}".format(prop, singular, context.of(prop, indices[0]), reason)
    return "{}: {}".format(prop, reason)


# ---------------------------------------------------------------------------------------------------

def _c_set_error():
    """ctypes' handle on PyErr_SetObject, or None where ctypes cannot reach the C API."""
    try:
        function = ctypes.pythonapi.PyErr_SetObject
        function.argtypes = [ctypes.py_object, ctypes.py_object]
        function.restype = None
        return function
    except (AttributeError, TypeError):
        return None


_SET_ERROR = _c_set_error()


def _raise_reported(message):
    """End execute() as failed without FreeCAD printing a traceback.

    FreeCAD 0.20 (Base::PyException) prints any exception that leaves a Python feature's execute()
    together with its traceback, unless the exception's value is the dict of a FreeCAD exception marked
    'breported'. Python code cannot raise such an un-normalised exception; the C API can:
    PyErr_SetObject(ValueError, {...}) through ctypes, which raises it when the call returns. FreeCAD
    then marks the object invalid with `message` (the tree's tooltip, obj.getStatusString()) and prints
    nothing. Python turns the exception into an object (and FreeCAD then prints it) wherever an except
    clause inspects it on its way out, and when it is raised while another one is handled: so neither
    this call nor its callers up to execute() may sit in a try statement with except clauses or in an
    except clause. Falls back to a plain exception (printed with its traceback) without ctypes."""
    if _SET_ERROR is not None:
        _SET_ERROR(ValueError, {"sErrMsg": message, "swhat": message, "breported": True})
    raise ValueError(message)


def fail(obj, proxy, message, details=None, error=None):
    """Report the failure of obj's recompute (once per distinct message) and end it as failed. Call it
    outside any except clause (see _raise_reported)."""
    if getattr(proxy, "last_failure", None) != message and not getattr(proxy, "quiet", False):
        App.Console.PrintError("RatBez: {}: {}\n".format(one_line(obj.Label), one_line(message)))
    proxy.last_failure = message
    if preferences.debug_tracebacks():
        if details:
            App.Console.PrintError(details)
        if error is not None:
            raise error
    _raise_reported(message)


def succeeded(proxy):
    proxy.last_failure = None
