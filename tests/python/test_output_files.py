"""Issue 14, items 1-6: every writer (export_openscad, write_stl, write_step, write_brep, write_text_file)
goes through one safe writer: a new exclusive temporary file beside the target, renamed over it; a symbolic
link at the target is refused, a read-only file is refused, errors name the folder when the folder is at
fault, long names work, a NUL byte in a path is refused."""

import os
import pwd
import shutil
import stat
import struct
import subprocess
import sys
import tempfile
import threading

import pytest

import ratbez
from conftest import needs_cgal, needs_occt, raises_naming

MODULE_DIR = os.path.dirname(ratbez.__file__)


def writers():
    """(name, extension, write(path), valid(bytes)) for every file writer the module has."""
    mesh = ratbez.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    solid = ratbez.cylinder(1, 2)
    result = [("write_text_file", ".txt", lambda p: ratbez.write_text_file(p, "x" * 100000 + "\nend\n"),
               lambda data: data == ("x" * 100000 + "\nend\n").encode())]
    if ratbez.has_cgal:
        result.append(("export_openscad", ".scad", lambda p: ratbez.export_openscad(mesh, p),
                       lambda data: data.startswith(b"// ratbez ") and data.rstrip().endswith(b"();")))
        result.append(("write_stl", ".stl", lambda p: ratbez.write_stl(mesh, p),
                       lambda data: len(data) == 84 + 50 * struct.unpack_from("<I", data, 80)[0] == 84 + 50 * 4))
    if ratbez.has_occt:
        result.append(("write_step", ".step", lambda p: ratbez.write_step(solid, p),
                       lambda data: data.startswith(b"ISO-10303-21;") and data.rstrip().endswith(b"END-ISO-10303-21;")))
        result.append(("write_brep", ".brep", lambda p: ratbez.write_brep(solid, p),
                       lambda data: data.startswith(b"DBRep_DrawableShape\n\nCASCADE Topology") and data.rstrip().endswith(b"+1 0")))
    return result


WRITERS = writers()
IDS = [w[0] for w in WRITERS]


def leftovers(folder):
    return [name for name in os.listdir(folder) if name.startswith(".ratbez-")]


@pytest.mark.parametrize("name,extension,write,valid", WRITERS, ids=IDS)
def test_symlink_at_the_target_is_refused_and_its_file_untouched(tmp_path, name, extension, write, valid):
    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    link = tmp_path / ("out" + extension)
    link.symlink_to(victim)
    error = raises_naming("path", write, str(link))
    assert "symbolic link" in str(error)
    assert victim.read_text() == "precious" and link.is_symlink()
    # A planted temporary-looking name is never opened either: the writer creates new names only.
    planted = tmp_path / (".ratbez-partial" + extension)
    planted.symlink_to(victim)
    target = tmp_path / ("fresh" + extension)
    write(str(target))
    assert valid(target.read_bytes()) and victim.read_text() == "precious"
    assert leftovers(tmp_path) == [planted.name]


