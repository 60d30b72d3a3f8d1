"""Synthesis speed of Ma et al. 2010's model (motionvar.ma2010) on one core.

Fits the model to every neutral forward walking cycle of a packed dataset (default
results/synthetic/data: 25 generated subjects with the full config; build it with
`snakemake --cores 2 results/synthetic/data/metadata.csv`), then synthesizes a long walk
at the median stride and prints, per stage and in total, seconds of computation per
second of motion, how many times faster than real time that is, and the ratio to the
paper's 0.15 s per second (Sec. 8). Baseline in the same run: the Kriging weights
solved per query from the bordered system instead of taken from its precomputed inverse
(Sec. 6.1 says to precompute it).

    python benchmarks/ma2010_synthesis.py [--data results/synthetic/data] [--seconds 60] [--repeats 5]
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_var] = "1"  # one core, before numpy loads its BLAS

import argparse  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from scipy.spatial.distance import cdist  # noqa: E402

from motionvar.core import cmu_joint_map  # noqa: E402
from motionvar.io import load_dataset  # noqa: E402
from motionvar.ma2010 import StyleVariationModel, root_solver  # noqa: E402
from motionvar.ma2010.examples import walk_cycles  # noqa: E402
from motionvar.ma2010.settings import Ma2010Settings  # noqa: E402
from motionvar.ma2010.synthesis import realtime_clips, stitch  # noqa: E402

PAPER_SECONDS_PER_SECOND = 0.15


def fit_model(data_dir: Path, n_frames: int):
    jm = cmu_joint_map()
    settings = Ma2010Settings().replace(clips__n_frames=n_frames)  # neutral forward walks, the default variogram
    clips, table = walk_cycles(load_dataset(data_dir), jm, settings, what=str(data_dir))
    sk = clips.skeleton
    model = StyleVariationModel(
        jm.group_indices(sk),
        "lower_first",
        settings.model.variogram_model,
        variogram_scale=settings.model.variogram_scale,
    ).fit(clips)
    return model, clips, root_solver(sk, jm), table["subject"].nunique()


def staged_synthesis(model, style, n_clips, solver, rng) -> tuple[dict[str, float], float]:
    """Seconds per stage and the motion's length (s)."""
    t = {}
    t0 = time.perf_counter()
    c = np.tile(style, (n_clips, 1))
    xi = model.sample_variation(c, rng=rng)
    t1 = time.perf_counter()
    pred = model.predict(c, xi)
    t2 = time.perf_counter()
    clips = realtime_clips(pred.rotations, pred.key_times, model.reference_keys_, model.fps_, pred.root_height)
    t3 = time.perf_counter()
    rot, height = stitch(clips)
    t4 = time.perf_counter()
    motion = solver.motion(rot, model.fps_, height)
    t5 = time.perf_counter()
    t = {
        "sample xi (Eq. 10)": t1 - t0,
        "SVI, 4 groups (Eq. 11)": t2 - t1,
        "inverse time warp": t3 - t2,
        "transitions (Eq. 14-15)": t4 - t3,
        "footskate cleanup": t5 - t4,
    }
    return t, motion.duration


def weights_by_solving(krig, x):
    """Baseline: the bordered system solved for every query instead of its inverse reused."""
    xs = krig._scale(np.atleast_2d(x))
    n = len(krig.x_)
    bordered = np.zeros((n + 1, n + 1))
    bordered[:n, :n] = krig.variogram_(cdist(krig.x_, krig.x_))
    bordered[:n, n] = bordered[n, :n] = 1.0
    rhs = np.concatenate([krig.variogram_(cdist(xs, krig.x_)), np.ones((len(xs), 1))], axis=1)
    return np.linalg.lstsq(bordered, rhs.T, rcond=None)[0].T[:, :n]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--data", type=Path, default=Path("results/synthetic/data"))
    ap.add_argument("--seconds", type=float, default=60.0)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--frames", type=int, default=64, help="frames of the common timeline")
    args = ap.parse_args()
    if not (args.data / "metadata.csv").is_file():
        raise SystemExit(f"{args.data}: no packed dataset; run `snakemake --cores 2 {args.data}/metadata.csv` first")
    model, clips, solver, n_subjects = fit_model(args.data, args.frames)
    style = np.median(clips.style, axis=0)
    n_clips = int(np.ceil(args.seconds / np.mean(model.key_times_span_)))
    print(
        f"model: {clips.n_clips} walking cycles of {n_subjects} subjects, {clips.n_frames} frames each; "
        f"synthesizing {n_clips} cycles"
    )
    best: dict[str, float] = {}
    length = 0.0
    for r in range(args.repeats):
        stages, length = staged_synthesis(model, style, n_clips, solver, np.random.default_rng(r))
        best = {k: min(v, best.get(k, np.inf)) for k, v in stages.items()}
    total = sum(best.values())
    print(f"{length:.1f} s of motion, best of {args.repeats} per stage:")
    for k, v in best.items():
        print(f"  {k:28s} {v / length * 1000:8.3f} ms per s of motion")
    sps = total / length
    print(
        f"total: {sps:.4f} s per s = {1 / sps:.0f}x faster than real time; "
        f"ratio to the paper's {PAPER_SECONDS_PER_SECOND} s per s: {sps / PAPER_SECONDS_PER_SECOND:.3f} "
        f"(target: >= 100x real time -> {'met' if 1 / sps >= 100 else 'NOT met'})"
    )

    codec, krig = model.interpolators_["legs"]
    xi = model.sample_variation(np.tile(style, (n_clips, 1)), rng=np.random.default_rng(0))
    x = np.concatenate([np.tile(style, (n_clips, 1)), xi["legs"][:, None]], axis=1)
    fast = slow = np.inf
    for _ in range(args.repeats):
        t0 = time.perf_counter()
        lam_fast, _ = krig.weights(x)
        t1 = time.perf_counter()
        lam_slow = weights_by_solving(krig, x)
        t2 = time.perf_counter()
        fast, slow = min(fast, t1 - t0), min(slow, t2 - t1)
    print(
        f"Kriging weights of {n_clips} queries, one group: precomputed inverse {fast * 1000:.2f} ms, solved per "
        f"query {slow * 1000:.2f} ms (ratio {slow / fast:.1f}); largest weight difference "
        f"{np.abs(lam_fast - lam_slow).max():.1e}"
    )


if __name__ == "__main__":
    main()
