"""Plots: stick figures, key-frame grids, the dataset overview and GIF animations."""

import imageio.v3 as iio
import numpy as np
import pandas as pd
import pytest

from motionvar.core import Motion, cmu_skeleton
from motionvar.core.quaternions import qidentity, quat_about_axis
from motionvar.io import load_dataset, save_dataset
from motionvar.plots import (
    KeyFrameRow,
    animate_motions,
    dataset_overview,
    gif_page,
    key_frame_grid,
    overview_clips,
    project,
    view_axis,
    write_gif,
)
from motionvar.plots.stick import joint_sides


def swinging_clip(n_frames=60, fps=30.0, speed_cm_s=100.0, swing=0.4):
    """A test clip (not a generator): CMU skeleton, legs swinging, root moving along +z."""
    sk = cmu_skeleton()
    t = np.arange(n_frames) / fps
    rot = qidentity((n_frames, sk.n_joints))
    phase = 2 * np.pi * t
    rot[:, sk.index("LeftUpLeg")] = quat_about_axis([1, 0, 0], swing * np.sin(phase))
    rot[:, sk.index("RightUpLeg")] = quat_about_axis([1, 0, 0], -swing * np.sin(phase))
    root = np.stack([np.zeros(n_frames), np.full(n_frames, 95.0), speed_cm_s * t], axis=-1)
    return Motion(sk, root, rot, fps)


def test_joint_sides_from_names():
    names = ["Hips", "LHipJoint", "LeftUpLeg", "RightArm", "RThumb", "lShldr", "hand_r", "Hand.L", "LowerBack", "Root"]
    assert joint_sides(names, len(names)) == [
        "centre",
        "left",
        "left",
        "right",
        "right",
        "left",
        "right",
        "left",
        "centre",
        "centre",
    ]


def test_view_axis_side_view_for_walking_front_view_for_standing():
    walk = swinging_clip().positions()
    assert np.allclose(view_axis(walk), [0, 0, 1], atol=1e-6)
    stand = swinging_clip(speed_cm_s=0.0, swing=0.0).positions()
    axis = view_axis(stand)
    assert abs(axis[0]) > 0.95  # left-right axis of the CMU rig is x


def test_project_keeps_heights_and_separates_depth():
    p = np.array([[0.0, 100.0, 0.0], [0.0, 100.0, 50.0]])
    xy = project(p, screen_x=[0, 0, 1])
    assert np.allclose(xy[:, 1], 100.0) and np.allclose(xy[:, 0], [0.0, 50.0])
    tilted = project(p, screen_x=[0, 0, 1], elevation_deg=30.0, azimuth_deg=20.0)
    assert not np.allclose(tilted, xy)
    with pytest.raises(ValueError, match="horizontal"):
        project(p, screen_x=[0, 1, 0])


def test_key_frame_grid_writes_a_figure(tmp_path):
    m = swinging_clip()
    rows = [KeyFrameRow("walk", m.positions(), m.skeleton.parents, m.skeleton.names, m.fps), None]
    fig = key_frame_grid(rows, n_keys=4, columns=2)
    out = tmp_path / "grid.png"
    fig.savefig(out)
    image = iio.imread(out)
    assert image.shape[0] > 100 and image.shape[1] > 200
    assert image[..., :3].std() > 5  # something was drawn


def test_key_frame_grid_rejects_bad_positions():
    m = swinging_clip()
    pos = m.positions()
    pos[3, 2, 1] = np.nan
    with pytest.raises(ValueError, match="NaN"):
        key_frame_grid([KeyFrameRow("bad", pos, m.skeleton.parents)])
    with pytest.raises(ValueError, match=r"\(T, 31, 3\)"):
        key_frame_grid([KeyFrameRow("bad", pos[:, :5], m.skeleton.parents)])


def _tiny_dataset(tmp_path):
    clips = [swinging_clip(), swinging_clip(speed_cm_s=0.0, swing=0.05), swinging_clip(speed_cm_s=150.0, swing=0.6)]
    meta = pd.DataFrame(
        {
            "clip_id": ["w1", "i1", "w2"],
            "subject": ["01", "01", "02"],
            "behaviour": ["walk", "idle", "walk"],
            "style": ["neutral", None, "proud"],
        }
    )
    save_dataset(tmp_path / "data", clips, meta)
    return load_dataset(tmp_path / "data")


def test_overview_picks_one_clip_per_behaviour_and_style(tmp_path):
    ds = _tiny_dataset(tmp_path)
    behaviours, styles = overview_clips(ds.metadata)
    assert behaviours == [("walk", 0), ("idle", 1)]
    assert styles == [("walk, neutral", 0), ("walk, proud", 2)]
    with pytest.raises(ValueError, match="'activity'"):
        overview_clips(ds.metadata, behaviour_col="activity")
    fig = dataset_overview(ds, n_keys=3)
    assert len([ax for ax in fig.axes if ax.get_visible()]) == 4
    fig.savefig(tmp_path / "overview.png")
    assert (tmp_path / "overview.png").stat().st_size > 10_000


def test_animation_gif_frames_rate_and_size(tmp_path):
    clips = [swinging_clip(n_frames=91, fps=30.0), swinging_clip(n_frames=30, fps=60.0, speed_cm_s=0.0)]
    out = tmp_path / "a.gif"
    size = animate_motions(out, clips, labels=["3 s at 30 fps", "0.5 s at 60 fps"], out_fps=20.0)
    assert size == out.stat().st_size and 0 < size < 3_000_000
    frames = iio.imread(out, index=None)
    assert frames.shape[0] == 61  # 3 s at 20 fps, both ends included
    assert frames.shape[2] == 2 * frames.shape[1]  # two square panels
    assert iio.immeta(out)["duration"] == 50
    assert not np.array_equal(frames[0], frames[30])  # it moves


def test_write_gif_over_the_size_limit_leaves_no_file(tmp_path):
    rng = np.random.default_rng(0)
    noise = rng.integers(0, 255, size=(5, 64, 64, 3), dtype=np.uint8)
    out = tmp_path / "big.gif"
    with pytest.raises(ValueError, match="big.gif"):
        write_gif(out, noise, max_bytes=1000)
    assert list(tmp_path.iterdir()) == []


def test_gif_page_inlines_the_gif_and_rejects_other_files(tmp_path):
    gif = tmp_path / "a.gif"
    animate_motions(gif, [swinging_clip(n_frames=20)], labels=["walk"])
    page = gif_page(gif, title="walk <1>")
    assert "data:image/gif;base64," in page and "walk &lt;1&gt;" in page
    png = tmp_path / "b.gif"
    png.write_bytes(b"\x89PNG\r\n\x1a\n")
    with pytest.raises(ValueError, match="b.gif: not a GIF"):
        gif_page(png)
