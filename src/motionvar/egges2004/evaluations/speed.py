"""Real time (Egges et al. 2004, Sec. 8: idle motions are "generated and played in
real-time"): frames of idle motion generated per second against the playback rate,
timed per stage.
"""

from __future__ import annotations

import os
import platform
import time
from typing import Any

import numpy as np
import pandas as pd

from ...claims import EvaluationResult, judge_claims
from ..balance import synthesize_balance
from ..claims import CLAIMS
from ..database import IdleDatabase
from ..pca import PosturePCA
from ..pipeline import IdleModel
from ..settings import Egges2004Settings, SpeedSettings


def generation_seconds(db: IdleDatabase, pca: PosturePCA, n_frames: int, seed: int, repeats: int) -> dict[str, float]:
    """Mean wall time (s) over ``repeats`` runs to generate ``n_frames`` frames of idle motion,
    per stage: balance shifting (Sec. 5.4), small variations (Sec. 6), PC values -> joint
    rotations and root translation (Sec. 3.2, the per-frame exponential maps), and the total of
    the three (Sec. 8's real-time claim)."""
    if repeats < 1:
        raise ValueError(f"egges2004.speed.repeats must be >= 1; got {repeats}")
    times = np.zeros((repeats, 3))
    for r in range(repeats):
        rng = np.random.default_rng(seed + r)
        t0 = time.perf_counter()
        pcs, _ = synthesize_balance(db, n_frames, rng)
        t1 = time.perf_counter()
        pcs = np.array(pcs, copy=True)
        pcs[:, db.variations.pcs] += db.variations.generate(n_frames, db.fps, rng)
        t2 = time.perf_counter()
        pca.to_rotations(pcs)
        t3 = time.perf_counter()
        times[r] = t1 - t0, t2 - t1, t3 - t2
    mean = dict(zip(("balance", "variations", "reconstruct"), map(float, times.mean(axis=0))))
    return {**mean, "total": float(times.sum(axis=1).mean())}


def machine() -> dict[str, Any]:
    """The hardware the timings ran on: the CPU model (``/proc/cpuinfo`` where there is one, else
    :func:`platform.processor`), the logical cores of the machine and those this process may use."""
    cpu = ""
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next((line.split(":", 1)[1].strip() for line in f if line.startswith("model name")), "")
    except OSError:
        pass
    usable = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    return {
        "cpu": cpu or platform.processor() or platform.machine() or "unknown CPU",
        "cores": os.cpu_count() or 0,
        "usable_cores": usable or 0,
    }


def speed(model: IdleModel, settings: Egges2004Settings) -> EvaluationResult:
    """Frames generated per second (balance + variations + PC -> rotations, mean time over
    ``repeats`` runs) against the playback rate, per subject (``settings.speed``,
    ``settings.seed``), on the hardware of :func:`machine`. Returns the table, the claim, for the
    figure ``sequence_s`` and ``cpu``, and the measurements (:func:`speed_measurements`)."""
    params, seed = settings.speed, settings.seed
    rows = []
    for s in list(model.databases)[: params.subjects or None]:
        db = model.databases[s]
        n = int(round(params.sequence_s * db.fps)) + 1
        t = generation_seconds(db, model.pca, n, seed, params.repeats)
        rows.append(
            {
                "subject": s,
                "frames": n,
                "playback_fps": db.fps,
                **{f"{k}_s": v for k, v in t.items()},
                "frames_per_second": n / t["total"],
                "realtime_ratio": n / t["total"] / db.fps,
            }
        )
    table = pd.DataFrame(rows)
    hardware = machine()
    measurements = speed_measurements(table, params, hardware)
    figure = {"sequence_s": params.sequence_s, "cpu": hardware["cpu"]}
    return EvaluationResult(table, judge_claims(CLAIMS, "egges2004_speed", measurements), figure, measurements)


def speed_measurements(table: pd.DataFrame, params: SpeedSettings, hardware: dict[str, Any]) -> dict[str, Any]:
    """What Sec. 8's real-time claim is judged on: the slowest subject's frames per second and its
    multiple of the playback rate, the playback rate, the sequence length, the runs averaged and
    the hardware (:func:`machine`)."""
    return {
        "min_realtime_ratio": float(table["realtime_ratio"].min()),
        "min_frames_per_second": float(table["frames_per_second"].min()),
        "playback_fps": float(table["playback_fps"].iloc[0]),
        "sequence_s": params.sequence_s,
        "repeats": params.repeats,
        **hardware,
    }
