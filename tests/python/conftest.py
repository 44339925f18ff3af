"""Shared helpers for the ratbez Python tests.

CTest puts the built module on PYTHONPATH. Run by hand from the repository root with, e.g.:
    PYTHONPATH=build/kernel/python /usr/bin/python3 -m pytest tests/python
"""
import math

import pytest

import ratbez


def close(a, b, tol=1e-12):
    """Component-wise comparison of two points or numbers."""
    if isinstance(a, (int, float)):
        return math.isclose(a, b, rel_tol=tol, abs_tol=tol)
    return len(a) == len(b) and all(math.isclose(x, y, rel_tol=tol, abs_tol=tol) for x, y in zip(a, b))


def raises_naming(argument, call, *args, **kwargs):
    """call(*args, **kwargs) must raise ratbez.Error whose message names `argument`."""
    with pytest.raises(ratbez.Error) as info:
        call(*args, **kwargs)
    assert argument in str(info.value), f"message {str(info.value)!r} does not name {argument!r}"
    return info.value


needs_occt = pytest.mark.skipif(not getattr(ratbez, "has_occt", False), reason="module built without OpenCASCADE")
needs_cgal = pytest.mark.skipif(not getattr(ratbez, "has_cgal", False), reason="module built without CGAL export")
