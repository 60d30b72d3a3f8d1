"""A small progress bar on stderr (no third-party dependency): redrawn in place on a
terminal, one line per update otherwise (logs, captured output)."""

from __future__ import annotations

import sys
import time
from typing import TextIO


class Progress:
    """``Progress("variants", 3)``; call ``update(done)`` (or use as the ``progress(done,
    total)`` callback of a generate function) and ``close()``. Disabled: does nothing."""

    def __init__(self, label: str, total: int, enabled: bool = True, stream: TextIO | None = None, width: int = 24):
        self.label, self.total, self.enabled, self.width = label, max(int(total), 1), enabled, width
        self.stream = stream if stream is not None else sys.stderr
        self.start = time.perf_counter()
        self.done = 0
        self.tty = bool(getattr(self.stream, "isatty", lambda: False)())
        self._open = False
        if enabled:
            self._draw()

    def _draw(self) -> None:
        filled = int(round(self.width * self.done / self.total))
        bar = "#" * filled + "." * (self.width - filled)
        line = f"{self.label} [{bar}] {self.done}/{self.total} {time.perf_counter() - self.start:5.1f} s"
        if self.tty:
            self.stream.write("\r" + line)
            self._open = True
        else:
            self.stream.write(line + "\n")
        self.stream.flush()

    def __call__(self, done: int, total: int | None = None) -> None:
        self.update(done, total)

    def update(self, done: int, total: int | None = None) -> None:
        if total is not None:
            self.total = max(int(total), 1)
        self.done = min(int(done), self.total)
        if self.enabled:
            self._draw()

    def close(self) -> None:
        if self.enabled and self._open:
            self.stream.write("\n")
            self.stream.flush()
            self._open = False

    def __enter__(self) -> "Progress":
        return self

    def __exit__(self, *exc) -> None:
        self.close()
