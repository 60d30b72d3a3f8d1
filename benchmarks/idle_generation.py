"""Idle-motion generation speed (Egges et al. 2004, Sec. 8: "generated and played in
real-time"), printed as ratios against baselines measured in the same run:

1. frames generated per second by the personalised engine (balance shifting + small
   variations + PC values -> joint rotations), and its ratio to the playback rate
   (the recordings' frame rate);
2. the same for the Perlin-noise-on-PCs baseline (Sec. 6) and the ratio engine / Perlin;
3. the share of each stage in the engine's time.

The database is built from synthetic idle recordings of one subject
(motionvar.synth.idle, self-contained: no pipeline run needed).

    python benchmarks/idle_generation.py [--seconds 300] [--clips 3] [--clip-seconds 90] [--repeats 3]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from motionvar.core import cmu_joint_map
from motionvar.egges2004 import IdleSettings, PosturePCA, analyse_recording, build_database
from motionvar.egges2004.baselines import perlin_pcs
from motionvar.egges2004.evaluations.sec8_speed import generation_seconds
from motionvar.synth.idle import IdleParams, generate_idle
from motionvar.synth.subjects import make_subjects


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=float, default=300.0, help="length of the generated sequence (s)")
    ap.add_argument("--clips", type=int, default=3, help="recorded idle clips in the database")
    ap.add_argument("--clip-seconds", type=float, default=90.0, help="length of each recorded clip (s)")
    ap.add_argument("--repeats", type=int, default=3, help="best of this many runs")
    args = ap.parse_args()

    subject = make_subjects(1, seed=0)[0]
    rng = np.random.default_rng(0)
    clips = [
        generate_idle(subject, IdleParams(duration_s=args.clip_seconds, heading_deg=90.0, start_xz=(0.0, 0.0)), rng)[0]
        for _ in range(args.clips)
    ]
    fps = clips[0].fps
    pca = PosturePCA.fit(clips)
    t0 = time.perf_counter()
    db = build_database(
        [analyse_recording(m, pca, cmu_joint_map(), f"clip{i}") for i, m in enumerate(clips)],
        pca, IdleSettings(), subject.subject_id,
    )
    print(f"database: {len(db.animations)} balance shifts, categories {db.categories.names}, "
          f"built in {time.perf_counter() - t0:.2f} s")

    n = int(round(args.seconds * fps)) + 1
    stages = generation_seconds(db, pca, n, seed=1, repeats=args.repeats)
    engine_fps = n / stages["total"]

    sds = np.concatenate([pca.project(m) for m in clips]).std(axis=0)[: db.variations.pcs.size]
    base = np.concatenate([pca.project(m) for m in clips]).mean(axis=0)
    perlin = np.inf
    for r in range(args.repeats):
        t0 = time.perf_counter()
        pca.to_rotations(perlin_pcs(base, sds, 0.5, n, fps, seed=r))
        perlin = min(perlin, time.perf_counter() - t0)
    perlin_fps = n / perlin

    print(f"generated {n} frames ({args.seconds:.0f} s at {fps:.0f} fps), best of {args.repeats}")
    print(f"engine : {engine_fps:12,.0f} frames/s = {engine_fps / fps:8.1f} x the playback rate")
    print(f"perlin : {perlin_fps:12,.0f} frames/s = {perlin_fps / fps:8.1f} x the playback rate")
    print(f"engine / perlin speed ratio: {engine_fps / perlin_fps:.2f}")
    for key in ("balance", "variations", "reconstruct"):
        print(f"  {key:12s} {stages[key]:.4f} s ({100 * stages[key] / stages['total']:.0f} %)")


if __name__ == "__main__":
    main()
