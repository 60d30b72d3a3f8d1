"""Ma et al. 2010 Sec. 8: seconds of computation per second of synthesized motion, for a
long walking sequence from the model of all walking cycles (sampling xi, four SVIs,
inverse time warp, transitions, footskate cleanup), on one core, averaged over runs as the
paper's "on average", with the CPU it ran on."""

from __future__ import annotations

import os
import platform
import time
from collections.abc import Callable

import numpy as np
import pandas as pd

from ...claims import EvaluationResult, judge_claims
from ..claims import CLAIMS, PUBLISHED_SECONDS_PER_SECOND
from ..examples import WalkCycles
from ..settings import Ma2010Settings
from ..svi import StyleVariationModel
from ..synthesis import RootSolver, sequence_motion


def cpu_model(cpuinfo: str = "/proc/cpuinfo") -> str:
    """The CPU's model name (``model name`` of ``cpuinfo`` on Linux, else what :mod:`platform`
    says; "unknown CPU" when neither names it)."""
    try:
        with open(cpuinfo, encoding="utf-8", errors="replace") as f:
            for line in f:
                if line.lower().startswith("model name") and ":" in line:
                    return " ".join(line.split(":", 1)[1].split())
    except OSError:
        pass
    return platform.processor() or platform.machine() or "unknown CPU"


def synthesis_seconds_per_second(
    model: StyleVariationModel,
    style: np.ndarray,
    solver: RootSolver,
    seconds: float,
    repeats: int,
    seed: int,
    clock: Callable[[], float] = time.perf_counter,
) -> tuple[np.ndarray, float]:
    """Sec. 8: computation time per second of synthesized motion for a sequence of about
    ``seconds`` s (xi sampling, SVI, inverse time warp, transitions, footskate cleanup), in
    each of ``repeats`` runs (run ``r`` draws xi with seed ``seed + r``). Returns ((repeats,)
    seconds per second, motion seconds of the last run)."""
    mean_cycle = float(np.mean(model.key_times_span_))
    n = max(int(np.ceil(seconds / mean_cycle)), 1)
    runs, length = [], 0.0
    for r in range(repeats):  # timing repeats
        rng = np.random.default_rng(seed + r)
        t0 = clock()
        pred, _ = model.synthesize_clips(np.tile(np.atleast_2d(style), (n, 1)), rng=rng)
        motion = sequence_motion(
            pred.rotations, pred.key_times, model.reference_keys_, solver, model.fps_, pred.root_height
        )
        elapsed = clock() - t0
        length = motion.duration
        runs.append(elapsed / max(length, 1e-9))
    return np.asarray(runs), length


def sec8_timing(
    walks: WalkCycles,
    model: StyleVariationModel,
    settings: Ma2010Settings,
    clock: Callable[[], float] = time.perf_counter,
) -> EvaluationResult:
    """Sec. 8 for ``model`` fitted to ``walks``: about ``settings.sec8.seconds`` s of
    walking at the median stride (xi seeded by ``settings.seed``), the mean of
    ``settings.sec8.repeats`` timings (the paper: "on average"), against the published
    0.15 s per s (measurements ``seconds_per_second``, ``sd_seconds_per_second``,
    ``motion_seconds``, ``example_cycles``, ``repeats``, ``cpu``: :func:`cpu_model`,
    ``logical_cores``). Figure: ``seconds_per_second``, ``motion_seconds``, ``n_cycles``."""
    style = np.median(walks.clips.style, axis=0)
    repeats = settings.sec8.repeats
    runs, length = synthesis_seconds_per_second(
        model, style, walks.solver, settings.sec8.seconds, repeats, settings.seed, clock
    )
    sps, sd = float(runs.mean()), float(runs.std(ddof=1)) if len(runs) > 1 else 0.0
    cpu, cores = cpu_model(), os.cpu_count() or 0
    n_cycles = walks.clips.n_clips
    table = pd.DataFrame(
        [
            {
                "example_cycles": n_cycles,
                "subjects": len(set(walks.subjects)),
                "frames_per_cycle": walks.clips.n_frames,
                "motion_seconds": length,
                "seconds_per_second": sps,
                "sd_seconds_per_second": sd,
                "runs": repeats,
                "min_seconds_per_second": float(runs.min()),
                "max_seconds_per_second": float(runs.max()),
                "times_faster_than_real_time": 1.0 / sps,
                "paper_seconds_per_second": PUBLISHED_SECONDS_PER_SECOND,
                "ratio_to_paper": sps / PUBLISHED_SECONDS_PER_SECOND,
                "cpu": cpu,
                "logical_cores": cores,
            }
        ]
    )
    measurements = {
        "seconds_per_second": sps,
        "sd_seconds_per_second": sd,
        "motion_seconds": float(length),
        "example_cycles": n_cycles,
        "repeats": repeats,
        "cpu": cpu,
        "logical_cores": cores,
    }
    figure = {
        "seconds_per_second": sps,
        "motion_seconds": length,
        "n_cycles": n_cycles,
        "published_seconds_per_second": PUBLISHED_SECONDS_PER_SECOND,
    }
    return EvaluationResult(table, judge_claims(CLAIMS, "ma2010_sec8", measurements), figure, measurements)
