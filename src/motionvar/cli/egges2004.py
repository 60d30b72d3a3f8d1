"""``motionvar egges2004``: personalised idle motion (Egges et al. 2004: balance shifts and
small posture variations) of one subject, from the model saved by rule egges2004_model."""

from __future__ import annotations

import argparse
from pathlib import Path

from .common import (
    CLIError,
    ResultsDir,
    at_most,
    dataset_rig,
    note,
    on_rig,
    out_file,
    output_files,
    positive,
    say,
    write_motions,
)
from .progress import Progress

MODEL = "egges2004/idle_model.npz"
MODEL_SETTINGS = "egges2004/idle_model.json"
WHAT = "the Egges 2004 idle model"
EVALUATIONS = ("egges2004_speed", "egges2004_identification", "egges2004_repetition", "egges2004_fitting")
# Most seconds of idle motion one command writes: the motion is generated and written whole
# (600 s at 120 fps: ~0.7 GB peak memory and ~45 s on the CI models).
MAX_SECONDS = 600.0


def add_parser(sub: argparse._SubParsersAction, common) -> None:
    p = sub.add_parser(
        "egges2004",
        parents=[common()],
        help="personalised idle motion (Egges et al. 2004)",
        description="Idle motion of one subject: balance shifts from their category graph and fitted animations "
        "(Sec. 5.4) with small posture variations (Sec. 6), on their own skeleton.",
    )
    p.add_argument(
        "--subject", default=None, help="whose idle motion (default: the first; `motionvar models` lists them)"
    )
    p.add_argument("--seconds", type=float, default=60.0, help=f"length (s; default 60; at most {MAX_SECONDS:g})")
    p.add_argument("--no-variations", action="store_true", help="balance shifts only (leave out Sec. 6)")
    p.add_argument("--out", required=True, help="output BVH file")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    rd = ResultsDir(Path(args.results), args.dataset)
    seconds = positive(args.seconds, "--seconds")
    at_most(seconds, MAX_SECONDS, "--seconds", "s of idle motion per command")
    from ..egges2004.generate import check_subject, idle_motion  # after the checks
    from ..egges2004.storage import load_idle_model

    out = out_file(args.out)
    files = output_files([out], args.force)
    path, _ = rd.require(WHAT, MODEL, MODEL_SETTINGS, evaluations=EVALUATIONS)
    model = rd.load(WHAT, load_idle_model, path)
    subject = args.subject if args.subject is not None else sorted(model.databases)[0]
    try:
        check_subject(model, subject)
    except ValueError as exc:
        raise CLIError(str(exc)) from exc
    fps = model.databases[subject].fps
    if seconds < 1.0 / fps:
        raise CLIError(
            f"--seconds {seconds:g}: shorter than one frame of subject {subject}'s idle motion "
            f"({fps:g} fps: at least {1.0 / fps:.3g} s)"
        )
    if args.subject is None:
        note(f"subject {subject} (the first of {len(model.databases)}; choose with --subject)")
    rig = dataset_rig(rd)
    with Progress("egges2004 idle", 1, enabled=not args.quiet) as bar:
        motion = idle_motion(model, subject, seconds, args.seed, variations=not args.no_variations)
        bar.update(1)
    write_motions(files, [on_rig(motion, rig)], args.unit_cm)
    say(
        f"{out}: {motion.n_frames} frames at {motion.fps:g} fps ({motion.duration:.2f} s), idle motion of subject "
        f"{subject}"
    )
    return 0
