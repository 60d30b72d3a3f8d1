"""The `motionvar` command's output as one transaction (motionvar.io.atomic.AtomicFiles):
its files appear together or not at all, a file that existed is overwritten only with
--force and keeps its content when the command fails or is stopped (an error, Ctrl-C,
SIGTERM, SIGHUP), and a target that is not a regular file (folder, named pipe, device,
symlink) is refused with one line and exit status 2, before any work."""

from __future__ import annotations

import errno
import os
import signal
import stat
import subprocess
import sys

import pytest
from cli_toy import DS, run, toy_results, toy_stride

import motionvar.cli.common
from motionvar.cli.main import main
from motionvar.io.atomic import TMP_SUFFIX
from motionvar.io.bvh import read_bvh

pytestmark = pytest.mark.usefixtures("one_torch_thread")  # tests/conftest.py

EARLIER = "earlier content\n"  # what a file had before the command


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    """results/toy of tests/cli_toy.py (built once per session)."""
    return toy_results(tmp_path_factory)


def walks(results, out, *extra):
    """``motionvar ma2010`` of two 2 s variants into the folder ``out``."""
    style = toy_stride(results)
    return run(results, "ma2010", "--style", style, "--seconds", "2", "--variants", "2", "--out", str(out), *extra)


def targets(results, out):
    """The two files of :func:`walks`."""
    style = f"{float(toy_stride(results)):g}"
    return [out / f"ma2010_{style}_{style}_v{k}.bvh" for k in (1, 2)]


def temporaries(folder):
    return sorted(p.name for p in folder.iterdir() if p.name.endswith(TMP_SUFFIX))


def one_error_line(capsys, command: str) -> str:
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"motionvar {command}: error: ") and "Traceback" not in err, err
    return err


def test_an_existing_file_stops_the_command_before_any_work_and_force_overwrites(
    results, tmp_path, capsys, monkeypatch
):
    v1, v2 = targets(results, tmp_path)
    v1.write_text(EARLIER)

    def no_work(*args, **kwargs):
        raise AssertionError("generated although an output file exists")

    with monkeypatch.context() as m:
        m.setattr("motionvar.ma2010.generate.generate_walks", no_work)
        assert walks(results, tmp_path) == 2
    err = one_error_line(capsys, "ma2010")
    assert f"{v1}: exists; pass --force to overwrite" in err
    assert v1.read_text() == EARLIER and not v2.exists()
    assert walks(results, tmp_path, "--force") == 0
    assert read_bvh(v1).n_frames == read_bvh(v2).n_frames > 1  # both written, v1 replaced
    assert temporaries(tmp_path) == []


def test_a_failed_second_file_leaves_the_first_files_earlier_content(results, tmp_path, capsys, monkeypatch):
    """A full disk on the second file: no file appears or changes (v1 keeps what it had,
    even with --force), no temporary file is left."""
    v1, v2 = targets(results, tmp_path)
    v1.write_text(EARLIER)
    write = motionvar.cli.common.write_bvh
    calls = []

    def full_disk_on_the_second(path, motion, scale=1.0):
        calls.append(path)
        if len(calls) == 2:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        write(path, motion, scale=scale)

    monkeypatch.setattr(motionvar.cli.common, "write_bvh", full_disk_on_the_second)
    assert walks(results, tmp_path, "--force") == 2
    err = one_error_line(capsys, "ma2010")
    assert f"cannot write {v2}: No space left on device; no file written" in err
    assert calls == [v1, v2]
    assert v1.read_text() == EARLIER and not v2.exists() and temporaries(tmp_path) == []


def test_a_folder_at_a_target_is_refused_and_nothing_changes(results, tmp_path, capsys):
    """The reported case: v1 a file, v2 a folder. Without --force v1 stops the command;
    with it, the folder does; v1 keeps its content either way."""
    v1, v2 = targets(results, tmp_path)
    v1.write_text(EARLIER)
    v2.mkdir()
    assert walks(results, tmp_path) == 2
    assert f"{v1}: exists" in one_error_line(capsys, "ma2010")
    assert walks(results, tmp_path, "--force") == 2
    assert f"{v2}: is a folder, not a regular file" in one_error_line(capsys, "ma2010")
    assert v1.read_text() == EARLIER and v2.is_dir() and not any(v2.iterdir())


def _special(kind, path):
    """Make a named pipe, a character device (as /dev/null's, skipped where mknod is not
    permitted) or a symlink to a file at ``path``; returns what is expected of it."""
    if kind == "named pipe":
        os.mkfifo(path)
    elif kind == "device":
        try:
            os.mknod(path, stat.S_IFCHR | 0o600, os.makedev(1, 3))
        except (PermissionError, OSError) as exc:
            pytest.skip(f"cannot make a device node here: {exc}")
    else:
        target = path.with_name("target.txt")
        target.write_text(EARLIER)
        path.symlink_to(target)
    return os.lstat(path).st_mode


@pytest.mark.parametrize("kind", ["named pipe", "device", "symlink"])
@pytest.mark.parametrize("force", [False, True], ids=["", "force"])
def test_a_target_that_is_not_a_regular_file_is_refused(results, tmp_path, capsys, kind, force):
    out = tmp_path / "idle.bvh"
    mode = _special(kind, out)
    argv = ["egges2004", "--subject", "01", "--seconds", "1", "--out", str(out), *(["--force"] if force else [])]
    assert run(results, *argv) == 2
    err = one_error_line(capsys, "egges2004")
    assert f"{out}: is a {kind}, not a regular file" in err
    assert os.lstat(out).st_mode == mode  # still the pipe, device or link
    if kind == "symlink":
        assert (tmp_path / "target.txt").read_text() == EARLIER
    assert temporaries(tmp_path) == []


