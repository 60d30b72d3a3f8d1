"""Progress lines of long loops (fits, training): one ``logging`` line at a steady interval,
so that ``tail -f`` on a rule's log shows the job alive and how long it has left.

A loop makes one :class:`ProgressLog` and calls it once per step (iteration, epoch, fitted
component) with the step's loss::

    progress = ProgressLog("autoencoder epoch", total=300, logger=log)
    for epoch in range(1, 301):
        ...
        progress(epoch, loss)

which logs at INFO, e.g. ``autoencoder epoch 12/300, loss 0.01234, elapsed 20.1 s, remaining
~482 s``: the first step (the rate shows early), then the first step at least
``every_s`` seconds (:data:`EVERY_S` unless given) after the line before, and the last
step (``total``). A loop whose ``total`` is an upper bound (an optimiser's iteration
limit) says ``remaining at most ~``. Logging only: the loop's numbers do not change."""

from __future__ import annotations

import logging
import math
import re
import time

EVERY_S = 10.0  # seconds between two progress lines of one loop

# a progress line: label, step[/total], [loss], elapsed, [remaining]
PROGRESS_LINE = re.compile(
    r"(?P<label>\S.*?) (?P<step>\d+)(?:/(?P<total>\d+))?(?:, loss (?P<loss>\S+))?, elapsed (?P<elapsed>[\d.]+) s"
    r"(?:, remaining (?:at most )?~(?P<remaining>\d+) s)?$"
)


class ProgressLog:
    """Logs ``label k/total, loss x, elapsed s, remaining ~s`` at a steady interval.

    label: names the loop and its step, e.g. "SFPCA L-BFGS-B iteration" (the line reads
    "SFPCA L-BFGS-B iteration 12/200, ..."). total: the number
    of steps (None if unknown). at_most: ``total`` is an upper bound (an iteration limit),
    not the count that will run. every_s: seconds between lines (default :data:`EVERY_S`).
    logger: where to log (default the ``motionvar.progress`` logger)."""

    def __init__(
        self,
        label: str,
        total: int | None = None,
        *,
        at_most: bool = False,
        every_s: float | None = None,
        logger: logging.Logger | None = None,
    ) -> None:
        self.label, self.total, self.at_most = label, total, at_most
        self.every_s = EVERY_S if every_s is None else float(every_s)
        self.logger = logger or logging.getLogger("motionvar.progress")
        self.start = self._last = time.perf_counter()
        self.step = 0
        self.lines = 0

    def __call__(self, step: int | None = None, loss: float | None = None) -> None:
        """Step ``step`` (default: the one after the last) is done, with ``loss``."""
        self.step = self.step + 1 if step is None else int(step)
        now = time.perf_counter()
        if self.lines and now - self._last < self.every_s and self.step != self.total:
            return
        self._last = now
        self.lines += 1
        self.logger.info("%s", self.line(now - self.start, loss))

    def line(self, elapsed: float, loss: float | None) -> str:
        """The progress line after ``elapsed`` seconds at the current step."""
        parts = [f"{self.label} {self.step}" + (f"/{self.total}" if self.total else "")]
        if loss is not None and math.isfinite(loss):
            parts.append(f"loss {loss:.6g}")
        parts.append(f"elapsed {elapsed:.1f} s")
        if self.total and self.step:
            remaining = elapsed / self.step * max(self.total - self.step, 0)
            parts.append(f"remaining {'at most ' if self.at_most else ''}~{remaining:.0f} s")
        return ", ".join(parts)

    def scipy_callback(self):
        """A scipy.optimize.minimize callback (``intermediate_result`` form) that logs each
        iteration's objective."""

        def callback(intermediate_result) -> None:
            self(loss=float(intermediate_result.fun))

        return callback
