"""What every ``motionvar`` subcommand shares: where a dataset's model files lie, the
one-line error for a missing or unreadable model (naming the Snakemake target that builds
it) or an argument out of range, the dataset's rig for the output, and writing the BVH
files as one transaction (:class:`motionvar.io.atomic.AtomicFiles`): all of them or none,
and no file that existed replaced without ``--force``."""

from __future__ import annotations

import argparse
import csv
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TypeVar

import numpy as np

from ..core.motion import Motion
from ..core.skeleton import Skeleton
from ..io.atomic import AtomicFiles, TargetError, TargetExistsError
from ..io.bvh import write_bvh
from ..io.model_file import exception_line
from ..io.units import unit_cm_problem

DATA_CLIPS = "data/clips.npz"  # the dataset's packed clips: its rig's channel layout
APPLICABILITY = "applicability.csv"  # the run's applicability table of the dataset
MAX_SEED = 2**32 - 1  # --seed: 0 to this (numpy's and torch's generators take every one)
MAX_REASON_CHARS = 300  # of a loader's message quoted in an error line
T = TypeVar("T")


class CLIError(Exception):
    """A user-facing error: printed as one line on stderr, exit status 2."""


class UnreadableFile(CLIError):
    """A file of the run that exists but cannot be read: names it and the Snakemake target
    that rebuilds it."""

    def __init__(self, what: str, path: Path, target: str, reason: str) -> None:
        self.path, self.target = path, target
        super().__init__(f"{what} cannot be read: {reason}; rebuild it with `snakemake --cores 2 --force {target}`")


def _reason(exc: BaseException, path: Path) -> str:
    """A loader's exception as one short line that names the file."""
    text = exception_line(exc)
    if str(path.with_suffix("")) not in text:
        text = f"{path}: {text}"
    return text if len(text) <= MAX_REASON_CHARS else text[: MAX_REASON_CHARS - 3] + "..."


@dataclass(frozen=True)
class ResultsDir:
    """``<results>/<dataset>``: the dataset's outputs of a pipeline run."""

    results: Path
    dataset: str

    @property
    def root(self) -> Path:
        return self.results / self.dataset

    def model(self, relative: str) -> Path:
        """A file under ``models/`` (``relative`` like ``ma2010/style_variation.npz``)."""
        return self.root / "models" / relative

    def target(self, path: Path) -> str:
        """The Snakemake target of a file of this dataset (relative to the workflow's
        working directory, where results/ lives)."""
        return f"results/{self.dataset}/{path.relative_to(self.root).as_posix()}"

    def check_dataset(self) -> None:
        """CLIError when the results folder holds nothing of the dataset."""
        if not self.root.is_dir():
            have = sorted(p.name for p in self.results.iterdir() if p.is_dir()) if self.results.is_dir() else []
            where = f"datasets there: {', '.join(have)}" if have else "no datasets there"
            raise CLIError(
                f"no results for dataset {self.dataset!r} in {self.results} ({where}); run "
                f"`snakemake --cores 2` first, or pass --results DIR"
            )

    def load(self, what: str, loader: Callable[[Path], T], path: Path) -> T:
        """``loader(path)`` behind the one error boundary of the commands' reads: whatever
        reading a file of the run raises (truncated or garbled .npz/.pt/.json/.csv, arrays
        or tensors under other names or of other shapes) ends as an UnreadableFile naming
        the file and the Snakemake target that rebuilds it."""
        try:
            return loader(path)
        except CLIError:
            raise
        except Exception as exc:
            raise UnreadableFile(what, path, self.target(path), _reason(exc, path)) from exc

    def unsupported(self, evaluations: Sequence[str]) -> str | None:
        """Why the dataset supports none of ``evaluations`` (whose models a command reads),
        from the run's applicability.csv; None when one is supported or it is not known."""
        path = self.root / APPLICABILITY
        if not evaluations or not path.is_file():
            return None
        rows = self.load("the run's applicability table", _applicability_rows, path)
        found = [rows[e] for e in evaluations if e in rows]
        if not found or any(str(r.get("applicable", "")).strip().lower() == "true" for r in found):
            return None
        reason = str(found[0].get("reason") or "not applicable").strip()
        first, sep, _ = reason.partition("; needs ")  # several unmet needs: the first says enough
        return first + (" (and more: applicability.csv)" if sep else "")

    def require(self, what: str, *relative: str, evaluations: Sequence[str] = ()) -> list[Path]:
        """The model files ``relative`` (under models/); CLIError naming the first missing
        one and the Snakemake target that builds it, or, when the dataset supports none of
        ``evaluations`` (the ones the model is fitted for), why it has no such model."""
        self.check_dataset()
        paths = [self.model(r) for r in relative]
        for p in paths:
            if not p.is_file():
                reason = self.unsupported(evaluations)
                if reason:
                    raise CLIError(
                        f"{what} for dataset {self.dataset!r} is missing ({p}): the dataset does not "
                        f"support it: {reason}"
                    )
                raise CLIError(
                    f"{what} for dataset {self.dataset!r} is missing ({p}): run "
                    f"`snakemake --cores 2 {self.target(paths[0])}` first"
                )
        return paths


