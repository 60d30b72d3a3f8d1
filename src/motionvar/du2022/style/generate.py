"""Stylistic motion from the fitted models of Du 2022 ch. 5, for the ``motionvar du2022
style`` command: random samples of a primitive's CVAE (one style) or neutral VAE, decoded by
the VAE decoder and the motion decoder (Fig. 5.2; :func:`.model.sample_features`, as
Fig. 5.4-5.5 and Tables 5.2-5.3 draw theirs) into the features of Sec. 5.2, integrated to
joint positions (:func:`.features.features_to_positions`) and put on the dataset's rig as
joint rotations (:func:`positions_to_motion`).

The models generate positions of the 21 feature joints only; a BVH file needs rotations
of every joint of the rig. :class:`StyleRig` (saved by rule ``du2022_style_rig`` beside the
models) holds what that takes and the models do not: the rig's mean skeleton, its feature
layout and the real-time frame rate of each primitive's canonical clips (the primitive's
mean duration over its 60 canonical frames, as Fig. 5.4's animation).

:func:`positions_to_motion` (our addition; the thesis looks at positions): every feature
joint's global rotation turns its rest-pose bone directions onto the generated ones — with
the directions to several feature descendants (hips, chest) by the weighted least-squares
rotation (Kabsch), with one by the smallest rotation from where the parent carries it
(swing, no added twist); joints between feature joints and the joints below the feature
set (fingers, end joints) keep their rest pose relative to their parent. Vectorised over
frames. Bone lengths are the rig's, so joint positions differ from the generated ones by
the difference in bone lengths (the samples mix the subjects' proportions).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

from ...core.joint_map import JointMap
from ...core.motion import Motion
from ...core.quaternions import qfix, qinv, qmul, qnormalize, qrot
from ...core.skeleton import Skeleton
from ...io.dataset import MotionDataset
from ...io.model_file import load_model, model_base, save_model
from .data import dataset_layout
from .evaluations.fig5_4 import primitive_clip_fps
from .features import FeatureLayout, features_to_positions
from .model import FeatureSpace, SavedVAE, sample_features

RIG_KIND = "du2022.StyleRig"
RIG_VERSION = 1
_EPS = 1e-6


@dataclass
class StyleRig:
    """The rig of a dataset's style models: mean skeleton, feature layout (Sec. 5.2), the
    real-time frame rate of each primitive's canonical clips, their frame count, the joint map."""

    skeleton: Skeleton
    layout: FeatureLayout
    fps: dict[str, float]
    n_frames: int
    joint_map: JointMap


def fit_rig(dataset: MotionDataset, joint_map: JointMap, n_frames: int) -> StyleRig:
    """The :class:`StyleRig` of a (preprocessed) dataset: bone offsets and end sites
    averaged over its clips, channel layout as its clips', the feature layout of its rig
    and a frame rate per primitive of its metadata."""
    a = dataset.arrays
    sk0 = dataset.motion(0).skeleton
    sk = Skeleton(
        names=sk0.names,
        parents=sk0.parents,
        offsets=np.asarray(a["offsets"], dtype=float).mean(axis=0),
        end_sites={
            int(j): np.asarray(a["end_site_offsets"], dtype=float)[:, k].mean(axis=0)
            for k, j in enumerate(a["end_site_joints"])
        },
        rotation_orders=sk0.rotation_orders,
        position_channels=sk0.position_channels,
    )
    meta = dataset.metadata
    prims = sorted({str(p) for p in meta["primitive"].dropna()} - {""}) if "primitive" in meta else []
    fps = {p: float(primitive_clip_fps(meta, p, n_frames)) for p in prims}
    return StyleRig(sk, dataset_layout(dataset, joint_map), fps, int(n_frames), joint_map)


