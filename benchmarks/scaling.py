"""Cost growth of each method with the size of its input: fit and main query timed at 4-5
sizes, the exponent k of time ~ N^k fitted by least squares on log-log axes, a table and
a log-log figure.

What grows (N), and what is timed (fit; main query):

- FPCA (Du Eq. 3.3-3.5), N clips: ``FPCA(20).fit``; transform + back-project 10 clips.
- SFPCA (Du Eq. 3.8), N clips: one objective + gradient evaluation, the cost of one
  L-BFGS-B iteration (the iteration count does not grow with N); the query as FPCA's.
- GMM (Du Sec. 4.4.1), N latent samples: EM with K = 8 full covariances, 20 iterations;
  log-density of 2,000 samples.
- universal Kriging (Ma Sec. 6.1), N examples: ``UniversalKriging().fit`` (variogram,
  bordered inverse); ``predict`` at 100 styles.
- idle posture PCA (Egges Sec. 3.2), N clips of ~60 frames: ``PosturePCA.fit``; project
  and reconstruct one clip.
- k-means tree (Du Sec. 4.4.2), N GMM samples: the tree build; one beam-2 search.
- idle synthesis (Egges Sec. 5.4-6), N frames: (database built once) generate N frames.

The inputs are self-contained (random smooth clips on the CMU rig, Gaussian latent
samples, a synthetic idle recording): what is measured is cost, which depends on the
sizes only. ``k`` is fitted over all sizes, ``k_last`` over the two largest (the growth
where the leading term dominates, e.g. the Kriging fit's cubic solve). Times are CPU
seconds of this process (``time.process_time``, single-threaded BLAS), the best of
``--repeats``, so that a loaded machine inflates them less than wall time. The "required"
column says what growth the algorithm itself implies; a measured k well above it points
at an implementation cost worth a look.

    python benchmarks/scaling.py [--out benchmarks/out] [--repeats 3]
    python benchmarks/scaling.py --quick          # tiny sizes, seconds (the test uses it)
    python benchmarks/scaling.py --only kriging,kmeans_tree
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # one core, before numpy loads its BLAS

import argparse  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from collections.abc import Callable  # noqa: E402
from dataclasses import dataclass  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

OUT = Path(__file__).resolve().parent / "out"


@dataclass
class Case:
    """One method: its sizes, a setup ``prepare(N) -> state`` (not timed), and the timed
    ``fit(state)`` and ``query(state, fitted)`` (``fit`` returns what ``query`` needs)."""

    name: str
    unit: str
    sizes: tuple[int, ...]
    quick: tuple[int, ...]
    prepare: Callable
    fit: Callable | None
    query: Callable | None
    required_fit: str
    required_query: str


# ---- inputs -----------------------------------------------------------------------------
def random_clips(n: int, seed: int = 0, frames=(50, 70)):
    """Smooth clips on the CMU rig (benchmarks/fda_sfpca.py's inputs, imported from there)."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    try:
        from fda_sfpca import random_clips as fda_random_clips
    finally:
        sys.path.pop(0)
    return fda_random_clips(n, seed, frames)


_CLIPS: dict[int, list] = {}


def clips(n: int) -> list:
    """The first ``n`` of one pool of random clips (made once, grown on demand)."""
    have = max(_CLIPS, default=0)
    if n > have:
        _CLIPS.clear()
        _CLIPS[n] = random_clips(n)
        return _CLIPS[n]
    return _CLIPS[have][:n]


def functional(n: int):
    from motionvar.du2022.fda import FunctionalMotions

    return FunctionalMotions.from_motions(clips(n), n_basis=10)


# ---- the methods ------------------------------------------------------------------------
def _fpca_fit(fd):
    from motionvar.du2022.fda import FPCA

    return FPCA(20).fit(fd)


def _fpca_query(fd, model):
    return model.inverse_transform(model.transform(fd.coefs[:10]))


def _sfpca_fit(fd):
    import torch

    from motionvar.du2022.fda.sfpca import ObservationObjective

    torch.set_num_threads(1)
    objective = ObservationObjective(fd, 20, n_eval_frames=20)
    objective.value_and_grad(np.ones(fd.layout.n_functions))
    return _fpca_fit(fd)  # the query projects as FPCA does (same cost, other weights)


def _gmm_prepare(n: int):
    rng = np.random.default_rng(0)
    centres = rng.normal(scale=3.0, size=(8, 20))
    return centres[rng.integers(0, 8, size=n)] + rng.normal(size=(n, 20))


def _gmm_fit(x):
    from sklearn.exceptions import ConvergenceWarning
    from sklearn.mixture import GaussianMixture

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        return GaussianMixture(8, covariance_type="full", max_iter=20, tol=0.0, random_state=0).fit(x)


def _gmm_query(x, gmm):
    return gmm.score_samples(_gmm_prepare(2000))


def _kriging_prepare(n: int):
    rng = np.random.default_rng(0)
    x = rng.uniform(size=(n, 3))
    y = np.sin(x @ rng.normal(size=(3, 60)) * 3) + 0.05 * rng.normal(size=(n, 60))
    return x, y


def _kriging_fit(data):
    from motionvar.ma2010.kriging import UniversalKriging

    return UniversalKriging("auto", variogram_scale="sd").fit(*data)  # config ma2010's defaults


def _kriging_query(data, model):
    return model.predict(np.random.default_rng(1).uniform(size=(100, 3)))


def _pca_fit(motions):
    from motionvar.egges2004 import Egges2004Settings, PosturePCA

    return PosturePCA(Egges2004Settings().translation_scale).fit(motions)


def _pca_query(motions, pca):
    return pca.to_rotations(pca.project(motions[0]))


def _tree_fit(x):
    from motionvar.du2022.graph.trees import SpacePartitioningTree

    return SpacePartitioningTree(x, kind="kmeans", leaf_size=16, seed=0)


def _tree_query(x, tree):
    target = x[len(x) // 3] + 0.1
    return tree.search(lambda s: ((s - target) ** 2).sum(axis=1), beam=2)


_IDLE: dict = {}


def _idle_prepare(n: int):
    """A one-subject idle database from two synthetic recordings (built once)."""
    if not _IDLE:
        from motionvar.core import cmu_joint_map
        from motionvar.egges2004 import Egges2004Settings, PosturePCA, analyse_recording, build_database
        from motionvar.synth.idle import IdleParams, generate_idle
        from motionvar.synth.subjects import make_subjects

        subject = make_subjects(1, seed=0)[0]
        rng = np.random.default_rng(0)
        recs = [
            generate_idle(subject, IdleParams(duration_s=40.0, heading_deg=90.0, start_xz=(0.0, 0.0)), rng)[0]
            for _ in range(2)
        ]
        settings = Egges2004Settings()
        pca = PosturePCA(settings.translation_scale).fit(recs)
        db = build_database(
            [analyse_recording(m, pca, cmu_joint_map(), f"clip{i}") for i, m in enumerate(recs)],
            pca,
            settings.analysis,
            subject.subject_id,
            settings.seed,
        )
        _IDLE.update(db=db, pca=pca)
    return n


def _idle_query(n, _):
    from motionvar.egges2004.evaluations.speed import generation_seconds

    return generation_seconds(_IDLE["db"], _IDLE["pca"], int(n), seed=1, repeats=1)


CASES = [
    Case(
        "fpca",
        "clips",
        (100, 200, 400, 800, 1600),
        (20, 40, 80),
        functional,
        _fpca_fit,
        _fpca_query,
        "linear in N: covariance of the P = K*D coefficients O(N P^2) + its eigendecomposition O(P^3); "
        "the SVD used (scikit-learn PCA, svd_solver='full') costs O(N P min(N, P)): quadratic below N = P",
        "O(1) in N: a projection per clip",
    ),
    Case(
        "sfpca",
        "clips",
        (100, 200, 400, 800, 1600),
        (20, 40, 80),
        functional,
        _sfpca_fit,
        _fpca_query,
        "per L-BFGS-B iteration O(N T J) forward kinematics + O(min(N, K Da)^3) eigendecomposition: "
        "linear in N once N > K Da, up to cubic below",
        "O(1) in N (as FPCA)",
    ),
    Case(
        "gmm",
        "samples",
        (1000, 2000, 4000, 8000, 16000),
        (200, 400, 800),
        _gmm_prepare,
        _gmm_fit,
        _gmm_query,
        "O(N K d^2) per EM iteration: linear",
        "O(1) in N (K d^2 per sample)",
    ),
    Case(
        "kriging",
        "examples",
        (50, 100, 200, 400, 800),
        (10, 20, 40),
        _kriging_prepare,
        _kriging_fit,
        _kriging_query,
        "O(N^3) once (inverse of the bordered N+1 system) + O(N^2) variogram pairs",
        "O(N) per query with the dual weights R^-1 r; O(N^2) as implemented (query row times the N+1 inverse)",
    ),
    Case(
        "egges_pca",
        "clips",
        (25, 50, 100, 200, 400),
        (5, 10, 20),
        clips,
        _pca_fit,
        _pca_query,
        "O(F D^2) for F = ~60 N frames: linear",
        "O(1) in N: one clip's frames",
    ),
    Case(
        "kmeans_tree",
        "samples",
        (1000, 2000, 4000, 8000, 16000),
        (200, 400, 800),
        _gmm_prepare,
        _tree_fit,
        _tree_query,
        "O(N log N): k-means over all samples at each of log4(N) levels",
        "O(log N): beam x children evaluations per level",
    ),
    Case(
        "idle_synthesis",
        "frames",
        (1000, 2000, 4000, 8000, 16000),
        (250, 500, 1000),
        _idle_prepare,
        None,
        _idle_query,
        "-",
        "O(N): a constant cost per frame",
    ),
]


def timed(fn, *args, repeats: int) -> tuple[float, object]:
    """Best CPU seconds of ``repeats`` calls, and the last result."""
    best, out = np.inf, None
    for _ in range(repeats):
        start = time.process_time()
        out = fn(*args)
        best = min(best, time.process_time() - start)
    return best, out


def exponent(sizes, seconds) -> float:
    """k of seconds ~ sizes^k by least squares on log-log axes (NaN with under 2 points)."""
    x, y = np.log(np.asarray(sizes, dtype=float)), np.log(np.maximum(np.asarray(seconds, dtype=float), 1e-9))
    ok = np.isfinite(y)
    return float(np.polyfit(x[ok], y[ok], 1)[0]) if ok.sum() >= 2 else float("nan")


def measure(cases, quick: bool, repeats: int, log=print) -> tuple[pd.DataFrame, pd.DataFrame]:
    """(timings: one row per method, stage and size; exponents: one row per method and stage)."""
    rows = []
    for case in cases:
        sizes = case.quick if quick else case.sizes
        state = case.prepare(sizes[0])  # warm-up, untimed: imports and first-call costs
        fitted = case.fit(state) if case.fit is not None else None
        if case.query is not None:
            case.query(state, fitted)
        for n in sizes:
            state = case.prepare(n)
            fitted = None
            if case.fit is not None:
                t, fitted = timed(case.fit, state, repeats=repeats)
                rows.append({"method": case.name, "stage": "fit", "unit": case.unit, "n": n, "cpu_s": t})
            if case.query is not None:
                t, _ = timed(case.query, state, fitted, repeats=repeats)
                rows.append({"method": case.name, "stage": "query", "unit": case.unit, "n": n, "cpu_s": t})
            log(
                f"  {case.name:15s} N = {n:6d}: "
                + ", ".join(
                    f"{r['stage']} {r['cpu_s']:.4f} s" for r in rows if r["method"] == case.name and r["n"] == n
                )
            )
    timings = pd.DataFrame(rows)
    out = []
    for case in cases:
        for stage, required in (("fit", case.required_fit), ("query", case.required_query)):
            t = timings[(timings["method"] == case.name) & (timings["stage"] == stage)]
            if len(t):
                out.append(
                    {
                        "method": case.name,
                        "stage": stage,
                        "unit": case.unit,
                        "sizes": f"{t['n'].min()}-{t['n'].max()}",
                        "k": exponent(t["n"], t["cpu_s"]),
                        "k_last": exponent(t["n"].iloc[-2:], t["cpu_s"].iloc[-2:]),
                        "cpu_s_largest": float(t["cpu_s"].iloc[-1]),
                        "required": required,
                    }
                )
    return timings, pd.DataFrame(out)


def draw(timings: pd.DataFrame, exponents: pd.DataFrame, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharey=False)
    for ax, stage in zip(axes, ("fit", "query")):
        for method, t in timings[timings["stage"] == stage].groupby("method", sort=False):
            k = exponents[(exponents["method"] == method) & (exponents["stage"] == stage)]["k"].iloc[0]
            ax.loglog(t["n"], t["cpu_s"], "o-", label=f"{method} (k = {k:.2f})")
        ax.set_title(f"{stage}: CPU seconds vs size N (log-log)")
        ax.set_xlabel("N (clips, samples, examples or frames; see the legend's method)")
        ax.set_ylabel("CPU s (best of repeats)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", type=Path, default=OUT, help="folder for scaling.csv, scaling_exponents.csv, scaling.png")
    ap.add_argument("--repeats", type=int, default=None, help="best of this many (default 3, 1 with --quick)")
    ap.add_argument("--quick", action="store_true", help="tiny sizes: seconds, for the test")
    ap.add_argument(
        "--only", default="", help="comma-separated methods (default all: " + ", ".join(c.name for c in CASES) + ")"
    )
    args = ap.parse_args(argv)
    wanted = [s for s in args.only.split(",") if s]
    unknown = sorted(set(wanted) - {c.name for c in CASES})
    if unknown:
        print(f"scaling: unknown method(s) {unknown}; choose from {[c.name for c in CASES]}", file=sys.stderr)
        return 1
    cases = [c for c in CASES if not wanted or c.name in wanted]
    repeats = args.repeats or (1 if args.quick else 3)
    start = time.perf_counter()
    timings, exponents = measure(cases, args.quick, repeats)
    args.out.mkdir(parents=True, exist_ok=True)
    timings.to_csv(args.out / "scaling.csv", index=False, float_format="%.6g")
    exponents.to_csv(args.out / "scaling_exponents.csv", index=False, float_format="%.4g")
    draw(timings, exponents, args.out / "scaling.png")
    with pd.option_context("display.max_colwidth", 90, "display.width", 250):
        print(exponents.to_string(index=False, float_format=lambda v: f"{v:.3g}"))
    print(f"{time.perf_counter() - start:.0f} s; written {args.out}/scaling.csv, scaling_exponents.csv, scaling.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
