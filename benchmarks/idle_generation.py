"""Idle-motion generation speed (Egges et al. 2004, Sec. 8: "generated and played in
real-time"), printed as ratios against baselines measured in the same run:

1. frames generated per second by the personalised engine (balance shifting + small
   variations + PC values -> joint rotations), and its ratio to the playback rate
   (the recordings' frame rate);
2. the same for the Perlin-noise-on-PCs baseline (Sec. 6) and the ratio engine / Perlin;
3. the share of each stage in the engine's time;
4. the code path of the ``motionvar egges2004`` command (motionvar.egges2004.generate.idle_motion:
   PC values to a Motion on the subject's skeleton, then writing the BVH file) as seconds of
   motion per second of computation, i.e. how many times faster than real time (issue #15
   asks for at least 100 x).

The database is built from synthetic idle recordings of one subject
(motionvar.synth.idle, self-contained: no pipeline run needed); ``--model`` times the
command's path on a model a pipeline run saved instead.

    python benchmarks/idle_generation.py [--seconds 300] [--clips 3] [--clip-seconds 90] [--repeats 3]
    python benchmarks/idle_generation.py --model results/synthetic/models/egges2004/idle_model.npz [--subject 01]
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

from motionvar.core import cmu_joint_map
from motionvar.egges2004 import Egges2004Settings, PosturePCA, analyse_recording, build_database
from motionvar.egges2004.baselines import perlin_pcs
from motionvar.egges2004.evaluations.speed import generation_seconds
from motionvar.egges2004.generate import idle_motion
from motionvar.egges2004.pipeline import IdleModel
from motionvar.egges2004.storage import load_idle_model
from motionvar.io.bvh import write_bvh
from motionvar.synth.idle import IdleParams, generate_idle
from motionvar.synth.subjects import make_subjects


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=float, default=300.0, help="length of the generated sequence (s)")
    ap.add_argument("--clips", type=int, default=3, help="recorded idle clips in the database")
    ap.add_argument("--clip-seconds", type=float, default=90.0, help="length of each recorded clip (s)")
    ap.add_argument("--repeats", type=int, default=3, help="best of this many runs")
    ap.add_argument("--model", default=None, help="time the command's path on this saved idle model (.npz)")
    ap.add_argument("--subject", default=None, help="subject of --model (default: its first)")
    args = ap.parse_args()

    subject = make_subjects(1, seed=0)[0]
    rng = np.random.default_rng(0)
    clips = [
        generate_idle(subject, IdleParams(duration_s=args.clip_seconds, heading_deg=90.0, start_xz=(0.0, 0.0)), rng)[0]
        for _ in range(args.clips)
    ]
    fps = clips[0].fps
    settings = Egges2004Settings()
    pca = PosturePCA(settings.translation_scale).fit(clips)
    t0 = time.perf_counter()
    db = build_database(
        [analyse_recording(m, pca, cmu_joint_map(), f"clip{i}") for i, m in enumerate(clips)],
        pca,
        settings.analysis,
        subject.subject_id,
        settings.seed,
    )
    print(
        f"database: {len(db.animations)} balance shifts, categories {db.categories.names}, "
        f"built in {time.perf_counter() - t0:.2f} s"
    )

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

    if args.model:
        model = load_idle_model(args.model)
        where = args.model
    else:
        sk = clips[0].skeleton
        model = IdleModel(pca, {subject.subject_id: db}, {subject.subject_id: sk}, {}, {})
        where = "the synthetic database above"
    who = args.subject or sorted(model.databases)[0]
    gen = write = np.inf
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(args.repeats):
            t0 = time.perf_counter()
            motion = idle_motion(model, who, args.seconds, seed=r)
            t1 = time.perf_counter()
            write_bvh(Path(tmp) / "idle.bvh", motion)
            gen, write = min(gen, t1 - t0), min(write, time.perf_counter() - t1)
    print(
        f"`motionvar egges2004` path ({where}, subject {who}): {args.seconds:.0f} s of idle motion "
        f"({motion.n_frames} frames at {motion.fps:g} fps), best of {args.repeats}"
    )
    print(f"  generate (idle_motion)   {gen:8.3f} s = {args.seconds / gen:8.0f} x faster than real time")
    print(
        f"  + write the BVH file     {write:8.3f} s = {args.seconds / (gen + write):8.0f} x faster than real time "
        f"(issue #15: >= 100 x)"
    )


if __name__ == "__main__":
    main()