def test_an_output_folder_that_cannot_be_made_or_written(results, tmp_path, capsys):
    (tmp_path / "a_file").write_text(EARLIER)
    assert (
        run(results, "egges2004", "--subject", "01", "--seconds", "1", "--out", str(tmp_path / "a_file" / "idle.bvh"))
        == 2
    )
    assert f"{tmp_path / 'a_file'}: is not a folder" in one_error_line(capsys, "egges2004")
    if os.geteuid() == 0:
        return  # root writes in any folder: the permission case needs another user
    locked = tmp_path / "locked"
    locked.mkdir(mode=0o500)
    assert run(results, "egges2004", "--subject", "01", "--seconds", "1", "--out", str(locked / "idle.bvh")) == 2
    assert f"{locked}: folder not writable (permission denied)" in one_error_line(capsys, "egges2004")


def test_new_folders_are_removed_when_the_command_fails(results, tmp_path, capsys, monkeypatch):
    write = motionvar.cli.common.write_bvh

    def fail_after_writing(path, motion, scale=1.0):
        write(path, motion, scale=scale)  # the temporary file and its folders are made
        raise OSError(errno.EIO, os.strerror(errno.EIO))

    monkeypatch.setattr(motionvar.cli.common, "write_bvh", fail_after_writing)
    assert (
        run(
            results,
            "egges2004",
            "--subject",
            "01",
            "--seconds",
            "1",
            "--out",
            str(tmp_path / "new" / "deep" / "idle.bvh"),
        )
        == 2
    )
    assert "Input/output error; no file written" in one_error_line(capsys, "egges2004")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGHUP], ids=["SIGINT", "SIGHUP"])
def test_a_stop_signal_while_writing_leaves_every_path_as_it_was(results, tmp_path, capsys, monkeypatch, signum):
    """Ctrl-C or SIGHUP (sent to this process) after the first of two files is written:
    exit status 128 + the signal, v1 keeps its earlier content, no v2, no temporaries."""

    def unhandled(*_):
        raise AssertionError(f"main() left {signal.Signals(signum).name} to the caller's handler")

    before = signal.signal(signum, unhandled)  # instead of this test run's end, should main() not handle it
    v1, v2 = targets(results, tmp_path)
    v1.write_text(EARLIER)
    write = motionvar.cli.common.write_bvh

    def signal_after_the_first(path, motion, scale=1.0):
        write(path, motion, scale=scale)
        if path == v1:
            os.kill(os.getpid(), signum)

    monkeypatch.setattr(motionvar.cli.common, "write_bvh", signal_after_the_first)
    try:
        assert walks(results, tmp_path, "--force") == 128 + signum
        assert signal.getsignal(signum) is unhandled  # main() put the caller's handler back
    finally:
        signal.signal(signum, before)
    assert capsys.readouterr().err.strip().endswith("interrupted" if signum == signal.SIGINT else "stopped by SIGHUP")
    assert v1.read_text() == EARLIER and not v2.exists() and temporaries(tmp_path) == []


# The command with its first file's write held open: it prints "written" and waits for a signal.
SLOW_WRITER = """
import sys, time
import motionvar.cli.common as common
write = common.write_bvh

def held(path, motion, scale=1.0):
    write(path, motion, scale=scale)
    print("written", path, flush=True)
    time.sleep(60)

common.write_bvh = held
from motionvar.cli.main import main
sys.exit(main(sys.argv[1:]))
"""


def test_sigterm_while_writing_cleans_up_like_ctrl_c(results, tmp_path):
    """`kill -TERM` while a two-variant command writes: exit status 143, no target appears
    or changes (v1 keeps its earlier content although --force), no temporary file left."""
    v1, v2 = targets(results, tmp_path)
    v1.write_text(EARLIER)
    argv = ["ma2010", "--results", str(results), "--dataset", DS, "--quiet", "--force", "--style", toy_stride(results)]
    argv += ["--seconds", "2", "--variants", "2", "--out", str(tmp_path)]
    proc = subprocess.Popen(
        [sys.executable, "-c", SLOW_WRITER, *argv], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    try:
        line = proc.stdout.readline()
        assert line == f"written {v1}\n", line + proc.stderr.read()
        assert len(temporaries(tmp_path)) == 1 and v1.read_text() == EARLIER  # mid-transaction
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=60)
    finally:
        proc.kill()
        proc.wait()
    assert proc.returncode == 128 + signal.SIGTERM, err
    assert err == "motionvar ma2010: stopped by SIGTERM\n"
    assert v1.read_text() == EARLIER and not v2.exists() and temporaries(tmp_path) == []


def test_main_in_a_thread_leaves_signals_alone(results, tmp_path):
    """Python sets signal handlers only in the main thread: elsewhere main() runs without."""
    import threading

    argv = ["egges2004", "--results", str(results), "--dataset", DS, "--quiet", "--seconds", "1"]
    codes = []
    thread = threading.Thread(target=lambda: codes.append(main([*argv, "--out", str(tmp_path / "idle.bvh")])))
    thread.start()
    thread.join(60)
    assert codes == [0] and read_bvh(tmp_path / "idle.bvh").n_frames == 31