@pytest.mark.parametrize("name,extension,write,valid", WRITERS, ids=IDS)
def test_concurrent_writers_each_leave_a_whole_file(tmp_path, name, extension, write, valid):
    target = str(tmp_path / ("shared" + extension))
    errors = []

    def run():
        try:
            write(target)
        except Exception as error:  # pragma: no cover - reported below
            errors.append(error)

    threads = [threading.Thread(target=run) for _ in range(16)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert errors == []
    assert valid(open(target, "rb").read())
    assert leftovers(tmp_path) == []


@pytest.mark.parametrize("name,extension,write,valid", WRITERS, ids=IDS)
def test_replacing_keeps_the_mode_and_long_names_work(tmp_path, name, extension, write, valid):
    target = tmp_path / ("old" + extension)
    target.write_text("old")
    os.chmod(target, 0o640)
    write(str(target))
    assert valid(target.read_bytes()) and stat.S_IMODE(target.stat().st_mode) == 0o640
    long_name = tmp_path / ("n" * (255 - len(extension)) + extension)  # NAME_MAX bytes: no room for a suffix
    write(str(long_name))
    assert valid(long_name.read_bytes())
    raises_naming("path", write, str(tmp_path / ("n" * 256 + extension)))
    assert leftovers(tmp_path) == []


@pytest.mark.parametrize("name,extension,write,valid", WRITERS, ids=IDS)
def test_nul_byte_and_folder_targets_are_refused(tmp_path, name, extension, write, valid):
    error = raises_naming("path", write, str(tmp_path / "a") + extension + "\0.txt")
    assert "NUL" in str(error)
    assert os.listdir(tmp_path) == []
    folder = tmp_path / ("folder" + extension)
    folder.mkdir()
    raises_naming("path", write, str(folder))
    error = raises_naming("path", write, str(tmp_path / "missing" / ("x" + extension)))
    assert "missing" in str(error) and "does not exist" in str(error)



class _BytesPath:
    """An os.PathLike whose __fspath__ gives bytes, as os.fsencode-minded libraries pass paths."""

    def __init__(self, path):
        self.path = os.fsencode(path)

    def __fspath__(self):
        return self.path


@pytest.mark.parametrize("name,extension,write,valid", WRITERS, ids=IDS)
def test_bytes_paths_write_as_open_takes_them(tmp_path, name, extension, write, valid):
    # open() takes bytes and os.PathLike[bytes]; so does every writer, and the reader gets the file back.
    target = os.fsencode(str(tmp_path / ("bytes é" + extension)))
    write(target)
    with open(target, "rb") as written:
        assert valid(written.read())
    write(_BytesPath(str(tmp_path / ("pathlike" + extension))))
    assert valid((tmp_path / ("pathlike" + extension)).read_bytes())
    if name == "write_step":
        assert ratbez.read_step(target).name == "bytes é"  # named after the file's stem, as with a str path
    error = raises_naming("path", write, bytes(tmp_path) + b"/\xff" + extension.encode())
    assert "UTF-8" in str(error)
    assert sorted(os.listdir(tmp_path)) == sorted(["bytes é" + extension, "pathlike" + extension])

# ---- As an unprivileged user: root may write anything, so the permission rules are checked as nobody ----

UNPRIVILEGED = r"""
import os, sys
sys.path.insert(0, sys.argv[1])
import ratbez
folder = sys.argv[2]
# A read-only file is refused (a shell redirect refuses it too), and left as it was.
readonly = os.path.join(folder, "readonly.txt")
try:
    ratbez.write_text_file(readonly, "new")
    raise SystemExit("read-only file replaced")
except ratbez.Error as error:
    assert error.argument == "path" and "read-only" in str(error) and readonly in str(error), error
assert open(readonly).read() == "old"
# A writable file in a read-only folder: the message names the folder.
locked = os.path.join(folder, "locked")
try:
    ratbez.write_text_file(os.path.join(locked, "file.txt"), "new")
    raise SystemExit("wrote into a read-only folder")
except ratbez.Error as error:
    assert error.argument == "path" and "folder '" + locked + "' is not writable" in str(error), error
assert open(os.path.join(locked, "file.txt")).read() == "old"
print("ok")
"""


def run_unprivileged(code, *args):
    def drop():
        if os.getuid() == 0:
            nobody = pwd.getpwnam("nobody")
            os.setgid(nobody.pw_gid)
            os.setuid(nobody.pw_uid)
    return subprocess.run([sys.executable, "-c", code, MODULE_DIR, *args], capture_output=True, text=True,
                          preexec_fn=drop, timeout=60)


def test_read_only_file_and_folder_are_refused_for_an_ordinary_user():
    if os.getuid() == 0:
        try:
            pwd.getpwnam("nobody")
        except KeyError:
            pytest.skip("no user 'nobody' to drop to")
    folder = tempfile.mkdtemp(prefix="ratbez-permissions-")
    try:
        os.chmod(folder, 0o777)
        readonly = os.path.join(folder, "readonly.txt")
        with open(readonly, "w") as f:
            f.write("old")
        os.chmod(readonly, 0o444)
        locked = os.path.join(folder, "locked")
        os.mkdir(locked)
        with open(os.path.join(locked, "file.txt"), "w") as f:
            f.write("old")
        os.chmod(os.path.join(locked, "file.txt"), 0o666)
        os.chmod(locked, 0o555)
        if os.getuid() == 0:
            nobody = pwd.getpwnam("nobody")
            os.chown(readonly, nobody.pw_uid, nobody.pw_gid)
        result = run_unprivileged(UNPRIVILEGED, folder)
        assert result.returncode == 0 and "ok" in result.stdout, result.stdout + result.stderr
        assert stat.S_IMODE(os.stat(readonly).st_mode) == 0o444
    finally:
        os.chmod(os.path.join(folder, "locked"), 0o755)
        shutil.rmtree(folder)
