"""Access to the compiled ratbez module.

The module is installed next to this workbench (the Mod folder is on sys.path) or anywhere else on
sys.path. It is imported on first use, so FreeCAD starts even when it is missing, and every feature
then fails with one clear message instead of a traceback at start-up.
"""

_module = None


class KernelMissing(ImportError):
    pass


def ratbez():
    """The ratbez module; raises KernelMissing with an installation hint when it cannot be imported."""
    global _module
    if _module is None:
        try:
            import ratbez as module
        except ImportError as error:
            raise KernelMissing(
                "the compiled kernel module 'ratbez' cannot be imported ({}). Install it with "
                "'cmake --install <build> --component freecad' so that it lies next to the RatBez "
                "workbench.".format(error)) from error
        _module = module
    return _module


def error_types():
    """The exception types that mean 'bad input' (reported to the user, not a bug)."""
    types = [ValueError, TypeError, KernelMissing]
    try:
        types.insert(0, ratbez().Error)
    except KernelMissing:
        pass
    return tuple(types)


def error_parts(error):
    """(argument, reason) of a kernel error: the argument it names ("minor_radius", "weights",
    "holes[1]") and why. ratbez.Error carries them as .argument and .reason where the module is new
    enough; otherwise its message is "<argument>: <reason>". ("", message) when it names none."""
    argument, reason = getattr(error, "argument", None), getattr(error, "reason", None)
    if isinstance(argument, str) and isinstance(reason, str):
        return argument, reason
    text = str(error)
    head, separator, tail = text.partition(": ")
    if separator and head and " " not in head.strip("[]0123456789"):
        return head, tail
    return "", text