def save_rig(path: str | Path, rig: StyleRig) -> list[Path]:
    """Write ``<base>.npz`` + ``<base>.json``; returns both paths."""
    sk, lay = rig.skeleton, rig.layout
    ends = np.array(sorted(sk.end_sites), dtype=np.int64)
    arrays = {
        "parents": sk.parents,
        "offsets": sk.offsets,
        "end_site_joints": ends,
        "end_site_offsets": np.array([sk.end_sites[j] for j in ends], dtype=float).reshape(-1, 3),
        "layout.joints": lay.joints,
        "layout.parents": lay.parents,
        "layout.left": lay.left,
        "layout.right": lay.right,
    }
    info = {
        "kind": RIG_KIND,
        "version": RIG_VERSION,
        "names": list(sk.names),
        "rotation_orders": list(sk.rotation_orders),
        "position_channels": [bool(p) for p in sk.position_channels],
        "layout_names": list(lay.names),
        "fps": dict(rig.fps),
        "n_frames": rig.n_frames,
        "joint_map": {
            "joints": dict(rig.joint_map.joints),
            "groups": {g: list(v) for g, v in rig.joint_map.groups.items()},
        },
    }
    return save_model(path, arrays, info)


def load_rig(path: str | Path) -> StyleRig:
    """Read a rig written by :func:`save_rig`; ValueError naming the file when incomplete."""
    a, info = load_model(path, kind=RIG_KIND)
    base = model_base(path)
    try:
        sk = Skeleton(
            names=tuple(info["names"]),
            parents=a["parents"],
            offsets=a["offsets"],
            end_sites={int(j): np.asarray(o) for j, o in zip(a["end_site_joints"], a["end_site_offsets"])},
            rotation_orders=tuple(info["rotation_orders"]),
            position_channels=tuple(bool(p) for p in info["position_channels"]),
        )
        lay = FeatureLayout(
            joints=a["layout.joints"],
            names=tuple(info["layout_names"]),
            parents=a["layout.parents"],
            left=a["layout.left"],
            right=a["layout.right"],
        )
        jm = JointMap.from_dict(info["joint_map"], origin=f"{base}.json")
        return StyleRig(sk, lay, {str(k): float(v) for k, v in info["fps"].items()}, int(info["n_frames"]), jm)
    except (KeyError, TypeError, ValueError) as exc:
        raise ValueError(f"{base}.npz/.json: not a complete {RIG_KIND} ({exc!r}); rerun rule du2022_style_rig") from exc


