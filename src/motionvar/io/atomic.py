"""Atomic file writes: a file appears at its path complete or not at all.

The content is written to a hidden temporary file beside the target
(``.<name>.<random>.tmp``) and renamed onto it. The file gets an ordinary file's mode
(``0666`` less the umask, 0644 usually — not the private 0600 of ``mkstemp``). A process
killed during a write cannot remove its temporary file; the next write of the same
target removes such leftovers first.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import Callable

TMP_SUFFIX = ".tmp"


def _file_mode() -> int:
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


def stale_temp_files(path: str | Path) -> list[Path]:
    """Leftover temporary files of earlier writes of ``path`` (from killed processes)."""
    path = Path(path)
    if not path.parent.is_dir():
        return []
    return sorted(path.parent.glob(f".{path.name}.*{TMP_SUFFIX}"))


def atomic_write(path: str | Path, write: Callable[[Path], None]) -> Path:
    """Call ``write(tmp)`` on a temporary file beside ``path`` and rename it onto ``path``
    when ``write`` succeeded; on any failure the temporary file is removed and nothing
    appears at ``path``. Leftovers of killed earlier writes of ``path`` are removed first."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    for stale in stale_temp_files(path):
        stale.unlink(missing_ok=True)
    fd, name = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=TMP_SUFFIX)
    os.close(fd)
    tmp = Path(name)
    try:
        write(tmp)
        os.chmod(tmp, _file_mode())
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return path
