"""``motionvar du2022 walk``: a Morphable Graph walk along a floor path (Du 2022 ch. 4,
Algorithm 1); ``motionvar du2022 style``: samples of a style's CVAE (or the neutral VAE)
decoded to motion (Du 2022 ch. 5)."""

from __future__ import annotations

import argparse
import math
import re
from pathlib import Path

from .common import (
    CLIError,
    ResultsDir,
    at_most,
    dataset_rig,
    note,
    on_rig,
    out_dir,
    out_file,
    output_files,
    parse_numbers,
    say,
    write_motions,
)
from .progress import Progress

GRAPH = "du2022/graph"
EDGES = f"{GRAPH}/graph/edges.npz"
EDGES_SETTINGS = f"{GRAPH}/graph/edges.json"
STYLE = "du2022_style"
AUTOENCODER = (f"{STYLE}/autoencoder.pt", f"{STYLE}/autoencoder.json")
RIG = (f"{STYLE}/rig.npz", f"{STYLE}/rig.json")
NEUTRAL = "neutral"
WALK_EVALUATIONS = ("du2022_fig4_10", "du2022_sec4_6_1", "du2022_fig4_12", "du2022_fig4_9")  # build walk primitives
STYLE_EVALUATIONS = ("du2022_table5_1", "du2022_table5_2", "du2022_fig5_4")  # build the style models
# Largest requests: a walk's path (each step is a Levenberg-Marquardt fit, ~2 s: 20 m took
# 35 steps, 76 s on the CI models) and its steps, and the samples of one style command
# (decoded and written together: 50 took ~20 s and 0.36 GB).
MAX_PATH_CM = 10_000.0
MAX_STEPS = 400
MAX_SAMPLES = 200


def add_parser(sub: argparse._SubParsersAction, common) -> None:
    p = sub.add_parser(
        "du2022",
        help="Morphable Graph walks and stylistic samples (Du 2022)",
        description="Du 2022: `walk` follows a floor path with the Morphable Graph (ch. 4); `style` "
        "decodes samples of a style's CVAE (ch. 5).",
    )
    kinds = p.add_subparsers(dest="kind", metavar="{walk,style}", required=True)
    w = kinds.add_parser(
        "walk",
        parents=[common()],
        help="a walk along a floor path (Morphable Graph, Algorithm 1)",
        description="A graph walk following the path: each step seeded from a k-means tree of GMM samples and "
        "optimised by Levenberg-Marquardt on Eq. 4.9 (settings: config du2022_graph.synthesis of the run).",
    )
    w.add_argument(
        "--path",
        required=True,
        help='floor points x,z in cm, separated by spaces or ";", e.g. "0,0 300,0 400,100" '
        f"(at most {MAX_PATH_CM:g} cm long)",
    )
    w.add_argument(
        "--max-steps",
        type=int,
        default=None,
        help=f"at most this many steps (default: enough for the path; at most {MAX_STEPS})",
    )
    w.add_argument("--out", required=True, help="output BVH file")
    w.set_defaults(run=run_walk)
    s = kinds.add_parser(
        "style",
        parents=[common()],
        help="samples of a style's CVAE decoded to motion",
        description="Random samples of the CVAE of a style (or the neutral VAE: --style neutral) of one primitive, "
        "decoded by the motion decoder into joint positions and put on the dataset's rig. One BVH per sample.",
    )
    s.add_argument("--style", required=True, help="style name (`motionvar models` lists them), or neutral")
    s.add_argument("--primitive", default=None, help="motion primitive (default: the first with a model of the style)")
    s.add_argument("--n", type=int, default=1, help=f"number of samples (default 1; at most {MAX_SAMPLES})")
    s.add_argument("--out", required=True, help="output folder (<style>_<primitive>_<k>.bvh)")
    s.set_defaults(run=run_style)


