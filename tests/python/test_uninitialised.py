"""Issue 14, item 7: an object made by Class.__new__(Class) without __init__ has no C++ value. Using it in
any way (a method, a property, an operator, as an argument) must raise a Python error, never crash the
interpreter or read garbage. The probes run in a child interpreter, so a crash fails the test instead of
killing pytest."""

import subprocess
import sys
import textwrap

PROBE = textwrap.dedent(r"""
    import copy, pickle, sys
    import ratbez

    classes = [c for c in vars(ratbez).values()
               if isinstance(c, type) and type(c).__name__ == "pybind11_type"]
    assert {"BezierCurve", "BezierSurface", "NurbsCurve", "NurbsSurface", "Mesh", "Face", "Solid"} <= \
        {c.__name__ for c in classes}, classes
    arguments = [(), (0.5,), (0.5, 0.5), (2,), (0.5, 1), (0.5, 0.5, 1, 1), ([0, 0, 1],), (1e-3,)]
    refused = 0

    def expect_error(what, call):
        global refused
        try:
            call()
        except Exception as error:  # any Python error is a refusal; a crash never gets here
            refused += 1
            return error
        raise AssertionError(what + " did not raise")

    for cls in classes:
        blank = cls.__new__(cls)
        for name in dir(cls):
            if name.startswith("__") and name not in ("__eq__", "__hash__", "__repr__", "__reduce__", "__copy__",
                                                       "__deepcopy__", "__getstate__", "__len__", "__iter__"):
                continue
            attribute = getattr(cls, name)
            if isinstance(attribute, property):
                expect_error(cls.__name__ + "." + name, lambda: getattr(blank, name))
                continue
            if not callable(attribute) or isinstance(attribute, type):
                continue
            for args in arguments:
                if name.startswith("__"):
                    # Operators may answer without looking at self (object's defaults, NotImplemented for a
                    # wrong arity or type); whatever they answer, they must not crash.
                    try:
                        getattr(blank, name)(*args)
                    except Exception:
                        pass
                    continue
                expect_error("{}.{}{}".format(cls.__name__, name, args), lambda: getattr(blank, name)(*args))
        for what, call in [("copy", lambda: copy.copy(blank)), ("deepcopy", lambda: copy.deepcopy(blank)),
                           ("pickle", lambda: pickle.dumps(blank))]:
            expect_error(cls.__name__ + " " + what, call)
        for call in [lambda: hash(blank), lambda: blank == blank, lambda: repr(blank)]:
            try:
                call()
            except Exception:
                pass
        # As an argument of every module function, alone and with plausible companions.
        for name, function in vars(ratbez).items():
            if callable(function) and not isinstance(function, type) and not name.startswith("_"):
                for args in [(blank,), (blank, 0.5), (blank, "/nonexistent-ratbez/x.stl"), ([blank],), ([blank, blank],)]:
                    try:
                        function(*args)
                    except Exception:
                        pass

    error = expect_error("Mesh.volume", lambda: ratbez.Mesh.__new__(ratbez.Mesh).volume())
    assert isinstance(error, TypeError) and "not initialised" in str(error), error
    # __init__ after __new__ is the ordinary two-step construction and still works.
    mesh = ratbez.Mesh.__new__(ratbez.Mesh)
    mesh.__init__([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    assert abs(mesh.volume() - 1 / 6) < 1e-15, mesh.volume()
    print("refused", refused)
""")


def test_uninitialised_objects_raise_instead_of_crashing():
    result = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, "probe exited with {} (negative: killed by signal)\n{}\n{}".format(
        result.returncode, result.stdout[-2000:], result.stderr[-4000:])
    assert "refused" in result.stdout
