"""A tiny test harness for scripts run inside FreeCAD (freecadcmd or the GUI), where pytest is not
available and an uncaught exception does not change the exit status.

    from harness import Suite
    suite = Suite()
    @suite.test
    def test_something(): ...
    suite.run_and_exit()          # prints RATBEZ_TEST_PASSED / RATBEZ_TEST_FAILED, exits 0 / 1
"""

import contextlib
import math
import os
import sys
import tempfile
import time
import traceback


def say(text):
    """Write to the process's real stdout (inside the FreeCAD GUI, print() goes to the report view)."""
    stream = sys.__stdout__ or sys.stdout
    stream.write(text + "\n")
    stream.flush()


class Suite:
    def __init__(self):
        self.tests = []

    def test(self, function):
        self.tests.append(function)
        return function

    def run(self):
        failures = []
        for function in self.tests:
            start = time.time()
            try:
                function()
            except BaseException as error:  # noqa: B902 -- SystemExit from a test is a failure too
                failures.append(function.__name__)
                say("FAIL  {}  ({:.1f} s)\n{}".format(function.__name__, time.time() - start,
                                                        traceback.format_exc()))
                if isinstance(error, KeyboardInterrupt):
                    break
            else:
                say("ok    {}  ({:.1f} s)".format(function.__name__, time.time() - start))
        return failures

    def run_and_exit(self, exit_function=None):
        try:
            failures = self.run()
        except BaseException:
            say(traceback.format_exc())
            failures = ["<harness>"]
        if failures:
            say("RATBEZ_TEST_FAILED: {} of {} failed: {}".format(len(failures), len(self.tests),
                                                                ", ".join(failures)))
        else:
            say("RATBEZ_TEST_PASSED: {} tests".format(len(self.tests)))
        (exit_function or os._exit)(1 if failures else 0)


def check(condition, message="check failed"):
    if not condition:
        raise AssertionError(message)


def close(actual, expected, rel, what=""):
    """Assert |actual - expected| <= rel * max(|expected|, tiny)."""
    scale = max(abs(expected), 1e-300)
    error = abs(actual - expected) / scale
    if not (error <= rel) or math.isnan(actual):
        raise AssertionError("{}: {} vs expected {} (relative error {:.3g} > {:.1g})".format(
            what or "value", actual, expected, error, rel))


@contextlib.contextmanager
def captured_output():
    """Capture what C++ and Python write to file descriptors 1 and 2 (FreeCAD's console in
    freecadcmd writes there). Yields a list that receives the captured text on exit."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    handle = tempfile.TemporaryFile()
    os.dup2(handle.fileno(), 1)
    os.dup2(handle.fileno(), 2)
    text = []
    try:
        yield text
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        os.close(saved[0])
        os.close(saved[1])
        handle.seek(0)
        text.append(handle.read().decode("utf-8", "replace"))
        handle.close()
        sys.stdout.write(text[0])
