"""Atomic file writes: a file appears at its path complete or not at all; and
:class:`AtomicFiles`, a set of files that appear together or not at all.

The content is written to a hidden temporary file beside the target
(``.<name>.<random>.tmp``) and renamed onto it. The file gets an ordinary file's mode
(``0666`` less the umask, 0644 usually — not the private 0600 of ``mkstemp``). Only a
regular file is ever replaced: a target that is a folder, a symlink, a device, a named pipe
or a socket is refused (:class:`TargetError`) before anything is written, so that a rename
never puts a file in the place of something else. A process killed during a write cannot
remove its temporary file; the next write of the same target removes such leftovers first.

Inside ``with AtomicFiles(paths):`` every :func:`atomic_write` of one of ``paths`` (and so
every writer built on it: BVH, model files, packed datasets) goes to its temporary file;
when the block ends without an error and every path was written, the temporaries are
renamed onto their paths; on any exception (``KeyboardInterrupt`` included) they are
removed and no path changes.
"""

from __future__ import annotations

import contextvars
import os
import secrets
import stat
from collections.abc import Sequence
from pathlib import Path
from typing import Callable

TMP_SUFFIX = ".tmp"
_ACTIVE: contextvars.ContextVar[AtomicFiles | None] = contextvars.ContextVar("motionvar_atomic_files", default=None)


class TargetError(ValueError):
    """A target path that a write refuses; the message names it."""


class TargetExistsError(TargetError):
    """A target that exists where the write may not overwrite it."""


def _file_mode() -> int:
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


def target_kind(path: str | Path) -> str | None:
    """What is at ``path`` itself (a symlink not followed): None for nothing, else "file"
    (a regular file), "folder", "symlink", "device", "named pipe", "socket"."""
    try:
        mode = os.lstat(path).st_mode
    except (FileNotFoundError, NotADirectoryError):
        return None
    kinds = [
        (stat.S_ISREG, "file"),
        (stat.S_ISDIR, "folder"),
        (stat.S_ISLNK, "symlink"),
        (stat.S_ISCHR, "device"),
        (stat.S_ISBLK, "device"),
        (stat.S_ISFIFO, "named pipe"),
        (stat.S_ISSOCK, "socket"),
    ]
    return next((kind for test, kind in kinds if test(mode)), "special file")


def check_target(path: str | Path, overwrite: bool = True) -> None:
    """TargetError unless ``path`` is free or (with ``overwrite``) a regular file."""
    kind = target_kind(path)
    if kind is None:
        return
    if kind != "file":
        raise TargetError(f"{path}: is a {kind}, not a regular file (only regular files are written or replaced)")
    if not overwrite:
        raise TargetExistsError(f"{path}: exists")


def check_folder(folder: str | Path) -> None:
    """TargetError unless files can be written in ``folder``: it, or the nearest of its
    ancestors that exists (the folders below are made), is a folder this process may write."""
    here = Path(folder)
    while not here.exists() and here != here.parent:
        here = here.parent
    if not here.is_dir():
        made = "" if here == Path(folder) else f", so the folder {folder} cannot be made"
        raise TargetError(f"{here}: is not a folder{made}")
    if not os.access(here, os.W_OK | os.X_OK):
        raise TargetError(f"{here}: folder not writable (permission denied)")


def stale_temp_files(path: str | Path) -> list[Path]:
    """Leftover temporary files of earlier writes of ``path`` (from killed processes)."""
    path = Path(path)
    if not path.parent.is_dir():
        return []
    return sorted(path.parent.glob(f".{path.name}.*{TMP_SUFFIX}"))


def _new_temp(path: Path, kind: str = "") -> Path:
    """A new empty hidden file beside ``path`` (``.<name>.<random><kind>.tmp``), made with
    O_EXCL so that it is this process's own."""
    while True:
        tmp = path.parent / f".{path.name}.{secrets.token_hex(6)}{kind}{TMP_SUFFIX}"
        try:
            os.close(os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600))
            return tmp
        except FileExistsError:
            continue


def _fresh_temp(path: Path) -> Path:
    """A temporary file beside ``path`` after the leftovers of killed writes are removed."""
    for stale in stale_temp_files(path):
        stale.unlink(missing_ok=True)
    return _new_temp(path)


