"""``motionvar ma2010``: style-and-variation walks (Ma et al. 2010, Eq. 10-15) from the
model saved by rule ma2010_model, one BVH per variant."""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

from .common import (
    CLIError,
    ResultsDir,
    at_most,
    dataset_rig,
    note,
    on_rig,
    out_dir,
    output_files,
    parse_numbers,
    positive,
    say,
    write_motions,
)
from .progress import Progress

CLEANUPS = ("root", "root+feet")  # motionvar.ma2010.postprocess.CLEANUPS (not imported: --help stays fast)

MODEL = "ma2010/style_variation.npz"
MODEL_SETTINGS = "ma2010/style_variation.json"
WHAT = "the Ma 2010 style-and-variation model"
EVALUATIONS = ("ma2010_fig6",)  # the model is built where these are supported
# Most seconds of walking (--seconds times --variants) one command writes: every walk is
# predicted and written whole (60 s at 120 fps: ~15 s and ~0.25 GB on the CI models).
MAX_SECONDS = 600.0


def add_parser(sub: argparse._SubParsersAction, common) -> None:
    p = sub.add_parser(
        "ma2010",
        parents=[common()],
        help="style-and-variation walks (Ma et al. 2010)",
        description="Walks of the given style with latent variation drawn from the parameter propagation network "
        "(Eq. 10) once per variant, or fixed with --xi; cycles predicted by Eq. 11-13, joined by "
        "transitions (Eq. 14-15), root from footskate cleanup (Sec. 6.3), by default followed by pinning "
        "the feet in contact with leg IK (Kovar et al. 2002; --cleanup root: the paper's alone). One BVH "
        "per variant.",
    )
    p.add_argument(
        "--style",
        required=True,
        help="the style parameters: the strides (cm) of the left and right support phase; one number "
        "for both or two comma-separated (`motionvar models` shows the range)",
    )
    p.add_argument(
        "--xi",
        default=None,
        help="fix the latent variation of joint groups: A=..,B=..,C=..,D=.. (A legs, B left arm, C right "
        "arm, D upper body; any subset) or 4 numbers A,B,C,D; the others are drawn from Eq. 10",
    )
    p.add_argument(
        "--seconds",
        type=float,
        default=10.0,
        help=f"length of each walk (s; default 10; at most {MAX_SECONDS:g} s over all variants)",
    )
    p.add_argument("--variants", type=int, default=1, help="number of walks, each with its own xi (default 1)")
    p.add_argument(
        "--cleanup",
        choices=CLEANUPS,
        default="root+feet",
        help="footskate cleanup: 'root' the paper's (Sec. 6.3: the support foot is fixed and the root "
        "follows; the other foot of a double support slides, 1-3 cm/s), 'root+feet' (default) that "
        "root, then every foot in contact held still by leg IK (Kovar et al. 2002)",
    )
    p.add_argument("--out", required=True, help="output folder (ma2010_<style>_v<k>.bvh)")
    p.set_defaults(run=run)


def parse_xi(text: str | None) -> dict[str, float]:
    """``A=0.1,B=0.2`` or ``0.1,0.2,0.3,0.4`` (groups A-D in order) -> {key: value};
    CLIError for a key given twice."""
    if not text:
        return {}
    if "=" not in text:
        values = parse_numbers(text, "--xi")
        if len(values) != 4:
            raise CLIError(f"--xi: give 4 numbers (groups A,B,C,D) or KEY=VALUE pairs; got {len(values)} numbers")
        return dict(zip("ABCD", values))
    out = {}
    for part in text.split(","):
        key, sep, value = part.partition("=")
        key = key.strip()
        if not sep or not key:
            raise CLIError(f"--xi: expected KEY=VALUE pairs like A=0.1,B=0.2; got {part!r}")
        if key.upper() in (k.upper() for k in out):
            raise CLIError(f"--xi: {key} is given twice in {text!r}; give each group once")
        out[key] = parse_numbers(value, f"--xi {key}")[0]
    return out


