"""``motionvar models``: what a pipeline run fitted for a dataset, what each generating
command needs and what it accepts (styles and their range, subjects, primitives). A model
file that exists but cannot be read is listed as UNREADABLE with the target that rebuilds
it; the listing goes on, and the command ends with that error (exit status 2)."""

from __future__ import annotations

import argparse
from collections.abc import Iterator
from pathlib import Path

from . import du2022, egges2004, ma2010
from .common import CLIError, ResultsDir, UnreadableFile, say


def add_parser(sub: argparse._SubParsersAction, common) -> None:
    p = sub.add_parser(
        "models",
        parents=[common()],
        help="list the fitted models and what each command needs",
        description="Which model files a pipeline run left for the dataset, which are missing (with "
        "the Snakemake target that builds them), and what each command accepts.",
    )
    p.set_defaults(run=run)


def _files(rd: ResultsDir, relative: list[str], evaluations: tuple[str, ...] = ()) -> tuple[bool, list[str]]:
    """Whether all files exist, and a line per file: ok, or MISSING with the Snakemake target
    that builds it (once per group), or why the dataset has no such model."""
    lines, ok, hint = [], True, True
    reason = rd.unsupported(evaluations)
    for r in relative:
        p = rd.model(r)
        there = p.is_file()
        ok &= there
        extra = ""
        if not there and hint:
            extra = f"   <- not applicable: {reason}" if reason else f"   <- snakemake --cores 2 {rd.target(p)}"
            hint = False
        lines.append(f"    {'ok     ' if there else 'MISSING'} {p}{extra}")
    return ok, lines


def _ma2010(rd: ResultsDir) -> Iterator[str]:
    from ..ma2010.generate import GROUP_LETTERS, STYLE_MARGIN, range_text, style_range, xi_range
    from ..ma2010.storage import load_style_variation_model

    ok, lines = _files(rd, [ma2010.MODEL, ma2010.MODEL_SETTINGS], ma2010.EVALUATIONS)
    yield "ma2010    motionvar ma2010 --style S[,S] [--xi A=..] --seconds N --variants K --out DIR"
    yield from lines
    if ok:
        saved = rd.load(ma2010.WHAT, load_style_variation_model, rd.model(ma2010.MODEL))
        m = saved.model
        lo, hi = style_range(m)
        ex_lo, ex_hi = style_range(m, 0.0)
        for k, name in enumerate(saved.style_names):
            rule = (
                f", widened by {STYLE_MARGIN:.0%} of it on each side; the strides must stay as close to each "
                "other as the examples'"
                if k == 0
                else ""
            )
            yield (
                f"    style {range_text(lo[k : k + 1], hi[k : k + 1], [name], saved.style_unit)} (examples "
                f"{ex_lo[k]:.1f}-{ex_hi[k]:.1f}{rule})"
            )
        letters = {g: k for k, g in GROUP_LETTERS.items()}
        yield "    xi: " + "; ".join(f"{letters[g]} ({g}) {a:.3g}-{b:.3g}" for g, (a, b) in xi_range(m).items())
        yield f"    {m.style_.shape[0]} example cycles of {len(set(saved.subjects))} subjects, {m.fps_:g} fps"
        yield f"    walks of at least {ma2010.min_seconds(m):.2f} s (one gait cycle)"


def _egges2004(rd: ResultsDir) -> Iterator[str]:
    from ..egges2004.storage import load_idle_model

    ok, lines = _files(rd, [egges2004.MODEL, egges2004.MODEL_SETTINGS], egges2004.EVALUATIONS)
    yield "egges2004 motionvar egges2004 --subject S --seconds N --out FILE.bvh"
    yield from lines
    if ok:
        model = rd.load(egges2004.WHAT, load_idle_model, rd.model(egges2004.MODEL))
        yield f"    subjects: {', '.join(sorted(model.databases))}"


