"""Du 2022 ch. 4 the search comparison (Fig. 4.12): its table, the k-d beam at a budget, the dense pick segments and its verdicts."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from claim_checks import check_value_bound

from motionvar.core import cmu_joint_map
from motionvar.du2022.graph import MedianKDTree, primitive_clips
from motionvar.du2022.graph.evaluations import evaluate_fig4_12, search_comparison, search_primitive, summarize_search
from motionvar.du2022.graph.figures import draw_fig4_12
from motionvar.du2022.graph.settings import GraphSettings, SearchSettings


def test_search_comparison_table(prim, joints):
    pose = [
        joints[k]
        for k in ("hips", "left_shoulder", "right_shoulder", "left_hand", "right_hand", "left_ankle", "right_ankle")
    ]
    table, trees = search_comparison(
        prim, joints["right_hand"], pose, SearchSettings(n_samples=500, n_queries=4, leaf_size=8, n_random=20), seed=0
    )
    assert set(table["method"]) == {
        "kmeans",
        "gmm",
        "median",
        "median_budget",
        "median_means",
        "random",
        "brute_force",
    }
    # per kind and query: k-means at beams 2, 3, 4, then GMM, the kd-tree greedy and at the k-means
    # tree's evaluations, our median split, random, brute force
    assert len(table) == 3 * 4 * (3 + 6)
    assert set(trees["method"]) == {"kmeans", "gmm", "median", "median_means", "brute_force"}
    assert sorted(set(table.loc[table["method"] == "kmeans", "beam"])) == [2, 3, 4]
    assert table.loc[table["method"] != "kmeans", "selected"].all()
    assert set(table.loc[table["method"] == "kmeans"].query("selected")["beam"]) == {4}  # the configured beam
    assert table["budget_beam"].sum() == 3 * 4  # one k-means beam of three
    # the kd-tree at the smallest beam that spends at least the k-means tree's evaluations at the verdict beam
    mean = table.groupby(["method", "beam"])["n_evals"].mean()
    (kd_beam,) = set(table.loc[table["method"] == "median_budget", "beam"])
    assert mean[("median_budget", kd_beam)] >= mean[("kmeans", 4)] > mean[("median", 1)]
    wide = table[table["selected"]].pivot_table(index=["kind", "query"], columns="method", values="error")
    assert (wide.drop(columns="random").min(axis=1) >= wide["brute_force"] - 1e-9).all()  # trees search its samples
    summary = summarize_search(table)
    columns = {"median", "median_over_random", "selected", "budget_beam", "beam", "mean_evals"}
    assert columns | {"share_under_120_evals"} <= set(summary.columns)
    assert np.allclose(summary.loc[summary["method"] == "random", "median_over_random"], 1.0)


def test_kd_tree_beam_matches_a_budget():
    """The kd-tree's equal-budget beam: the smallest whose mean evaluations reach the target,
    stopping where a wider beam evaluates no more (the whole tree visited)."""
    from motionvar.du2022.graph.evaluations.fig4_12 import _kd_at_budget

    tree = MedianKDTree(np.arange(64.0)[:, None])
    tried = []

    def run(beam, cap=1e9):
        tried.append(beam)
        return [("position", q, "median_budget", beam, 0.0, min(10 * beam, cap), 0.0) for q in range(3)]

    greedy, rows = _kd_at_budget(tree, run, 35.0)
    assert tried == [1, 2, 3, 4] and {r[3] for r in greedy} == {1} and {r[3] for r in rows} == {4}
    tried.clear()
    greedy, rows = _kd_at_budget(tree, lambda b: run(b, cap=20), 35.0)
    assert tried == [1, 2, 3] and {r[3] for r in rows} == {2}  # beam 3 evaluates no more than beam 2


def test_dense_pick_segments_align_to_pick_reaches():
    from motionvar.prep import align_motions
    from motionvar.synth.dense_picks import dense_pick_segments

    pieces, meta = dense_pick_segments(1, 0, 2)
    assert len(pieces) == 2 and (meta["primitive"] == "pick_reach").all() and (meta["variant"] == "dense").all()
    assert list(meta["stop_frame"] - meta["start_frame"]) == [p.n_frames for p in pieces]
    clips = align_motions(pieces, cmu_joint_map())
    assert np.allclose(clips[0].root_pos[0, [0, 2]], 0.0, atol=1e-6)  # aligned: starts above the origin
    with pytest.raises(ValueError, match="per_subject"):
        dense_pick_segments(1, 0, 0)


def test_fig4_12_halving_names_the_cause_of_a_miss():
    """A primitive whose k-means / random median ratio misses 0.5 is named: too little power when
    the paired bootstrap interval over its queries reaches 0.5, the method when it lies above."""
    from motionvar.claims import judge_claims
    from motionvar.du2022.claims import CLAIMS
    from motionvar.du2022.graph.evaluations.fig4_12 import fig4_12_measurements, kmeans_ratio_intervals

    rng = np.random.default_rng(0)
    queries, rows = [], []
    for primitive, n, spread in (("tight", 400, 0.05), ("few", 12, 0.6)):
        random = rng.uniform(1.0, 2.0, n)
        kmeans = random * 0.56 * np.exp(rng.normal(scale=spread, size=n))
        for method, errors in (("kmeans", kmeans), ("random", random), ("brute_force", random * 0.1)):
            queries.append(
                pd.DataFrame(dict(primitive=primitive, kind="position", joint="hand", query=np.arange(n))).assign(
                    method=method, beam=4 if method == "kmeans" else 0, selected=True, error=errors, n_evals=50
                )
            )
            rows.append(dict(primitive=primitive, kind="position", method=method, median=np.median(errors), sd=0.1))
    per_query = pd.concat(queries, ignore_index=True)
    intervals = kmeans_ratio_intervals(per_query)
    assert intervals[("tight", "position")][0] > 0.5 and intervals[("few", "position")][0] < 0.5
    m = fig4_12_measurements(pd.DataFrame(rows), per_query)
    claim = next(c for c in judge_claims(CLAIMS, "du2022_fig4_12", m) if c.claim_id.endswith("error_position"))
    assert claim.verdict == "not reproduced" and "95 % interval" in claim.measured
    assert "Missed by too little power (the bootstrap interval over the queries reaches 0.5): few" in claim.note
    assert "by the method (its interval lies above 0.5): tight." in claim.note


def test_fig4_12_verdicts_follow_the_numbers():
    from motionvar.claims import judge_claims
    from motionvar.du2022.claims import CLAIMS
    from motionvar.du2022.graph.evaluations.fig4_12 import fig4_12_measurements

    def fig4_12_claims(rows, per_query):
        m = fig4_12_measurements(pd.DataFrame(rows), per_query)
        return {c.claim_id.split(".")[-1]: c for c in judge_claims(CLAIMS, "du2022_fig4_12", m)}

    def compactness_claim(model_bytes, data_bytes):
        m = dict(model_bytes=model_bytes, data_bytes=data_bytes, clips=1, frames=1, half=None)
        return judge_claims(CLAIMS, "du2022_sec4_6_1", m)[0]

    thesis = (("kmeans", 1.0), ("gmm", 1.2), ("median", 3.5), ("median_budget", 3.0), ("random", 4.0))
    rows = [
        dict(primitive="p", kind=kind, method=method, median=med, sd=med / 2)
        for kind in ("position", "orientation", "pose")
        for method, med in (*thesis, ("brute_force", 0.9))
    ]
    per_query = pd.DataFrame(dict(method=["kmeans"] * 4, n_evals=[50, 60, 130, 70]))
    claims = fig4_12_claims(rows, per_query)
    assert list(claims)[:3] == [f"kmeans_halves_random_error_{k}" for k in ("position", "orientation", "pose")]
    assert list(claims)[-2:] == ["kmeans_near_brute_force_position", "kmeans_near_brute_force_pose"]
    assert all(c.verdict == "reproduced" for c in claims.values())
    assert claims["kmeans_under_120_evaluations"].value == 0.75 and claims["gmm_tree_close_to_kmeans"].value == 1.0
    assert claims["kmeans_under_120_evaluations"].kind == "replication"
    # the GMM tree's SD below the k-means tree's: not "k-means slightly lower" though the medians agree
    narrow = fig4_12_claims([dict(r, sd=0.1) if r["method"] == "gmm" else r for r in rows], per_query)
    assert narrow["gmm_tree_close_to_kmeans"].verdict == "not reproduced"
    # the median tree at the k-means tree's evaluations as good as k-means: one of two comparisons per case
    budget = fig4_12_claims([dict(r, median=1.0) if r["method"] == "median_budget" else r for r in rows], per_query)
    assert budget["median_tree_closer_to_random"].verdict == "partial"
    assert budget["median_tree_closer_to_random"].value == 0.5
    rows = [dict(r, median=r["median"] if r["method"] != "kmeans" else 3.9) for r in rows]
    claims = fig4_12_claims(rows, per_query)
    assert claims["kmeans_halves_random_error_position"].value == 0.0  # share of primitives, bound 1
    for name in ("halves_random_error_position", "halves_random_error_pose", "near_brute_force_position"):
        assert claims[f"kmeans_{name}"].verdict == "not reproduced"
    assert claims["kmeans_near_brute_force_pose"].verdict == "not reproduced"
    # where brute force cannot halve random's error the primitive cannot show the claim: left out, and the
    # claim is not testable when every primitive is (pose and position here, the thesis' bar for both)
    rows = [
        dict(r, median=2.2) if (r["kind"] in ("pose", "position") and r["method"] in ("kmeans", "brute_force")) else r
        for r in rows
    ]
    claims = fig4_12_claims(rows, per_query)
    pose, position = claims["kmeans_halves_random_error_pose"], claims["kmeans_halves_random_error_position"]
    assert pose.verdict == position.verdict == "not testable" and "0.55" in pose.note and pose.value is None
    two = rows + [dict(r, primitive="q") for r in rows if r["kind"] == "pose"]
    two = [dict(r, median=0.4) if (r["primitive"], r["method"]) == ("q", "brute_force") else r for r in two]
    claims = fig4_12_claims(two, per_query)
    pose = claims["kmeans_halves_random_error_pose"]  # q testable (k-means 2.2 / 4 misses), p left out
    assert (pose.verdict, pose.value) == ("not reproduced", 0.0) and "Not testable where brute force does not: p" in (
        pose.note
    )
    assert claims["kmeans_halves_random_error_orientation"].verdict == "not reproduced"  # brute force can: a verdict
    for c in claims.values():
        check_value_bound(c)
    assert compactness_claim(1_000, 200_000).verdict == "reproduced"
    assert compactness_claim(1_000, 20_000).verdict == "partial"
    assert compactness_claim(1_000, 2_000).verdict == "not reproduced"
    for data_bytes in (200_000, 20_000, 2_000):
        c = compactness_claim(1_000, data_bytes)
        assert (c.value, c.bound, c.unit) == (data_bytes / 1_000, 100.0, "ratio")
        check_value_bound(c)


def test_primitive_clips_selects_and_names_the_file(dataset):
    motions, meta = primitive_clips(dataset, "pick_reach", "prep/clips.npz")
    assert len(motions) == 8 and (meta["primitive"] == "pick_reach").all()
    with pytest.raises(ValueError, match=r"prep/clips.npz: 0 clips of primitive 'run'.*du2022_graph.primitives"):
        primitive_clips(dataset, "run", "prep/clips.npz")


def test_search_primitive_and_fig4_12(prim, right):
    search = SearchSettings(
        n_samples=300,
        n_queries=3,
        leaf_size=8,
        n_random=10,
        joints={"walk_leftStance": "left_ankle"},
        default_joint="right_hand",
        pose_joints=("hips", "left_hand", "right_hand"),
    )
    settings = GraphSettings(search=search)
    tables = [search_primitive(p, cmu_joint_map(), settings) for p in (prim, right)]
    queries, trees = tables[0]
    assert list(queries.columns[:3]) == ["primitive", "kind", "joint"] and set(queries["joint"]) == {"left_ankle"}
    assert set(tables[1][0]["joint"]) == {"right_hand"} and (trees["primitive"] == "walk_leftStance").all()
    with pytest.raises(KeyError, match="du2022_graph.search.joints.walk_leftStance.*left_foot"):
        bad = search.replace(joints={"walk_leftStance": "left_foot"})
        search_primitive(prim, cmu_joint_map(), settings.replace(search=bad))
    with pytest.raises(KeyError, match="du2022_graph.search.pose_joints"):
        bad = search.replace(joints={}, pose_joints=("hips", "tail"))
        search_primitive(prim, cmu_joint_map(), settings.replace(search=bad))
    result = evaluate_fig4_12(pd.concat([t[0] for t in tables], ignore_index=True))
    assert len(result.table) == 2 * 3 * (3 + 6) and "mean_time_ms" not in result.table.columns
    assert {"selected", "budget_beam"} <= set(result.table.columns)
    assert [c.claim_id.split(".")[-1] for c in result.claims] == [
        "kmeans_halves_random_error_position",
        "kmeans_halves_random_error_orientation",
        "kmeans_halves_random_error_pose",
        "kmeans_under_120_evaluations",
        "gmm_tree_close_to_kmeans",
        "median_tree_closer_to_random",
        "kmeans_near_brute_force_position",
        "kmeans_near_brute_force_pose",
    ]
    assert "beams 2/3/4" in result.claims[0].measured and "budget beam" in result.claims[0].measured
    assert "kd-tree" in result.claims[5].note and "median_budget" in result.claims[5].measured
    assert result.measurements["beam"] == {"walk_leftStance": 4, "walk_rightStance": 4}
    for c in result.claims:
        check_value_bound(c)
    assert len(draw_fig4_12(result).axes) == 2 * 3
