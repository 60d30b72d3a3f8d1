"""What every ``motionvar`` subcommand shares: where a dataset's model files lie, the
one-line error for a missing model (naming the Snakemake target that builds it) or an
argument out of range, the dataset's rig for the output, and writing BVH files so that a
failed command leaves none behind."""

from __future__ import annotations

import csv
import sys
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from ..core.motion import Motion
from ..core.skeleton import Skeleton
from ..io.bvh import write_bvh

DATA_CLIPS = "data/clips.npz"  # the dataset's packed clips: its rig's channel layout


class CLIError(Exception):
    """A user-facing error: printed as one line on stderr, exit status 2."""


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

    def unsupported(self, evaluations: Sequence[str]) -> str | None:
        """Why the dataset supports none of ``evaluations`` (whose models a command reads),
        from the run's applicability.csv; None when one is supported or it is not known."""
        path = self.root / "applicability.csv"
        if not evaluations or not path.is_file():
            return None
        with open(path, newline="", encoding="utf-8") as fh:
            rows = {r.get("evaluation"): r for r in csv.DictReader(fh)}
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


def load_or_fail(what: str, loader, *args):
    """``loader(*args)``, with a file that is not a readable model turned into a CLIError."""
    try:
        return loader(*args)
    except (OSError, ValueError, KeyError) as exc:
        raise CLIError(f"{what}: {exc}") from exc


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
    try:
        with np.load(path, allow_pickle=False) as z:  # reads only the arrays named
            ends = z["end_site_joints"]
            offsets = z["end_site_offsets"]
            return RigLayout(
                tuple(str(n) for n in z["names"]),
                np.asarray(z["parents"]),
                tuple(str(o) for o in z["rotation_orders"]),
                tuple(bool(p) for p in z["position_channels"]),
                {int(j): offsets[:, k].mean(axis=0) for k, j in enumerate(ends)},
            )
    except (OSError, ValueError, KeyError) as exc:
        raise CLIError(f"{path}: not a readable packed dataset ({exc})") from exc


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


def write_motions(paths: Sequence[Path], motions: Sequence[Motion], unit_cm: float = 1.0) -> None:
    """Write each motion as BVH (atomic per file); if one fails, the files this call
    already wrote are removed, so a failed command leaves no output."""
    written: list[Path] = []
    try:
        for p, m in zip(paths, motions, strict=True):
            write_bvh(p, m, scale=unit_cm)
            written.append(p)
    except BaseException:
        for p in written:
            p.unlink(missing_ok=True)
        raise


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