def parse_path(text: str) -> list[list[float]]:
    """'0,0 300,0 400,100' (or ';'-separated) -> [[x, z], ...]; CLIError naming the bad point."""
    points = [t for t in re.split(r"[\s;]+", str(text).strip()) if t]
    out = []
    for t in points:
        xz = parse_numbers(t, f"--path point {t!r}")
        if len(xz) != 2:
            raise CLIError(f"--path: point {t!r} is not x,z (two comma-separated numbers in cm)")
        out.append(xz)
    if len(out) < 2:
        raise CLIError(f"--path: needs at least 2 points x,z (cm); got {len(out)} in {text!r}")
    return out


def path_length(points: list[list[float]]) -> float:
    """Length (cm) of the polyline through ``points``."""
    return float(sum(math.dist(a, b) for a, b in zip(points, points[1:])))


def has_steps(graph, names: list[str]) -> bool:
    """Whether the graph has a transition from one of the walking primitives ``names``."""
    return any(graph.edges.get(n) for n in names)


def graph_primitives(rd: ResultsDir, names: list[str]) -> dict:
    """The saved motion primitives among ``names`` that exist; CLIError naming the target
    of the first stepping primitive when none does."""
    from ..du2022.graph import MotionPrimitive

    found = {n: rd.model(f"{GRAPH}/{n}.npz") for n in names}
    found = {n: p for n, p in found.items() if p.is_file() and p.with_suffix(".json").is_file()}
    return {n: rd.load(f"the motion primitive {n}", MotionPrimitive.load, p) for n, p in found.items()}


def run_walk(args: argparse.Namespace) -> int:
    rd = ResultsDir(Path(args.results), args.dataset)
    points = parse_path(args.path)
    if args.max_steps is not None and args.max_steps < 1:
        raise CLIError(f"--max-steps must be >= 1; got {args.max_steps}")
    at_most(args.max_steps or 0, MAX_STEPS, "--max-steps", "steps per walk")
    at_most(path_length(points), MAX_PATH_CM, "--path of length", "cm per walk")
    from ..du2022.graph.generate import check_path, steps_for_path, walk_along_path, walk_settings  # after the checks
    from ..du2022.graph.storage import load_graph

    out = out_file(args.out)
    try:
        path = check_path(points)
    except ValueError as exc:
        raise CLIError(str(exc)) from exc
    files = output_files([out], args.force)
    edges, _ = rd.require("the Morphable Graph's transitions (Du 2022 ch. 4)", EDGES, EDGES_SETTINGS)
    saved = rd.load("the Morphable Graph's transitions", load_graph, edges)
    settings = walk_settings(saved.settings)
    cyclic = list(settings.cyclic)
    primitives = graph_primitives(rd, [settings.start, *cyclic, settings.end])
    if not any(n in primitives for n in cyclic):
        rd.require(
            f"the walking primitive {cyclic[0]} (Du 2022 ch. 4)",
            f"{GRAPH}/{cyclic[0]}.npz",
            f"{GRAPH}/{cyclic[0]}.json",
            evaluations=WALK_EVALUATIONS,
        )
    if not has_steps(saved.graph, [settings.start, *cyclic]):
        raise CLIError(
            f"the Morphable Graph of dataset {args.dataset!r} has no transitions between its walking "
            "primitives (each clip of its prep data is one primitive, so no clip shows one step following "
            "another): a walk cannot go beyond one step"
        )
    max_steps = args.max_steps or steps_for_path(primitives, path, saved.joint_map, settings)
    settings = walk_settings(saved.settings, max_steps)
    rig = dataset_rig(rd)
    with Progress("du2022 walk (trees, then the walk)", len(primitives) + 1, enabled=not args.quiet) as bar:
        walk = walk_along_path(primitives, saved.graph, path, saved.joint_map, settings, args.seed, bar)
    write_motions(files, [on_rig(walk.motion, rig)], args.unit_cm)
    hips = saved.joint_map.index(walk.motion.skeleton, "hips")
    gap = walk.end_gap_cm(hips)
    step = walk.path.length / max(len(walk.steps), 1)
    if gap > step:
        note(
            f"warning: {out}: the walk ends {gap:.0f} cm from the path's end, more than a step (--max-steps "
            f"{settings.max_steps})"
        )
    names = " ".join(s.primitive.removeprefix("walk_") for s in walk.steps)
    say(
        f"{out}: {walk.motion.n_frames} frames at {walk.motion.fps:g} fps ({walk.motion.duration:.2f} s); "
        f"{len(walk.steps)} steps ({names}); path {path.length:.0f} cm, the walk ends {gap:.1f} cm from its end"
    )
    return 0