def atomic_write(path: str | Path, write: Callable[[Path], None]) -> Path:
    """Call ``write(tmp)`` on a temporary file beside ``path`` and rename it onto ``path``
    when ``write`` succeeded; on any failure the temporary file is removed and nothing
    appears at ``path``. TargetError (before ``write`` is called) when ``path`` is not free
    or a regular file. Inside an :class:`AtomicFiles` block of ``path`` the rename waits
    for the block's end."""
    path = Path(path)
    files = _ACTIVE.get()
    if files is not None and path in files.paths:
        return files.stage(path, write)
    check_target(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = _fresh_temp(path)
    try:
        write(tmp)
        os.chmod(tmp, _file_mode())
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return path


class AtomicFiles:
    """Files written as one transaction (module docstring): ``with AtomicFiles(paths) as
    files:`` and write each path with :func:`atomic_write` (or a writer built on it).

    Without ``overwrite`` a path that exists is refused (TargetExistsError); any path that
    is not free or a regular file, or whose folder cannot be written, is refused
    (TargetError): on construction, before any work, and again before the renames. A
    rename replaces an overwritten file only after a hard link keeps its content, so a
    failure between two renames puts back every path as it was (on a file system without
    hard links an overwritten file keeps its new content then)."""

    def __init__(self, paths: Sequence[str | Path], overwrite: bool = False) -> None:
        self.paths = [Path(p) for p in paths]
        if len(set(self.paths)) != len(self.paths):
            raise ValueError(f"AtomicFiles: a path is given twice in {[str(p) for p in self.paths]}")
        self.overwrite = overwrite
        self._staged: dict[Path, Path] = {}
        self._made: list[Path] = []
        self._token: contextvars.Token | None = None
        self.check()

    def check(self) -> None:
        """TargetError naming the first path that may not be written."""
        for p in self.paths:
            check_target(p, self.overwrite)
            check_folder(p.parent)

    def stage(self, path: Path, write: Callable[[Path], None]) -> Path:
        """``write(tmp)`` on the temporary file of ``path`` (renamed at the block's end)."""
        if path in self._staged:
            raise ValueError(f"AtomicFiles: {path} is written twice")
        self._make_folder(path.parent)
        self._staged[path] = tmp = _fresh_temp(path)
        write(tmp)
        os.chmod(tmp, _file_mode())
        return path

    def _make_folder(self, folder: Path) -> None:
        """Make ``folder`` and the missing ones above it, remembering them for discard()."""
        missing = []
        while not folder.exists() and folder != folder.parent:
            missing.append(folder)
            folder = folder.parent
        for f in reversed(missing):
            f.mkdir()
            self._made.append(f)

    def commit(self) -> None:
        """Rename every temporary file onto its path; on a failure (or an interruption) the
        renamed paths are put back as they were, the temporaries removed, and the exception
        raised."""
        done: list[tuple[Path, Path, bool, Path | None]] = []  # (path, temporary, existed, link to it)
        try:
            unwritten = [str(p) for p in self.paths if p not in self._staged]
            if unwritten:
                raise ValueError(f"AtomicFiles: not written: {', '.join(unwritten)}")
            self.check()
            for p in self.paths:
                existed = p.exists()
                done.append((p, self._staged[p], existed, _new_link(p) if existed else None))
                os.replace(self._staged[p], p)
        except BaseException:
            for p, tmp, existed, kept in reversed(done):
                if not tmp.exists():  # renamed onto p: put back what was there
                    if kept is not None:
                        os.replace(kept, p)
                        kept = None
                    elif not existed:
                        p.unlink(missing_ok=True)
                if kept is not None:
                    kept.unlink(missing_ok=True)
            self.discard()
            raise
        for *_, kept in done:
            if kept is not None:
                kept.unlink(missing_ok=True)
        self._staged.clear()
        self._made.clear()

    def discard(self) -> None:
        """Remove the temporary files and the folders made for them (when empty)."""
        for tmp in self._staged.values():
            tmp.unlink(missing_ok=True)
        self._staged.clear()
        for folder in reversed(self._made):
            try:
                folder.rmdir()
            except OSError:
                pass
        self._made.clear()

    def __enter__(self) -> AtomicFiles:
        self._token = _ACTIVE.set(self)
        return self

    def __exit__(self, exc_type, exc, tb) -> None:
        _ACTIVE.reset(self._token)
        if exc_type is None:
            self.commit()
        else:
            self.discard()


def _new_link(path: Path) -> Path | None:
    """A hard link to ``path`` beside it (``.<name>.<random>.kept.tmp``); None where the
    file system has no hard links (the earlier content cannot be put back then)."""
    while True:
        link = path.parent / f".{path.name}.{secrets.token_hex(6)}.kept{TMP_SUFFIX}"
        try:
            os.link(path, link)
            return link
        except FileExistsError:
            continue
        except OSError:
            return None
