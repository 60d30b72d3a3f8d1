"""Du 2022 Fig. 4.12 / Sec. 4.6.2: constraint search by the k-means, GMM and median
space-partitioning trees against random sampling and brute force.

Two steps: :func:`search_primitive` runs the random queries on one primitive (one table
row per query, method and beam; rule ``du2022_graph_search``), :func:`evaluate_fig4_12`
summarises the queries of all primitives and checks the claims of Sec. 4.6.2. Where the
thesis says "close", "most" or "much smaller" without a number, the threshold used is
written in the claim's note.

Methods (column ``method``):

- ``kmeans``: the k-means tree with beam search, at every beam of ``SearchSettings.beams``
  (:mod:`~motionvar.du2022.graph.settings`, config ``graph.search``);
  the verdicts use the beam chosen from the thesis' budget (``beam="auto"``: the largest
  beam whose mean number of evaluations stays under ``max_evaluations``, 120 in the
  thesis) or the explicit ``beam``; column ``selected`` marks the rows the verdicts use;
- ``gmm``: the GMM tree, same beam;
- ``median``: the median tree as DFKI built it (:class:`MedianKDTree`: median-sample nodes,
  greedy descent, max-variance splits); the claim "median tree close to random" uses it;
- ``median_means``: our earlier median-split tree (node means and the k-means tree's beam),
  a variant row;
- ``random``: the best of ``n_random`` fresh GMM samples; ``brute_force``: the exact best
  of the trees' samples.

Computation (the same selections, errors and evaluation counts as one query at a time, at
a fraction of the cost): the key-frame poses of every tree's samples and node means are
computed once (:class:`KeyFramePositionIndex`), and the queries of one constraint kind
run in lockstep (``search_many`` of the trees: one vectorised objective call per tree
level for all queries; :func:`random_search_many`). Column ``time_s`` is a method's time
for the queries of a kind divided evenly over them.

A bar that even brute force over the same samples cannot meet ("k-means halves random's
error" where brute force itself is above half of random's error) is not testable on this
data: those cases get the verdict ``not testable`` with the numbers, apart from the rest.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import replace

import numpy as np
import pandas as pd

from ....claims import Claim, EvaluationResult, verdict_from_fraction, verdict_threshold
from ....core.joint_map import JointMap
from ..constraints import ConstraintStack, random_constraints
from ..primitive import MotionPrimitive
from ..settings import THESIS_BUDGET, GraphSettings, SearchSettings
from ..trees import (
    KeyFramePositionIndex,
    MedianKDTree,
    SearchResult,
    SpacePartitioningTree,
    random_search_many,
    select_beam,
)
from .common import semantic_index

PAPER = "du2022"
CONSTRAINT_KINDS = ("position", "orientation", "pose")
METHODS = ("kmeans", "gmm", "median", "median_means", "random", "brute_force")
HALF = 0.5  # "reduces the median error ... by more than half"
CLOSE_GMM = 1.5  # "close": the GMM tree's median error at most 1.5x the k-means tree's
CLOSE_BRUTE = 0.25  # "close to the ground truth": k-means closes >= 75 % of the random -> brute-force gap
MOST = 0.5  # "in most cases": more than half of the queries


COLUMNS = ["kind", "query", "method", "beam", "error", "n_evals", "time_s"]


def _build_trees(samples: np.ndarray, leaf_size: int, seed: int) -> tuple[dict, list[dict]]:
    """The k-means, GMM, median (DFKI's kd-tree) and median-means trees over ``samples``,
    and one row per tree (method, n_nodes, depth, build_s)."""
    trees, rows = {}, []
    for name in ("kmeans", "gmm", "median", "median_means"):
        t0 = time.perf_counter()
        if name == "median":
            trees[name] = MedianKDTree(samples)
        else:
            kind = "median" if name == "median_means" else name
            trees[name] = SpacePartitioningTree(samples, kind, leaf_size=leaf_size, seed=seed)
        rows.append(
            dict(method=name, n_nodes=trees[name].n_nodes, depth=trees[name].depth, build_s=time.perf_counter() - t0)
        )
    return trees, rows


def _timed_rows(
    queries: Mapping[str, list], name: str, beam: int, search_all: Callable[[str], list[SearchResult]]
) -> list[tuple]:
    """Rows (:data:`COLUMNS`) of one method: ``search_all(kind)`` answers all queries of a kind
    at once; its time is shared evenly by them."""
    out = []
    for kind, qs in queries.items():
        t0 = time.perf_counter()
        found = search_all(kind)
        dt = (time.perf_counter() - t0) / max(len(qs), 1)
        out += [(kind, q, name, beam, r.error, r.n_evals, dt) for q, r in enumerate(found)]
    return out


def _sorted_table(rows: list[tuple], beam: int, kinds: Sequence[str]) -> pd.DataFrame:
    """The per-query table: column ``selected`` (the rows the verdicts use: every method but
    the k-means tree, which only at ``beam``), sorted by kind, query, method, beam."""
    table = pd.DataFrame(rows, columns=COLUMNS)
    table.insert(4, "selected", (table["method"] != "kmeans") | (table["beam"] == beam))
    order = {m: i for i, m in enumerate(METHODS)}
    return table.sort_values(
        ["kind", "query", "method", "beam"],
        key=lambda c: (
            c.map(order)
            if c.name == "method"
            else (c.map({k: i for i, k in enumerate(kinds)}) if c.name == "kind" else c)
        ),
        kind="stable",
    ).reset_index(drop=True)


def search_comparison(
    primitive: MotionPrimitive,
    position_joint: int,
    pose_joints: Sequence[int],
    settings: SearchSettings,
    seed: int,
    kinds: Sequence[str] = CONSTRAINT_KINDS,
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Fig. 4.12 for one primitive: random constraints of each kind at the last canonical
    frame (Eq. 4.2), met by fresh GMM samples; the best sample found by each tree (the
    k-means tree at every candidate beam), by random sampling and by brute force over the
    tree's samples. The beam of the verdicts (GMM and ``median_means`` run at it) is
    :func:`~motionvar.du2022.graph.trees.select_beam` of the k-means tree's mean
    evaluations over all queries of this primitive, or the explicit one. Samples,
    constraints and trees draw from ``seed``.

    Returns (per-query table: kind, query, method, beam, selected, error, n_evals, time_s;
    per-tree table: method, n_nodes, depth, build_s).
    """
    st = settings
    rng = np.random.default_rng(seed)
    samples = primitive.sample(st.n_samples, rng)
    trees, tree_rows = _build_trees(samples, st.leaf_size, seed)
    last = primitive.n_frames - 1
    joints = [int(position_joint)] + [int(j) for j in pose_joints if int(j) != int(position_joint)]
    t0 = time.perf_counter()
    exact = KeyFramePositionIndex(primitive, samples, [last], joints)
    tree_rows.append(dict(method="brute_force", n_nodes=len(samples), depth=0, build_s=time.perf_counter() - t0))
    # the key-frame poses of every latent vector a search can evaluate, computed once (module docstring)
    poses = {
        name: exact if tree.points is samples else KeyFramePositionIndex(primitive, tree.points, [last], joints)
        for name, tree in trees.items()
    }
    queries = {}
    for kind in kinds:
        cons_joints = [int(position_joint)] if kind != "pose" else [int(j) for j in pose_joints]
        queries[kind] = random_constraints(primitive, kind, st.n_queries, cons_joints, last, rng)
    stacks = {kind: ConstraintStack([[c] for c in qs]) for kind, qs in queries.items()}

    def tree_run(name: str, beam: int) -> list[tuple]:
        tree, n = trees[name], st.n_queries
        if name == "median":
            return _timed_rows(queries, name, 1, lambda k: tree.search_many(poses[name].objective_many(stacks[k]), n))
        return _timed_rows(
            queries, name, beam, lambda k: tree.search_many(poses[name].objective_many(stacks[k]), n, beam)
        )

    rows = [row for b in st.candidates for row in tree_run("kmeans", b)]
    mean_evals = pd.DataFrame(rows, columns=COLUMNS).groupby("beam")["n_evals"].mean().to_dict()
    beam = select_beam(mean_evals, st.max_evaluations)[0] if st.beam == "auto" else int(st.beam)
    for name in ("gmm", "median_means", "median"):
        rows += tree_run(name, beam)
    rows += _timed_rows(
        queries, "random", 0, lambda k: random_search_many(primitive, [[c] for c in queries[k]], st.n_random, rng)
    )
    # exact: the same best sample as evaluating all of them
    rows += _timed_rows(
        queries, "brute_force", 0, lambda k: [replace(exact.search([c]), n_evals=len(samples)) for c in queries[k]]
    )
    return _sorted_table(rows, beam, kinds), pd.DataFrame(tree_rows)


def search_primitive(
    primitive: MotionPrimitive, joint_map: JointMap, settings: GraphSettings
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """:func:`search_comparison` on one primitive with ``settings.search`` and
    ``settings.seed``, with semantic joints: the position and orientation joint is
    ``search.joints[primitive.name]`` (else ``search.default_joint``), the pose constraints
    use ``search.pose_joints``. Returns (per-query table with the primitive and the joint,
    per-tree table with the primitive); KeyError naming the config key of a joint the joint
    map lacks."""
    st, name = settings.search, primitive.name
    sem = st.joint(name)
    joint = semantic_index(joint_map, primitive.skeleton, sem, f"graph.search.joints.{name}")
    pose = [semantic_index(joint_map, primitive.skeleton, j, "graph.search.pose_joints") for j in st.pose_joints]
    table, trees = search_comparison(primitive, joint, pose, st, settings.seed)
    table.insert(0, "primitive", name)
    table.insert(2, "joint", sem)
    trees.insert(0, "primitive", name)
    return table, trees


def summarize_search(table: pd.DataFrame) -> pd.DataFrame:
    """Median, quartiles, SD of the error, mean evaluations and the share under the thesis'
    120 evaluations per (primitive, kind, method, beam), with ``selected`` (the rows the
    verdicts use) and ``median_over_random`` (the median error over random sampling's)."""
    keys = [k for k in ("primitive", "kind", "method", "beam") if k in table.columns]
    g = table.groupby(keys, sort=False)
    out = g["error"].agg(
        median="median", q25=lambda x: x.quantile(0.25), q75=lambda x: x.quantile(0.75), sd="std", mean="mean"
    )
    if "selected" in table.columns:
        out.insert(0, "selected", g["selected"].all())
    out["mean_evals"] = g["n_evals"].mean()
    out["share_under_120_evals"] = g["n_evals"].apply(lambda x: float(np.mean(x < THESIS_BUDGET)))
    out["mean_time_ms"] = 1e3 * g["time_s"].mean()
    out = out.reset_index()
    case = [k for k in ("primitive", "kind") if k in out.columns]
    rand = out[out["method"] == "random"].set_index(case)["median"]
    idx = pd.MultiIndex.from_frame(out[case]) if len(case) > 1 else out[case[0]]
    out.insert(
        out.columns.get_loc("median") + 1, "median_over_random", out["median"].to_numpy() / rand.reindex(idx).to_numpy()
    )
    return out


def _selected(summary: pd.DataFrame) -> pd.DataFrame:
    return summary[summary["selected"]] if "selected" in summary.columns else summary


def _medians(summary: pd.DataFrame) -> pd.DataFrame:
    """(primitive, kind) x method table of median errors (the rows the verdicts use)."""
    return _selected(summary).pivot_table(index=["primitive", "kind"], columns="method", values="median", sort=False)


def _beams(summary: pd.DataFrame) -> tuple[pd.DataFrame, dict[str, int]]:
    """(primitive, kind) x beam table of the k-means tree's median errors, and the beam of
    the verdicts per primitive."""
    km = summary[summary["method"] == "kmeans"]
    if "beam" not in km.columns:
        return pd.DataFrame(index=_medians(summary).index), {}
    by_beam = km.pivot_table(index=["primitive", "kind"], columns="beam", values="median", sort=False)
    chosen = km[km["selected"]] if "selected" in km.columns else km
    return by_beam, {str(p): int(b) for p, b in zip(chosen["primitive"], chosen["beam"])}


def _ratios_by_beam(by_beam: pd.DataFrame, random: pd.Series, case) -> str:
    if by_beam.empty or case not in by_beam.index:
        return ""
    row = by_beam.loc[case] / random.loc[case]
    return "beams " + "/".join(str(b) for b in row.index) + ": " + "/".join(f"{v:.2f}" for v in row)


def _share(n_ok: int, n: int) -> float:
    """The share of cases a ``verdict_from_fraction`` verdict is computed from (NaN without cases)."""
    return n_ok / n if n else float("nan")


def _halves_claim(
    kind: str, med: pd.DataFrame, by_beam: pd.DataFrame, beam_of: dict[str, int], n_samples: int
) -> Claim:
    """k-means halves random's median error for constraint ``kind``, over the primitives
    where brute force over the same samples can (module docstring); ``not testable`` when
    it can in none."""
    sub = med.xs(kind, level="kind")
    ratio = sub["kmeans"] / sub["random"]
    brute = sub["brute_force"] / sub["random"]
    testable = brute < HALF
    ok = (ratio < HALF) & testable
    parts = [
        f"{p}: {r:.2f} (beam {beam_of.get(p, '?')}; "
        + (_ratios_by_beam(by_beam, med["random"], (p, kind)) + "; " if not by_beam.empty else "")
        + f"brute force {b:.2f})"
        for p, r, b in zip(sub.index, ratio, brute)
    ]
    changed = (
        "Changed since the previous run (issue 13): one claim per constraint type, the beam chosen from the "
        "thesis' budget instead of fixed at 2, and cases where brute force cannot halve random counted as not "
        "testable instead of not reproduced."
    )
    value, bound, unit, direction = None, None, "", ""  # not testable: no share to compare
    if not testable.any():
        verdict = "not testable"
        note = (
            f"Even brute force over the same {n_samples} samples reaches only {brute.min():.2f}-{brute.max():.2f} "
            f"of random sampling's median error (>= {HALF}): no search over these samples can halve it, so the "
            f"bar cannot be met on this data. {changed}"
        )
    else:
        verdict = verdict_from_fraction(int(ok.sum()), int(testable.sum()))
        value, bound, unit, direction = int(ok.sum()) / int(testable.sum()), 1.0, "share", ">="
        left = [f"{p} (brute force/random {b:.2f})" for p, b in zip(sub.index[~testable], brute[~testable])]
        note = (
            f"{int(ok.sum())} of {int(testable.sum())} primitives below {HALF} among those where brute force "
            f"itself is below it; partial when at least half are."
            + (f" Not testable, left out: {', '.join(left)}." if left else "")
            + f" {changed}"
        )
    return Claim(
        f"{PAPER}.fig4_12.kmeans_halves_random_error_{kind}",
        PAPER,
        "Fig. 4.12",
        f"The k-means tree search reduces the median error of random sampling (100 samples) by more than half "
        f"for every primitive ({kind} constraints).",
        f"median error ratio k-means / random < {HALF} for all primitives",
        "k-means / random median error: " + "; ".join(parts),
        verdict,
        note=note,
        value=value,
        bound=bound,
        unit=unit,
        direction=direction,
    )


def _budget_claim(per_query: pd.DataFrame, beam_of: dict[str, int]) -> Claim:
    """The k-means tree search needs fewer than 120 evaluations in most cases (at the verdict beam)."""
    km_all = per_query[per_query["method"] == "kmeans"]
    km = km_all[km_all["selected"]] if "selected" in km_all.columns else km_all
    share = float(np.mean(km["n_evals"] < THESIS_BUDGET))
    per_beam = km_all.groupby(["primitive", "beam"])["n_evals"].mean() if "beam" in km_all.columns else None
    beams_txt = (
        ""
        if per_beam is None
        else "; mean evaluations by beam: "
        + "; ".join(
            f"{p}: " + ", ".join(f"{b}: {e:.0f}" for b, e in per_beam[p].items())
            for p in per_beam.index.levels[0]
            if p in per_beam.index.get_level_values(0)
        )
    )
    return Claim(
        f"{PAPER}.fig4_12.kmeans_under_120_evaluations",
        PAPER,
        "Fig. 4.12",
        "The k-means tree search needs fewer than 120 objective evaluations in most cases.",
        "< 120 evaluations in most cases",
        f"{100 * share:.1f} % of {len(km)} queries under 120 at the verdict beam "
        f"({', '.join(f'{p}: {b}' for p, b in beam_of.items())}); mean {km['n_evals'].mean():.1f} evaluations"
        + beams_txt,
        verdict_threshold(share, MOST + 1e-9, ">="),
        value=share,
        bound=MOST + 1e-9,
        unit="share",
        direction=">=",
        note="'most' read as more than half of the k-means queries at the verdict beam. The beam is chosen per "
        "primitive as the largest whose mean evaluations stay under the budget (graph.search.max_evaluations, "
        "the thesis' 120), so this claim checks that choice rather than an independent finding. Changed since "
        "the previous run (issue 13): beam from the budget instead of fixed at 2 (~58 evaluations at full size).",
    )


def _gmm_claim(med: pd.DataFrame, cases: list[str]) -> Claim:
    """The GMM tree close to the k-means tree, k-means slightly lower (per primitive and kind)."""
    g = med["gmm"] / med["kmeans"]
    ok = (g >= 1.0) & (g <= CLOSE_GMM)
    return Claim(
        f"{PAPER}.fig4_12.gmm_tree_close_to_kmeans",
        PAPER,
        "Fig. 4.12",
        "The GMM tree is about as accurate as the k-means tree, with k-means slightly lower median errors "
        "for all primitives.",
        "GMM close to k-means, k-means slightly lower",
        "median error ratio GMM / k-means: " + "; ".join(f"{c}: {r:.2f}" for c, r in zip(cases, g)),
        verdict_from_fraction(int(ok.sum()), len(ok)),
        value=_share(int(ok.sum()), len(ok)),
        bound=1.0,
        unit="share",
        direction=">=",
        note=f"a case agrees when 1 <= GMM / k-means <= {CLOSE_GMM} ('close' and k-means lower); "
        f"{int(ok.sum())} of {len(ok)} agree; both trees at the verdict beam. Changed since the previous run "
        "(issue 13): the beam from the budget.",
    )


def _median_claim(med: pd.DataFrame, cases: list[str]) -> Claim:
    """The median tree (DFKI's kd-tree) closer to random sampling than to the k-means tree."""
    closer = (med["median"] - med["random"]).abs() < (med["median"] - med["kmeans"]).abs()
    variant = ""
    if "median_means" in med.columns:
        vc = (med["median_means"] - med["random"]).abs() < (med["median_means"] - med["kmeans"]).abs()
        variant = (
            f" Our median-split tree with node means and the k-means tree's beam (variant row median_means): "
            f"{int(vc.sum())} of {len(vc)} closer to random; median / random "
            + ", ".join(f"{c}: {r:.2f}" for c, r in zip(cases, med["median_means"] / med["random"]))
            + "."
        )
    return Claim(
        f"{PAPER}.fig4_12.median_tree_closer_to_random",
        PAPER,
        "Fig. 4.12",
        "The median-split tree's result is closer to random sampling than to the k-means tree.",
        "median tree closer to random than to k-means",
        "median errors (median tree, random, k-means): "
        + "; ".join(
            f"{c}: {a:.3g}, {b:.3g}, {k:.3g}" for c, a, b, k in zip(cases, med["median"], med["random"], med["kmeans"])
        ),
        verdict_from_fraction(int(closer.sum()), len(closer)),
        value=_share(int(closer.sum()), len(closer)),
        bound=1.0,
        unit="share",
        direction=">=",
        note=f"{int(closer.sum())} of {len(closer)} cases closer to random. The median tree is DFKI's kd-tree "
        "(every node the median sample of the dimension of maximum variance, greedy descent to a leaf). "
        "Changed since the previous run (issue 13): it was our median split with node means and beam "
        f"search.{variant}",
    )


def _brute_claim(med: pd.DataFrame, by_beam: pd.DataFrame) -> Claim:
    """For position constraints the k-means tree leaves at most :data:`CLOSE_BRUTE` of the gap
    between random sampling and brute force."""
    pos = med.xs("position", level="kind")
    gap = (pos["kmeans"] - pos["brute_force"]) / (pos["random"] - pos["brute_force"]).clip(lower=1e-12)
    ok = gap <= CLOSE_BRUTE
    gap_beams = ""
    if not by_beam.empty:
        bb = by_beam.xs("position", level="kind")
        g_b = bb.sub(pos["brute_force"], axis=0).div((pos["random"] - pos["brute_force"]).clip(lower=1e-12), axis=0)
        gap_beams = (
            " Gap by beam: "
            + "; ".join(f"{p}: " + ", ".join(f"{b}: {v:.2f}" for b, v in g_b.loc[p].items()) for p in g_b.index)
            + "."
        )
    return Claim(
        f"{PAPER}.fig4_12.kmeans_near_brute_force_position",
        PAPER,
        "Fig. 4.12",
        "For position constraints the k-means tree search reaches close to the brute-force ground truth over "
        "the same 10,000 samples.",
        "k-means close to brute force for position constraints",
        "share of the random-to-brute-force gap left by k-means: "
        + "; ".join(
            f"{p}: {v:.2f} (median {a:.2f} vs {b:.2f} cm)"
            for p, v, a, b in zip(pos.index, gap, pos["kmeans"], pos["brute_force"])
        ),
        verdict_from_fraction(int(ok.sum()), len(ok)),
        value=_share(int(ok.sum()), len(ok)),
        bound=1.0,
        unit="share",
        direction=">=",
        note=f"'close' read as leaving at most {CLOSE_BRUTE:.0%} of the gap between random sampling and brute "
        f"force; {int(ok.sum())} of {len(ok)} primitives at the verdict beam.{gap_beams} Changed since the "
        "previous run (issue 13): the beam from the budget.",
    )


def fig4_12_claims(summary: pd.DataFrame, per_query: pd.DataFrame) -> list[Claim]:
    """The Fig. 4.12 claims from :func:`summarize_search` output (with a ``primitive``
    column) and the per-query table: k-means halves random's error (one claim per
    constraint type), under 120 evaluations, GMM close to k-means, the median tree closer
    to random, k-means near brute force for position constraints."""
    med = _medians(summary)
    by_beam, beam_of = _beams(summary)
    cases = [f"{p}/{k}" for p, k in med.index]
    n_samples = (
        int(per_query.loc[per_query["method"] == "brute_force", "n_evals"].max())
        if "brute_force" in set(per_query["method"])
        else 0
    )
    kinds = [k for k in CONSTRAINT_KINDS if k in set(med.index.get_level_values("kind"))]
    return [
        *(_halves_claim(k, med, by_beam, beam_of, n_samples) for k in kinds),
        _budget_claim(per_query, beam_of),
        _gmm_claim(med, cases),
        _median_claim(med, cases),
        _brute_claim(med, by_beam),
    ]


def evaluate_fig4_12(queries: pd.DataFrame) -> EvaluationResult:
    """Fig. 4.12 over the per-query tables of all primitives (:func:`search_primitive`,
    concatenated): error summary per primitive, constraint kind, method and beam (timings
    left out: they are not reproducible), the claims, and the queries for the box plots."""
    if "beam" in queries.columns:
        queries = queries.astype({"beam": int})
    summary = summarize_search(queries).drop(columns="mean_time_ms")
    return EvaluationResult(table=summary, claims=fig4_12_claims(summary, queries), figure={"queries": queries})
