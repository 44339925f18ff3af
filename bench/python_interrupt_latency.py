"""How soon Ctrl-C stops the module's long calls: each call runs on the main thread with the GIL released,
SIGINT arrives from a timer thread partway through, and the time from the signal to KeyboardInterrupt
coming out of the call is printed (three runs each). Not a pass/fail test (tests/python/test_progress.py
checks that the calls stop); the numbers for the notes and the README.

Usage: PYTHONPATH=build/kernel/python /usr/bin/python3 bench/python_interrupt_latency.py
"""

import os
import signal
import tempfile
import threading
import time

import ratbez


def latency(call, after):
    """Seconds from SIGINT (sent `after` seconds into the call) to KeyboardInterrupt; None if it finished."""
    sent = []

    def fire():
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(after, fire)
    timer.start()
    try:
        call()
        return None
    except KeyboardInterrupt:
        return time.perf_counter() - sent[0]
    finally:
        timer.cancel()


def main():
    sphere = ratbez.sphere(10.0)
    fine = sphere.tessellate(1.5e-4)
    huge = ratbez.torus(10.0, 3.0).tessellate(2e-5)
    folder = tempfile.mkdtemp()
    cases = [
        (f"export_openscad, {len(fine.triangles):,} triangles",
         lambda: ratbez.export_openscad(sphere, os.path.join(folder, "a.scad"), tolerance=1.5e-4), 1.5),
        (f"check_mesh, {len(fine.triangles):,} triangles", lambda: ratbez.check_mesh(fine), 0.5),
        (f"check_mesh, {len(huge.triangles):,} triangles", lambda: ratbez.check_mesh(huge), 3.0),
        (f"write_stl, {len(huge.triangles):,} triangles", lambda: ratbez.write_stl(huge, os.path.join(folder, "b.stl")), 1.0),
        ("occt_check(grid=2000)", lambda: ratbez.occt_check(sphere, grid=2000), 0.5),
        ("tessellate(1e-5) of a torus", lambda: ratbez.torus(3.0, 1.0).tessellate(1e-5), 0.5),
    ]
    for name, call, after in cases:
        runs = [latency(call, after) for _ in range(3)]
        print(f"{name}: " + ", ".join("finished" if r is None else f"{r * 1e3:.0f} ms" for r in runs))


if __name__ == "__main__":
    main()