def _applicability_rows(path: Path) -> dict[str, dict[str, str]]:
    """evaluation -> row of an applicability.csv (ValueError when it has no such column)."""
    with open(path, newline="", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    if rows and "evaluation" not in rows[0]:
        raise ValueError(f"{path}: no 'evaluation' column")
    return {r["evaluation"]: r for r in rows}


@dataclass(frozen=True)
class RigLayout:
    """A dataset's rig as its packed clips store it (names, parents, BVH channel layout,
    mean end sites): what the output BVH follows."""

    names: tuple[str, ...]
    parents: np.ndarray
    rotation_orders: tuple[str, ...]
    position_channels: tuple[bool, ...]
    end_sites: dict[int, np.ndarray]


def dataset_rig(rd: ResultsDir) -> RigLayout | None:
    """The rig layout of ``<dataset>/data/clips.npz``, or None when that file is absent
    (the models' own skeleton is written then)."""
    path = rd.root / DATA_CLIPS
    if not path.is_file():
        return None
    return rd.load("the dataset's packed clips", _rig_layout, path)


def _rig_layout(path: Path) -> RigLayout:
    """The RigLayout stored in a packed dataset's clips.npz (reads only those arrays)."""
    with np.load(path, allow_pickle=False) as z:
        ends = z["end_site_joints"]
        offsets = z["end_site_offsets"]
        return RigLayout(
            tuple(str(n) for n in z["names"]),
            np.asarray(z["parents"]),
            tuple(str(o) for o in z["rotation_orders"]),
            tuple(bool(p) for p in z["position_channels"]),
            {int(j): offsets[:, k].mean(axis=0) for k, j in enumerate(ends)},
        )


def on_rig(motion: Motion, rig: RigLayout | None) -> Motion:
    """``motion`` with the rig's BVH channel layout (rotation orders, position channels)
    and, where its skeleton has none, the rig's end sites; bone offsets stay the motion's.
    The model's skeleton is the dataset's rig (re-rooted at the hips on import where the
    BVH root is not the pelvis), so the joints agree; CLIError when they do not."""
    if rig is None:
        return motion
    sk = motion.skeleton
    if sk.names != rig.names or not np.array_equal(sk.parents, rig.parents):
        raise CLIError(
            f"the model's skeleton ({sk.n_joints} joints) is not the dataset's rig ({len(rig.names)} joints "
            f"in {DATA_CLIPS}); rerun the pipeline so that models and data agree"
        )
    out = Skeleton(
        names=sk.names,
        parents=sk.parents,
        offsets=sk.offsets,
        end_sites=sk.end_sites if sk.end_sites else rig.end_sites,
        rotation_orders=rig.rotation_orders,
        position_channels=rig.position_channels,
    )
    return replace(motion, skeleton=out)


def check_output_options(args: argparse.Namespace) -> None:
    """CLIError for a --unit-cm outside the range of length units
    (:data:`motionvar.io.units.UNIT_CM_MIN`-``UNIT_CM_MAX``) or a --seed outside 0 to
    :data:`MAX_SEED`; nothing for a command without them."""
    if hasattr(args, "unit_cm"):
        problem = unit_cm_problem(args.unit_cm)
        if problem:
            raise CLIError(f"--unit-cm {args.unit_cm:g}: {problem}")
    if hasattr(args, "seed") and not 0 <= args.seed <= MAX_SEED:
        raise CLIError(f"--seed {args.seed}: a seed is 0 to {MAX_SEED}")


def output_files(paths: Sequence[Path], force: bool) -> AtomicFiles:
    """The command's output files as one transaction, checked now, before any work:
    CLIError naming a file that exists (unless ``force``), a path that is not free or a
    regular file (a folder, symlink, device, named pipe), or a folder that cannot be
    written."""
    try:
        return AtomicFiles(paths, overwrite=force)
    except TargetExistsError as exc:
        others = sum(p.exists() for p in paths) - 1
        more = f" (and {others} more of the {len(paths)} output files)" if others else ""
        raise CLIError(f"{exc}{more}; pass --force to overwrite, or choose another --out") from exc
    except TargetError as exc:
        raise CLIError(str(exc)) from exc


def write_motions(files: AtomicFiles, motions: Sequence[Motion], unit_cm: float = 1.0) -> None:
    """Write each motion as BVH to its path of ``files``, all or none: the files appear
    together when every one is written; on any failure (disk full, permission, Ctrl-C,
    SIGTERM) none does and every path keeps what it had; OSError becomes a CLIError."""
    try:
        with files:
            for path, m in zip(files.paths, motions, strict=True):
                try:
                    write_bvh(path, m, scale=unit_cm)
                except OSError as exc:
                    raise CLIError(f"cannot write {path}: {exc.strerror or exc}; no file written") from exc
    except TargetError as exc:  # a path taken while the command ran
        raise CLIError(f"{exc}; no file written") from exc
    except OSError as exc:  # the renames at the end
        raise CLIError(
            f"cannot put the files in place ({exc.strerror or exc}); every output path is as it was"
        ) from exc


def parse_numbers(text: str, what: str) -> list[float]:
    """Comma-separated numbers; CLIError naming ``what`` otherwise."""
    parts = [t.strip() for t in str(text).split(",")]
    try:
        values = [float(t) for t in parts]
    except ValueError:
        raise CLIError(f"{what}: expected comma-separated numbers; got {text!r}") from None
    if not all(np.isfinite(values)):
        raise CLIError(f"{what}: values must be finite; got {text!r}")
    return values


def at_most(value: float, limit: float, what: str, unit_scope: str) -> None:
    """CLIError ``<what> <value>: at most <limit> <unit_scope>`` (e.g. "--n 100000: at most
    200 samples per command") when ``value`` exceeds ``limit``: a request too large for
    memory or a sitting is refused before anything is loaded."""
    if value > limit:
        raise CLIError(f"{what} {value:g}: at most {limit:g} {unit_scope}")


def positive(value: float, what: str) -> float:
    if not (np.isfinite(value) and value > 0):
        raise CLIError(f"{what} must be > 0; got {value:g}")
    return float(value)


def out_file(path: str, suffix: str = ".bvh") -> Path:
    """An output file path; CLIError if it names a folder or its parent cannot be made."""
    p = Path(path)
    if p.is_dir():
        raise CLIError(f"--out {path}: is a folder; give a file name ending in {suffix}")
    return p


def out_dir(path: str) -> Path:
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise CLIError(f"--out {path}: exists and is not a folder")
    return p


def say(text: str) -> None:
    """A result line on stdout."""
    print(text, file=sys.stdout, flush=True)


def note(text: str) -> None:
    """A remark on stderr."""
    print(text, file=sys.stderr, flush=True)
