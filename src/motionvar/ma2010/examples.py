"""Example clips for the model (Ma et al. 2010, Sec. 4): cut locomotion into cycles at
the key frames, space- and time-warp them, normalize them to the standard skeleton and
measure their style parameters (stride length per support phase, Sec. 7.2); the walking
cycles of a dataset (:func:`walk_cycles`) and their loaded form with what the model
needs (:class:`WalkCycles`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..core.skeleton import Skeleton
from ..metrics.stride import footfall_strides
from .contacts import foot_contacts
from .correspondence import movement_direction, reference_key_positions, space_warp, standard_skeleton, time_warp
from .keyframes import Cycle, KeyframeSignal, find_extrema, keyframe_signal, segment_cycles
from .postprocess import reconstruct_root
from .representation import ClipSet, rest_hip_height
from .settings import ROOT_GROUPS, Ma2010Settings
from .svi import StyleVariationModel, style_variation_model
from .synthesis import MIN_SUPPORT_S, RootSolver, rest_foot_heights


@dataclass(frozen=True)
class CycleExtraction:
    """Key frames of one motion and the cycles cut at them."""

    signal: KeyframeSignal
    frames: np.ndarray
    kinds: np.ndarray
    cycles: list[Cycle]


def joint_groups(joint_map: JointMap, skeleton: Skeleton, root_group: str) -> dict[str, np.ndarray]:
    """The four joint groups of Fig. 4 (``JointMap.group_indices``) with the root joint
    (joint 0, the pelvis) moved into ``root_group`` (config ma2010.model.root_group, one of
    :data:`.settings.ROOT_GROUPS`): "legs" (A, what every shipped joint map says) or
    "upper_body" (D). Fig. 4 does not say where the root rotation goes; it tilts the
    pelvis that carries both legs, Sec. 8 keeps the legs together for foot constraints and
    Sec. 6.3 models the root's height with the legs.
    Only the root's rotation moves: the keyframe signal (Eq. 1-4) takes positions relative
    to the root, so it is the same either way."""
    if root_group not in ROOT_GROUPS:
        raise ValueError(f"joint_groups: root_group must be one of {list(ROOT_GROUPS)}; got {root_group!r}")
    groups = joint_map.group_indices(skeleton)
    out = {g: j[j != 0] for g, j in groups.items()}
    out[root_group] = np.sort(np.append(out[root_group], 0))
    return out


def lower_upper(joint_map: JointMap, skeleton: Skeleton) -> tuple[np.ndarray, np.ndarray]:
    """Lower body = the legs group, upper body = every other joint (Sec. 4.1)."""
    groups = joint_map.group_indices(skeleton)
    lower = groups["legs"]
    upper = np.setdiff1d(np.arange(skeleton.n_joints), lower)
    return lower, upper


def extract_cycles(
    motion: Motion,
    joint_map: JointMap,
    min_prominence: float,
    min_separation_s: float,
    n_components: int | None = None,
) -> CycleExtraction:
    """Key frames (Eq. 1-4) of one motion and its gait cycles (:func:`segment_cycles`)."""
    sk = motion.skeleton
    pos = motion.positions()
    lower, upper = lower_upper(joint_map, sk)
    sig = keyframe_signal(pos, lower, upper, n_components)
    frames, kinds = find_extrema(sig.signal, min_prominence, int(round(min_separation_s * motion.fps)))
    la, ra = joint_map.index(sk, "left_ankle"), joint_map.index(sk, "right_ankle")
    cycles = segment_cycles(frames, kinds, pos[:, la], pos[:, ra], movement_direction(motion, joint_map))
    return CycleExtraction(sig, frames, kinds, cycles)


def root_solver(
    skeleton: Skeleton, joint_map: JointMap, flight_threshold: float | None = None, min_support_s: float = MIN_SUPPORT_S
) -> RootSolver:
    """Footskate cleanup settings on ``skeleton``: each foot stands on its ankle or its
    toe, planted at their rest heights above the sole; strides are measured at the ankles;
    the support foot switches with a minimum contact time of ``min_support_s`` (0: the
    lower foot of every frame, the literal rule)."""
    feet = np.array([joint_map.indices(skeleton, [f"{side}_ankle", f"{side}_toe"]) for side in ("left", "right")])
    planted = np.stack([rest_foot_heights(skeleton, f) for f in feet])
    return RootSolver(skeleton, feet, planted, flight_threshold, min_support_s)


#: Shortest contact that is a footfall (s): a walking stance lasts ~60 % of a ~1 s cycle, a
#: running one 30-40 % of ~0.7 s (docs/gait.md); shorter "contacts" are a swing foot
#: grazing the floor (the contact detection keeps runs from 0.05 s).
MIN_FOOTFALL_S = 0.1


#: The first and last poses of a measured clip are held this long (s) before its root is recovered:
#: a foot on the floor at the clip's first or last frame then has a contact there (its footfall, cut
#: by the key frame) however few of that contact's frames the clip holds (a walking cycle starts as
#: the trailing foot leaves the floor), and the support at the clip's end passes to the foot that
#: stays down. At least :data:`MIN_FOOTFALL_S`.
EDGE_HOLD_S = MIN_FOOTFALL_S
#: A footfall is located by the ankle unless the toe stands lower than the ankle by more than this
#: (cm, above their planted heights) at one end of the phase: a heel rolling off rises by several cm
#: (9 cm at a generator walk's key frame), a planted ankle sits at its planted height.
JOINT_TOLERANCE_CM = 1.0


def stride_root(rotations: np.ndarray, solver: RootSolver, fps: float) -> np.ndarray:
    """(T, 3) root of ``rotations`` (T, J, 4) at ``fps`` on the solver's skeleton for the stride
    measure: the footskate cleanup's (Sec. 6.3, :func:`.postprocess.reconstruct_root`: the
    support foot, the lower one with the solver's minimum contact time, stays put at its lowest
    joint), with the step into a frame where the support passes to the other foot carried by the
    foot that is planted over it (``planted_carrier``; on the standard skeleton a foot may slide
    as it lands). Walking only: no flight phases."""
    return reconstruct_root(
        rotations,
        solver.skeleton,
        solver.feet,
        solver.planted,
        min_support_frames=int(round(solver.min_support_s * fps)),
        planted_carrier=True,
    )


def support_strides(motion: Motion, key_frames: np.ndarray, solver: RootSolver) -> np.ndarray:
    """Stride length (cm) of the left and the right support phase of one cycle (key frames 0-2
    and 2-4, frames of ``motion``, its root recovered): the horizontal travel of the swing foot
    between its footfalls (:func:`..metrics.stride.footfall_strides`: at each key frame each
    foot stands on its nearest contact of at least :data:`MIN_FOOTFALL_S` from
    :func:`foot_contacts`, located by its ankle or, where the heel is up at one end of the
    phase, its toe: :data:`JOINT_TOLERANCE_CM`)."""
    pos = motion.positions()
    feet = pos[:, np.asarray(solver.feet)]  # (T, 2, 2, 3): ankle and toe of each foot
    bounds = np.asarray(key_frames)[[0, 2, 4]]
    shortest = int(round(MIN_FOOTFALL_S * motion.fps))
    contacts = foot_contacts(motion, solver.feet, pos)
    return footfall_strides(
        feet, contacts, bounds, shortest, planted=solver.planted, joint_tolerance=JOINT_TOLERANCE_CM
    )


def normalized_strides(rotations: np.ndarray, key_frames: np.ndarray, solver: RootSolver, fps: float) -> np.ndarray:
    """The style parameter of one walking clip (Sec. 7.2: the strides of its left and right
    support phases), the one measure of every walking clip here: an example cycle cut from a
    walk and a synthesized clip retimed to real time alike. Its rotations (T, J, 4) at ``fps``,
    the first and last poses held :data:`EDGE_HOLD_S`, are put on the solver's (standard)
    skeleton (Sec. 1: normalizing to one skeleton "unifies the style parameter spaces"), the
    root recovered (:func:`stride_root`) and the strides measured between the clip's key frames
    (:func:`support_strides`). On the generator's walks each cycle measured alone on its own
    skeleton is within 0.25 % of the true stride of each phase whose two footfalls of the swing
    foot it holds, within 1 % where the foot leaves the standing start, lands a frame after the
    cycle's last key frame or lifts off one frame into the cycle (the held first pose plants it
    on its toe, ahead of its footprint: up to 0.83 %; tests/ma2010/test_ma2010_postprocess.py)."""
    n = int(round(EDGE_HOLD_S * fps))
    held = np.pad(rotations, ((n, n), (0, 0), (0, 0)), mode="edge")
    motion = Motion(skeleton=solver.skeleton, root_pos=stride_root(held, solver, fps), rotations=held, fps=fps)
    return support_strides(motion, np.asarray(key_frames) + n, solver)


def build_clipset(
    cycles: Sequence[Motion],
    key_frames: Sequence[np.ndarray],
    skeleton: Skeleton,
    joint_map: JointMap,
    n_frames: int,
    style: np.ndarray | None = None,
    clip_ids: Sequence[str] | None = None,
) -> ClipSet:
    """Aligned examples on the standard ``skeleton`` (Sec. 4.2).

    Every cycle is space-warped (Eq. 5-6) and time-warped to ``n_frames`` frames with its
    key frames on the common reference positions. Its rotations are used as they are on
    the standard skeleton; its root height is scaled by the ratio of rest hip heights.
    Without ``style`` the style parameters are the cycle's two support-phase strides
    measured on the standard skeleton by the measure of a synthesized clip
    (:func:`normalized_strides`, on the cycle alone, in real time).
    """
    if len(cycles) != len(key_frames) or not cycles:
        raise ValueError(f"build_clipset: {len(cycles)} cycles and {len(key_frames)} key-frame sets")
    ref = reference_key_positions(key_frames, [m.n_frames for m in cycles], n_frames)
    foot_joints = joint_map.indices(skeleton, ["left_ankle", "left_toe", "right_ankle", "right_toe"])
    std_hip = rest_hip_height(skeleton, foot_joints)
    rots, heights, keys = [], [], []
    for m, k in zip(cycles, key_frames):  # loop over clips
        w = time_warp(space_warp(m, joint_map), k, ref)
        scale = std_hip / rest_hip_height(m.skeleton, foot_joints)
        rots.append(w.rotations)
        heights.append(w.root_pos[:, 1] * scale)
        keys.append(np.asarray(k, dtype=float) / m.fps)
    rotations = np.stack(rots)
    fps = float(cycles[0].fps)
    if style is None:
        solver = root_solver(skeleton, joint_map)
        style = np.stack(
            [normalized_strides(space_warp(m, joint_map).rotations, k, solver, fps) for m, k in zip(cycles, key_frames)]
        )
    ids = list(clip_ids) if clip_ids is not None else []
    return ClipSet(
        rotations=rotations,
        key_times=np.stack(keys),
        root_height=np.stack(heights),
        style=np.asarray(style, dtype=float),
        reference_keys=ref,
        skeleton=skeleton,
        fps=fps,
        clip_ids=ids,
    )


def cut(motion: Motion, cycle: Cycle) -> Motion:
    """The frames of one cycle as a motion."""
    return motion.slice(cycle.start, cycle.stop + 1)


def collect_cycles(
    motions: Sequence[Motion],
    clip_ids: Sequence[str],
    joint_map: JointMap,
    min_prominence: float,
    min_separation_s: float,
) -> tuple[list[Motion], list[np.ndarray], pd.DataFrame]:
    """Every cycle of every motion (Sec. 4.1-4.2: key frames, then clips): the cycles as
    motions, their key frames, and a table (clip_id = "<source>_c<k>", source_clip,
    start_frame, stop_frame, n_frames). Motions without a complete cycle add nothing."""
    cycles, keys, rows = [], [], []
    for m, cid in zip(motions, clip_ids):  # loop over clips
        for k, c in enumerate(extract_cycles(m, joint_map, min_prominence, min_separation_s).cycles):
            cycles.append(cut(m, c))
            keys.append(c.key_frames)
            rows.append(
                {
                    "clip_id": f"{cid}_c{k}",
                    "source_clip": cid,
                    "start_frame": c.start,
                    "stop_frame": c.stop,
                    "n_frames": c.stop - c.start + 1,
                }
            )
    columns = ["clip_id", "source_clip", "start_frame", "stop_frame", "n_frames"]
    return cycles, keys, pd.DataFrame(rows, columns=columns)


def rows_matching(metadata: pd.DataFrame, what: str = "metadata", **filters: str | Sequence[str]) -> np.ndarray:
    """Row indices of ``metadata`` whose columns take the given values (a string, or a list
    of accepted values; an empty list accepts all). ValueError naming ``what`` when a
    filtered column is missing or nothing matches."""
    mask = np.ones(len(metadata), dtype=bool)
    for column, accepted in filters.items():
        values = [accepted] if isinstance(accepted, str) else list(accepted)
        if not values:
            continue
        if column not in metadata:
            raise ValueError(f"{what}: no column {column!r} to select {values}")
        mask &= metadata[column].astype(str).isin(values).to_numpy()
    if not mask.any():
        raise ValueError(f"{what}: no clip with {filters}")
    return np.flatnonzero(mask)


CLIPSET_KIND = "ma2010.ClipSet"  # the "kind" of a saved ClipSet (motionvar.io.model_file)


def walk_cycles(
    dataset, joint_map: JointMap, settings: Ma2010Settings, what: str = "metadata"
) -> tuple[ClipSet, pd.DataFrame]:
    """The walking clips of a dataset (``motionvar.io.MotionDataset``) with the styles and
    variants of ``settings`` (walk_styles, walk_variants; n_frames, keyframe_prominence,
    keyframe_min_separation_s) cut into gait cycles at their key frames (Eq. 1-4), space- and
    time-warped onto the mean skeleton (Sec. 4.2), with their style parameters (strides of
    the left and right support phases, Sec. 7.2, measured on each cycle as on a synthesized
    clip: :func:`normalized_strides`). Returns the clips and one table row per
    cycle (:func:`collect_cycles`' columns, the source clip's subject, style, stride and
    speed, the two strides and the duration). ValueError naming ``what`` when no clip
    matches or fewer than 3 cycles come out."""
    meta = dataset.metadata
    idx = rows_matching(
        meta, behaviour="walk", style=settings.clips.walk_styles, variant=settings.clips.walk_variants, what=what
    )
    motions = [dataset.motion(int(i)) for i in idx]
    cycles, keys, table = collect_cycles(
        motions,
        meta["clip_id"].iloc[idx].tolist(),
        joint_map,
        settings.clips.keyframe_prominence,
        settings.clips.keyframe_min_separation_s,
    )
    if len(cycles) < 3:
        seconds = np.array([m.duration for m in motions])
        found = "no complete gait cycle" if not cycles else f"only {len(cycles)} complete gait cycle(s)"
        raise ValueError(
            f"{what}: {found} in the {len(idx)} walk clips (they last {seconds.min():.2g}-{seconds.max():.2g} s, "
            f"median {np.median(seconds):.2g} s); need at least 3. A cycle (Sec. 4.2) runs from the legs "
            "farthest apart with the left foot ahead, through the same with the right foot ahead, to the left ahead "
            "again: two steps, so a clip needs two foot strikes of each foot, a walk of at least ~2 s"
        )
    sk = standard_skeleton([c.skeleton for c in cycles])
    clips = build_clipset(cycles, keys, sk, joint_map, settings.clips.n_frames, clip_ids=table["clip_id"].tolist())
    src = meta.set_index("clip_id").loc[table["source_clip"]]
    table["subject"] = src["subject"].astype(str).to_numpy()
    for col in ("style", "stride_length_cm", "speed_cm_s"):
        if col in src:
            table[f"source_{col}"] = src[col].to_numpy()
    table["left_support_stride_cm"], table["right_support_stride_cm"] = clips.style[:, 0], clips.style[:, 1]
    table["duration_s"] = clips.key_times[:, -1]
    return clips, table


def source_of_cycle(clip_id: str, what: str = "walking cycles") -> str:
    """The walk (source clip) of a cycle named "<source>_c<k>" (:func:`collect_cycles`)."""
    head, sep, k = str(clip_id).rpartition("_c")
    if not sep or not head or not k.isdigit():
        raise ValueError(f"{what}: cycle id {clip_id!r} is not '<source clip>_c<k>'; give the source clips")
    return head


@dataclass
class WalkCycles:
    """The walking cycles of a dataset (:func:`walk_cycles`) as the evaluations use them:
    the clips, each cycle's subject and the rig's joint map (``source`` names where they
    came from, for error messages), with the joint groups (:func:`joint_groups`, the root
    rotation in ``root_group``, config ma2010.model.root_group) and the root solver derived. ``source_clips`` names each
    cycle's walk (the ``source_clip`` column of :func:`walk_cycles`' table); without it,
    the walk is read from the cycle's clip id ("<source>_c<k>", :func:`collect_cycles`)."""

    clips: ClipSet
    subjects: list[str]
    joint_map: JointMap
    source: str = "walking cycles"
    root_group: str = field(kw_only=True)
    source_clips: list[str] | None = None
    groups: dict = field(init=False, repr=False)  # joint group -> joint indices (Fig. 4)
    solver: RootSolver = field(init=False, repr=False)  # footskate cleanup on the clips' skeleton

    def __post_init__(self) -> None:
        self.subjects = [str(s) for s in self.subjects]
        if len(self.subjects) != self.clips.n_clips:
            raise ValueError(f"{self.source}: {len(self.subjects)} subjects for {self.clips.n_clips} cycles")
        if self.source_clips is None:
            self.source_clips = [source_of_cycle(c, self.source) for c in self.clips.clip_ids]
        self.source_clips = [str(s) for s in self.source_clips]
        if len(self.source_clips) != self.clips.n_clips:
            raise ValueError(f"{self.source}: {len(self.source_clips)} source clips for {self.clips.n_clips} cycles")
        self.groups = joint_groups(self.joint_map, self.clips.skeleton, self.root_group)
        self.solver = root_solver(self.clips.skeleton, self.joint_map)

    def fit_model(self, settings: Ma2010Settings) -> StyleVariationModel:
        """The model of Sec. 5-6 fitted to all the cycles, with the structure and variogram of
        ``settings`` ("auto" structure: Fig. 5 by D_l vs D_u of the cycles)."""
        return style_variation_model(self.groups, settings.model.structure, settings).fit(self.clips)