def one_per_group(xi_in: dict[str, float], letters: dict[str, str]) -> None:
    """CLIError when two keys of ``xi_in`` name the same joint group (a letter of
    ``letters`` and the group's name)."""
    groups: dict[str, str] = {}
    for key in xi_in:
        g = letters.get(key.upper(), key)
        if g in groups:
            raise CLIError(f"--xi: {groups[g]} and {key} both set joint group {g}; give each group once")
        groups[g] = key


def min_seconds(model) -> float:
    """The shortest walk: one gait cycle, the longest of the model's example cycles, in s
    rounded up to 0.01 s (as the error line and `motionvar models` give it)."""
    return math.ceil(float(np.max(model.key_times_span_)) * 100) / 100


def run(args: argparse.Namespace) -> int:
    rd = ResultsDir(Path(args.results), args.dataset)
    seconds = positive(args.seconds, "--seconds")
    if args.variants < 1:
        raise CLIError(f"--variants must be >= 1; got {args.variants}")
    at_most(seconds * args.variants, MAX_SECONDS, "--seconds x --variants =", "s of walks per command")
    from ..ma2010.examples import root_solver  # after the checks: a refused request ends at once
    from ..ma2010.generate import GROUP_LETTERS, STRIDE_TOLERANCE, check_style, check_xi, generate_walks
    from ..ma2010.storage import load_style_variation_model

    style_in = parse_numbers(args.style, "--style")
    xi_in = parse_xi(args.xi)
    one_per_group(xi_in, GROUP_LETTERS)
    folder = out_dir(args.out)
    path, _ = rd.require(WHAT, MODEL, MODEL_SETTINGS, evaluations=EVALUATIONS)
    saved = rd.load(WHAT, load_style_variation_model, path)
    model = saved.model
    shortest = min_seconds(model)
    if seconds < shortest:
        raise CLIError(
            f"--seconds {seconds:g}: a walk is at least one gait cycle, {shortest:.2f} s (the longest of the "
            "model's example cycles)"
        )
    d = model.style_.shape[1]
    if len(style_in) == 1 and d > 1:
        style_in = style_in * d  # one number: every stride
    try:
        style = check_style(style_in, model, saved.style_names, saved.style_unit)
        xi = check_xi(xi_in, model)
    except ValueError as exc:
        raise CLIError(str(exc)) from exc
    tag = "_".join(f"{v:g}" for v in style)
    files = output_files([folder / f"ma2010_{tag}_v{k + 1}.bvh" for k in range(args.variants)], args.force)
    solver = root_solver(model.skeleton_, saved.joint_map)
    rig = dataset_rig(rd)
    with Progress("ma2010 walks", args.variants, enabled=not args.quiet) as bar:
        walks = generate_walks(
            model, solver, style, seconds, args.variants, args.seed, xi, progress=bar, cleanup=args.cleanup
        )
    write_motions(files, [on_rig(w.motion, rig) for w in walks], args.unit_cm)
    for p, w in zip(files.paths, walks):
        m = w.measures
        strides = [m["left_support_stride_cm"], m["right_support_stride_cm"]]
        measured = bool(np.all(np.isfinite(strides)))
        xi_text = ", ".join(f"{g} {v:.3g}" for g, v in w.xi.items())
        drawn = "" if w.draws == 1 else f" (xi drawn {w.draws} times: strides off by > {STRIDE_TOLERANCE:.0%} redrawn)"
        say(
            f"{p}: {w.motion.n_frames} frames at {w.motion.fps:g} fps ({w.motion.duration:.2f} s); style "
            f"{', '.join(f'{v:g}' for v in style)} {saved.style_unit}; measured strides "
            f"{', '.join(f'{v:.1f}' for v in strides)} cm; foot skating "
            f"{m['foot_skating_cm_s']:.2f} cm/s (cleanup {args.cleanup}); xi: {xi_text}{drawn}"
        )
        if not measured:
            note(f"warning: {p}: too short to measure both strides (each foot needs two footfalls; try more --seconds)")
        elif not w.accepted:
            note(
                f"warning: {p}: no draw of xi in {w.draws} gave the requested strides within {STRIDE_TOLERANCE:.0%}; "
                f"this is the closest (try another --seed or --xi)"
            )
    return 0
