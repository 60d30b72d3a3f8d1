"""Messages about the user's data (issue #11): later steps name the clip that is too short
(Du 2022 call sites of motionvar.prep), and the Ma 2010 evaluations say what the data
lacks (Fig. 3's not-applicable claim and foot-strike source, the walking-cycle count,
Sec. 7.4's subject condition)."""

import matplotlib

matplotlib.use("Agg")  # noqa: E402  (tests draw figures to nowhere)

import matplotlib.pyplot as plt
import pandas as pd
import pytest
from ma2010_toywalk import toy_walk

from motionvar.claims import NotApplicable
from motionvar.core import cmu_joint_map
from motionvar.io import load_dataset, save_dataset
from motionvar.ma2010 import figures
from motionvar.ma2010.evaluations.fig3 import fig3_keyframes
from motionvar.ma2010.evaluations.sec7_4 import sec7_4_comparison
from motionvar.ma2010.examples import WalkCycles, walk_cycles
from motionvar.ma2010.settings import Ma2010Settings
from motionvar.prep import detect_foot_contacts, format_intervals

JM = cmu_joint_map()


def walks(path, n_cycles, n_clips=2, contacts=False):
    motions = [toy_walk(hip_amp=0.3 + 0.03 * i, n_cycles=n_cycles) for i in range(n_clips)]
    meta = pd.DataFrame(
        {
            "clip_id": [f"w{i}" for i in range(n_clips)],
            "subject": [f"{i:02d}" for i in range(n_clips)],
            "behaviour": "walk",
            "style": "neutral",
            "variant": "forward",
        }
    )
    if contacts:  # as the generator writes them: its ground truth
        c = [detect_foot_contacts(m, JM) for m in motions]
        meta["left_contacts"] = [format_intervals(x.left_intervals) for x in c]
        meta["right_contacts"] = [format_intervals(x.right_intervals) for x in c]
    save_dataset(path, motions, meta)
    return load_dataset(path)


def legend_labels(fig) -> list[str]:
    return [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]


def test_fig3_without_whole_steps_is_not_applicable_with_the_reason(tmp_path):
    result = fig3_keyframes(walks(tmp_path, n_cycles=0.3), JM, Ma2010Settings())
    claim = {c.claim_id: c for c in result.claims}["ma2010.fig3.walk_keyframes_at_one_gait_phase"]
    assert len(result.claims) == 2 and claim.verdict == "not applicable"
    assert "none of the 2 walk clips has a maximum of S_M(t)" in claim.note and "detected foot strikes" in claim.note
    fig = figures.draw_fig3(result)
    assert "foot strike (detected)" in legend_labels(fig)
    plt.close(fig)


@pytest.mark.parametrize("contacts, label", [(False, "detected"), (True, "ground truth")])
def test_fig3_says_where_the_foot_strikes_come_from(tmp_path, contacts, label):
    result = fig3_keyframes(walks(tmp_path, n_cycles=2, contacts=contacts), JM, Ma2010Settings())
    claim = {c.claim_id: c for c in result.claims}["ma2010.fig3.walk_keyframes_at_one_gait_phase"]
    assert claim.verdict != "not applicable"
    source = "generator ground truth" if contacts else "detected from foot contacts"
    assert f"Steps run from one foot strike ({source}" in claim.note
    fig = figures.draw_fig3(result)
    assert f"foot strike ({label})" in legend_labels(fig)
    plt.close(fig)


def test_walk_cycles_say_what_the_walks_lack(tmp_path):
    with pytest.raises(
        ValueError,
        match="meta.csv: no complete gait cycle in the 2 walk clips \\(they last "
        "[0-9.]+-[0-9.]+ s, median [0-9.]+ s\\); need at least 3.*"
        "two foot strikes of each foot",
    ):
        walk_cycles(walks(tmp_path, n_cycles=0.3), JM, Ma2010Settings().replace(clips__n_frames=24), what="meta.csv")


def test_sec7_4_needs_cycles_of_two_subjects(tmp_path):
    settings = Ma2010Settings().replace(clips__n_frames=24)
    clips, table = walk_cycles(walks(tmp_path, n_cycles=3, n_clips=2), JM, settings)
    one = WalkCycles(clips, ["solo"] * clips.n_clips, JM, source="my walks", root_group=settings.model.root_group)
    with pytest.raises(
        NotApplicable,
        match=f"my walks: 1 subject\\(s\\) among the {clips.n_clips} walking cycles; Sec. "
        "7.4 takes its example cycles one per subject.*at least 2 subjects",
    ):
        sec7_4_comparison(one, settings)


# ----------------------------------------------------------------------------- Du 2022 call sites


def primitives_with_a_sliver(path):
    m = toy_walk(n_cycles=0.5)
    motions = [m, m.slice(0, 40), m.slice(3, 4), m.slice(0, 50)]
    meta = pd.DataFrame(
        {
            "clip_id": ["p0", "p1", "sliver_07", "p3"],
            "subject": "s",
            "behaviour": "walk",
            "style": "neutral",
            "primitive": "walk_leftStance",
        }
    )
    save_dataset(path, motions, meta)
    return load_dataset(path)


@pytest.mark.parametrize(
    "time_warping, message",
    [("dtw", "warp_to_median: clips sliver_07 \\(1 frame"), ("linear", "resample_motion: clip sliver_07 has 1 frame")],
)
def test_fda_canonical_primitives_name_the_clip(tmp_path, time_warping, message):
    from motionvar.du2022.fda.primitives import canonical_primitives

    with pytest.raises(ValueError, match=message):
        canonical_primitives(primitives_with_a_sliver(tmp_path), ["walk"], 3, time_warping)


def test_graph_and_style_clips_name_the_clip(tmp_path):
    from motionvar.du2022.graph import MotionPrimitive
    from motionvar.du2022.graph import primitive_clips as graph_clips
    from motionvar.du2022.style.data import primitive_clips as style_clips

    data = primitives_with_a_sliver(tmp_path)
    with pytest.raises(
        ValueError,
        match="prep/clips.npz: clips sliver_07 \\(1 frame\\(s\\)\\) of primitive "
        "'walk_leftStance' have fewer than 2 frames",
    ):
        graph_clips(data, "walk_leftStance", source="prep/clips.npz")
    with pytest.raises(ValueError, match="warp_to_median: clips walk_leftStance #2 \\(1 frame"):
        MotionPrimitive("walk_leftStance").fit([data.motion(i) for i in range(4)])
    with pytest.raises(ValueError, match="resample_motion: clip sliver_07 has 1 frame"):
        style_clips(data, "walk_leftStance", "neutral", 16)