def _du2022_walk(rd: ResultsDir) -> Iterator[str]:
    from ..du2022.graph.generate import walk_settings
    from ..du2022.graph.storage import load_graph

    ok, lines = _files(rd, [du2022.EDGES, du2022.EDGES_SETTINGS])
    yield 'du2022    motionvar du2022 walk --path "x,z x,z ..." --out FILE.bvh'
    yield from lines
    if ok:
        saved = rd.load("the Morphable Graph's transitions", load_graph, rd.model(du2022.EDGES))
        settings = walk_settings(saved.settings)
        names = [settings.start, *settings.cyclic, settings.end]
        have = [n for n in names if rd.model(f"{du2022.GRAPH}/{n}.npz").is_file()]
        missing = [n for n in names if n not in have]
        yield f"    walking primitives: {', '.join(have) or 'none'}" + (
            f" (not modelled: {', '.join(missing)})" if missing else ""
        )
        if not du2022.has_steps(saved.graph, [settings.start, *settings.cyclic]):
            yield (
                "    no transitions between walking primitives: a walk stops after one step (each clip of "
                "the prep data is one primitive)"
            )
        if not any(n in have for n in settings.cyclic):
            reason = rd.unsupported(du2022.WALK_EVALUATIONS)
            target = rd.target(rd.model(f"{du2022.GRAPH}/{settings.cyclic[0]}.npz"))
            yield "    MISSING a stepping primitive   <- " + (
                f"not applicable: {reason}" if reason else f"snakemake --cores 2 {target}"
            )


def _du2022_style(rd: ResultsDir) -> Iterator[str]:
    ok, lines = _files(rd, [*du2022.AUTOENCODER, *du2022.RIG], du2022.STYLE_EVALUATIONS)
    yield "du2022    motionvar du2022 style --style NAME [--primitive P] --n K --out DIR"
    yield from lines
    models = du2022._style_models(rd)
    by_style: dict[str, list[str]] = {}
    for p, s in models:
        by_style.setdefault(s, []).append(p)
    if by_style:
        yield from (f"    style {s}: primitives {', '.join(sorted(ps))}" for s, ps in sorted(by_style.items()))
    else:
        reason = rd.unsupported(du2022.STYLE_EVALUATIONS)
        yield "    no VAE or CVAE   <- " + (
            f"not applicable: {reason}"
            if reason
            else f"snakemake --cores 2 {rd.target(rd.model(du2022.STYLE + '/vae'))}/<primitive>.pt"
        )


def _listing(rd: ResultsDir) -> Iterator[str | UnreadableFile]:
    """The lines of every command's section; an UnreadableFile in the place of the rest of
    a section whose model cannot be read."""
    for part in (_ma2010, _egges2004, _du2022_walk, _du2022_style):
        try:
            yield from part(rd)
        except UnreadableFile as exc:
            yield exc


def run(args: argparse.Namespace) -> int:
    results = Path(args.results)
    if args.dataset is None:
        found = sorted(p.name for p in results.iterdir() if (p / "models").is_dir()) if results.is_dir() else []
        if not found:
            raise CLIError(
                f"no dataset with models in {results}: run `snakemake --cores 2` first, or pass --results DIR"
            )
        datasets = found
    else:
        datasets = [args.dataset]
    unreadable: list[UnreadableFile] = []
    for ds in datasets:
        rd = ResultsDir(results, ds)
        rd.check_dataset()
        say(f"dataset {ds} ({rd.root})")
        for line in _listing(rd):
            if isinstance(line, UnreadableFile):
                unreadable.append(line)
                line = f"    UNREADABLE {line.path}   <- snakemake --cores 2 --force {line.target}"
            say("  " + line)
    if unreadable:
        more = f" (and {len(unreadable) - 1} more UNREADABLE above)" if len(unreadable) > 1 else ""
        raise CLIError(f"{unreadable[0]}{more}")
    return 0