def _style_models(rd: ResultsDir) -> dict[tuple[str, str], Path]:
    """(primitive, style) -> weights file of every saved VAE (style neutral) and CVAE."""
    base = rd.model(STYLE)
    out = {(p.stem, NEUTRAL): p for p in sorted((base / "vae").glob("*.pt"))}
    out.update({(p.parent.name, p.stem): p for p in sorted((base / "cvae").glob("*/*.pt"))})
    return {k: p for k, p in out.items() if p.with_suffix(".json").is_file()}


def run_style(args: argparse.Namespace) -> int:
    rd = ResultsDir(Path(args.results), args.dataset)
    if args.n < 1:
        raise CLIError(f"--n must be >= 1; got {args.n}")
    at_most(args.n, MAX_SAMPLES, "--n", "samples per command (run again with another --seed for more)")
    import torch  # after the checks: a refused request ends at once

    from ..du2022.style import FeatureSpace, load_vae
    from ..du2022.style.generate import load_rig, sample_motions

    folder = out_dir(args.out)
    ae, _ = rd.require("the Du 2022 motion autoencoder", *AUTOENCODER, evaluations=STYLE_EVALUATIONS)
    rig_path, _ = rd.require("the Du 2022 style rig (skeleton, feature layout, frame rates)", *RIG)
    models = _style_models(rd)
    styles = sorted({s for _, s in models})
    if args.style not in styles:
        have = ", ".join(styles) if styles else "none"
        target = rd.target(rd.model(f"{STYLE}/cvae/walk_leftStance/{args.style}.pt"))
        raise CLIError(
            f"style {args.style!r} has no model for dataset {args.dataset!r}; styles with models: {have} "
            f"(a configured style is built by `snakemake --cores 2 {target}`)"
        )
    prims = sorted(p for p, s in models if s == args.style)
    primitive = args.primitive or prims[0]
    if primitive not in prims:
        raise CLIError(f"primitive {primitive!r} has no {args.style} model; primitives with one: {', '.join(prims)}")
    files = output_files([folder / f"{args.style}_{primitive}_{k + 1}.bvh" for k in range(args.n)], args.force)
    torch.set_num_threads(1)
    space = rd.load("the motion autoencoder", FeatureSpace.load, ae)
    saved = rd.load(f"the {args.style} model of {primitive}", load_vae, models[(primitive, args.style)])
    rig = rd.load("the style rig", load_rig, rig_path)
    layout = dataset_rig(rd)
    with Progress(f"du2022 style {args.style}", 1, enabled=not args.quiet) as bar:
        try:
            motions = sample_motions(saved, space, rig, args.n, args.seed)
        except ValueError as exc:
            raise CLIError(str(exc)) from exc
        bar.update(1)
    write_motions(files, [on_rig(m, layout) for m in motions], args.unit_cm)
    for p, m in zip(files.paths, motions):
        travel = float(((m.root_pos[-1] - m.root_pos[0])[[0, 2]] ** 2).sum() ** 0.5)
        say(
            f"{p}: {m.n_frames} frames at {m.fps:.4g} fps ({m.duration:.2f} s), {args.style} {primitive} "
            f"(the hips travel {travel:.0f} cm)"
        )
    return 0