def _swing(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """(T, 4) smallest rotations taking unit vectors a (T, 3) onto b (T, 3)."""
    w = 1.0 + np.sum(a * b, axis=-1, keepdims=True)
    xyz = np.cross(a, b)
    opposite = w[:, 0] < _EPS  # a half turn about any axis perpendicular to a
    if opposite.any():
        perp = np.cross(a[opposite], np.array([1.0, 0.0, 0.0]))
        perp = np.where(
            np.linalg.norm(perp, axis=-1, keepdims=True) < 1e-3, np.cross(a[opposite], [0.0, 1.0, 0.0]), perp
        )
        xyz[opposite], w[opposite] = perp, 0.0
    return qnormalize(np.concatenate([w, xyz], axis=-1))


def _kabsch(rest: np.ndarray, target: np.ndarray, weights: np.ndarray) -> np.ndarray:
    """(T, 4) rotations R minimising sum_k w_k |R rest_k - target_k(t)|^2 over unit vectors
    rest (K, 3) and target (T, K, 3): Kabsch's SVD solution, one batched SVD."""
    H = np.einsum("k,ki,tkj->tij", weights, rest, target)  # sum_k w r d^T
    U, _, Vt = np.linalg.svd(H)
    d = np.sign(np.linalg.det(U) * np.linalg.det(Vt))  # det(V U^T)
    D = np.zeros_like(H)
    D[:, 0, 0] = D[:, 1, 1] = 1.0
    D[:, 2, 2] = np.where(d == 0, 1.0, d)
    R = np.einsum("tji,tjk,tlk->til", Vt, D, U)  # V D U^T
    return Rotation.from_matrix(R).as_quat(scalar_first=True)


def _targets(skeleton: Skeleton, feature: np.ndarray) -> dict[int, list[tuple[int, np.ndarray]]]:
    """Feature joint -> [(feature descendant k, rest vector from the joint to k in its
    frame)]: its nearest feature descendants, and where such a descendant sits on the joint
    (a zero rest vector, e.g. the CMU clavicles on the chest), that one's own instead."""
    parents = skeleton.parents
    is_feature = np.zeros(skeleton.n_joints, dtype=bool)
    is_feature[feature] = True
    nearest = np.full(skeleton.n_joints, -1)  # nearest feature ancestor (strict)
    rest = np.zeros((skeleton.n_joints, 3))  # rest vector from that ancestor
    for j in range(1, skeleton.n_joints):  # parents precede children
        p = parents[j]
        nearest[j], rest[j] = (p, skeleton.offsets[j]) if is_feature[p] else (nearest[p], rest[p] + skeleton.offsets[j])
    out: dict[int, list[tuple[int, np.ndarray]]] = {int(j): [] for j in feature}
    for k in feature[1:] if feature[0] == 0 else feature:
        if nearest[k] >= 0:
            out[int(nearest[k])].append((int(k), rest[k]))
    for j in list(out):  # replace descendants sitting on the joint by their own targets
        todo, kept = list(out[j]), []
        while todo:
            k, r = todo.pop(0)
            if np.linalg.norm(r) > _EPS:
                kept.append((k, r))
            else:
                todo += [(kk, r + rr) for kk, rr in out[k]]
        out[j] = kept
    return out


def positions_to_motion(positions: np.ndarray, skeleton: Skeleton, layout: FeatureLayout, fps: float) -> Motion:
    """A Motion on ``skeleton`` whose feature joints point where ``positions`` (T, J_f, 3),
    the global positions of ``layout``'s joints, say (module docstring); its root is at the
    generated root position."""
    P = np.asarray(positions, dtype=float)
    T = len(P)
    feature = np.asarray(layout.joints, dtype=np.int64)
    if P.ndim != 3 or P.shape[1:] != (len(feature), 3):
        raise ValueError(f"positions_to_motion: positions must be (T, {len(feature)}, 3); got {P.shape}")
    if feature[0] != 0:
        raise ValueError("positions_to_motion: the layout's first joint must be the rig's root")
    world = {int(j): P[:, k] for k, j in enumerate(feature)}
    targets = _targets(skeleton, feature)
    G = np.zeros((T, skeleton.n_joints, 4))
    for j in range(skeleton.n_joints):  # parents first: a loop over joints, vectorised over frames
        parent = np.tile([1.0, 0.0, 0.0, 0.0], (T, 1)) if j == 0 else G[:, skeleton.parents[j]]
        pairs = targets.get(j, [])
        if not pairs:
            G[:, j] = parent
            continue
        rest = np.stack([r / np.linalg.norm(r) for _, r in pairs])
        d = np.stack([world[k] - world[j] for k, _ in pairs], axis=1)  # (T, K, 3)
        d = d / np.maximum(np.linalg.norm(d, axis=-1, keepdims=True), _EPS)
        if len(pairs) >= 2 and np.linalg.matrix_rank(rest, tol=1e-3) >= 2:
            G[:, j] = _kabsch(rest, d, np.array([np.linalg.norm(r) for _, r in pairs]))
        else:
            a = qrot(parent, np.broadcast_to(rest[0], (T, 3)))
            G[:, j] = qmul(_swing(a, d[:, 0]), parent)
    local = G.copy()
    local[:, 1:] = qmul(qinv(G[:, skeleton.parents[1:]]), G[:, 1:])
    return Motion(skeleton=skeleton, root_pos=P[:, 0].copy(), rotations=qfix(qnormalize(local), axis=0), fps=float(fps))


def sample_motions(saved: SavedVAE, space: FeatureSpace, rig: StyleRig, n: int, seed: int = 0) -> list[Motion]:
    """``n`` random clips of one VAE/CVAE (``load_vae``'s triple; its info names the
    primitive) as Motions on the rig, at the primitive's real-time frame rate; the draws
    come from the seeded generator of :func:`.model.sample_maps`. Each starts at the origin
    facing +x."""
    vae, shape, info = saved
    primitive = str(info.get("primitive", ""))
    if primitive not in rig.fps:
        raise ValueError(f"style rig: no frame rate for primitive {primitive!r} (has {', '.join(sorted(rig.fps))})")
    if n < 1:
        raise ValueError(f"samples: need at least 1; got {n}")
    feats = sample_features(vae, shape, space, int(n), int(seed))
    pos = features_to_positions(feats, rig.layout)
    return [positions_to_motion(p, rig.skeleton, rig.layout, rig.fps[primitive]) for p in pos]


def feature_position_error(motion: Motion, positions: np.ndarray, layout: FeatureLayout) -> float:
    """Mean distance (cm) between a motion's feature joints and ``positions`` (T, J_f, 3)."""
    return float(np.linalg.norm(motion.positions()[:, layout.joints] - positions, axis=-1).mean())
