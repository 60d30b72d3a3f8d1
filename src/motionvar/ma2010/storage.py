"""The fitted :class:`~motionvar.ma2010.svi.StyleVariationModel` on disk, in the project's
one model format (:mod:`motionvar.io.model_file`): arrays in ``<base>.npz``, the joint
groups, network structure, variogram models and the rig's joint map in ``<base>.json``.
Loading rebuilds the model exactly as it was fitted (the latent variation parameters
tau/xi, the parameter propagation network of Eq. 10, each joint group's clip codec and
universal Kriging of Eq. 11-13, the standard skeleton, the examples' style parameters),
so that synthesis never refits: ``load_style_variation_model(path).model.predict(...)``
gives the same clips as the model that was saved.

Only what prediction and sampling need is kept of each Kriging: the standardisation,
the trend hyperplane, the residuals, the scaled example parameters, the variogram and the
inverse bordered matrix (not the binned semivariogram it was fitted to, which only the
variogram figure draws).
"""

from __future__ import annotations

import inspect
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..core.joint_map import JointMap
from ..core.skeleton import Skeleton
from ..io.model_file import load_model, model_base, save_model
from .kriging import UniversalKriging, Variogram
from .network import NodeModel, PropagationNetwork
from .representation import ClipCodec
from .svi import StyleVariationModel

KIND = "ma2010.StyleVariationModel"
VERSION = 1
_KRIGING_ARRAYS = ("x_mean_", "x_scale_", "trend_", "residuals_", "x_", "bordered_inv_")


def _init_settings(obj: object) -> dict:
    """The constructor arguments of ``obj`` that it keeps as attributes of the same name
    (UniversalKriging, StyleVariationModel), JSON-able ones only: a setting added to either
    class later is saved and restored without touching this module."""
    names = [n for n in inspect.signature(type(obj).__init__).parameters if n != "self"]
    out = {}
    for n in names:
        v = getattr(obj, n, inspect.Parameter.empty)
        if v is None or isinstance(v, (bool, int, float, str)):
            out[n] = v
    return out


@dataclass
class SavedStyleModel:
    """A loaded model with what the file says about it: the rig's joint map (feet for the
    footskate cleanup, joint groups), the style parameters' names and units, the ids and
    subjects of the example cycles, and the fitting settings."""

    model: StyleVariationModel
    joint_map: JointMap
    style_names: list[str]
    style_unit: str
    clip_ids: list[str]
    subjects: list[str]
    settings: dict


def _skeleton_arrays(sk: Skeleton) -> dict[str, np.ndarray]:
    ends = np.array(sorted(sk.end_sites), dtype=np.int64)
    return {
        "skeleton.parents": sk.parents,
        "skeleton.offsets": sk.offsets,
        "skeleton.end_site_joints": ends,
        "skeleton.end_site_offsets": np.array([sk.end_sites[j] for j in ends], dtype=float).reshape(-1, 3),
    }


def save_style_variation_model(
    path: str | Path,
    model: StyleVariationModel,
    joint_map: JointMap,
    clip_ids: list[str] | None = None,
    subjects: list[str] | None = None,
    style_names: tuple[str, ...] = ("left_support_stride", "right_support_stride"),
    style_unit: str = "cm",
    settings: dict | None = None,
) -> list[Path]:
    """Write a fitted model as ``<base>.npz`` + ``<base>.json``; returns both paths.
    ``style_names``/``style_unit`` name the style parameters c (Ma 2010 Sec. 7.2: the
    strides of the left and the right support phase, cm); ``settings`` (JSON-able) records
    how it was fitted."""
    if not hasattr(model, "interpolators_"):
        raise ValueError("save_style_variation_model: the model is not fitted")
    sk = model.skeleton_
    if model.style_.shape[1] != len(style_names):
        raise ValueError(
            f"save_style_variation_model: {model.style_.shape[1]} style parameters but names {list(style_names)}"
        )
    arrays = {
        "eta": model.eta_,
        "style": model.style_,
        "reference_keys": model.reference_keys_,
        "key_times_span": model.key_times_span_,
        **_skeleton_arrays(sk),
    }
    groups, nodes, interps = {}, {}, {}
    for g, joints in model.groups.items():
        arrays[f"groups.{g}"] = joints
        arrays[f"xi.{g}"] = model.xi_[g]
        groups[g] = int(model.tau_[g])
    for node, m in model.network_.nodes_.items():
        arrays[f"network.{node}.weights"] = m.weights
        nodes[node] = {"parents": list(m.parents), "mu": m.mu, "sigma2": m.sigma2}
    for g, (codec, krig) in model.interpolators_.items():
        arrays[f"codec.{g}.reference"] = codec.reference_
        arrays[f"codec.{g}.joints"] = codec.joints
        for k in _KRIGING_ARRAYS:
            arrays[f"kriging.{g}.{k}"] = getattr(krig, k)
        v = krig.variogram_
        interps[g] = {
            "timing": bool(codec.timing),
            "key_timing": codec.key_timing,
            "root_height": bool(codec.root_height),
            "kriging": _init_settings(krig),
            "variogram": {"model": v.model, "nugget": float(v.nugget), "params": [float(p) for p in v.params]},
        }
    info = {
        "kind": KIND,
        "version": VERSION,
        "skeleton": {"names": list(sk.names)},
        "tau": groups,
        "group_order": list(model.groups),
        "structure": {n: list(p) for n, p in model.network_.structure.items()},
        "network": nodes,
        "interpolators": interps,
        "timing_group": model.timing_group_,
        "n_keys": int(model.n_keys_),
        "fps": float(model.fps_),
        "model_settings": {k: v for k, v in _init_settings(model).items() if k not in ("groups", "structure")},
        "structure_setting": model.structure if isinstance(model.structure, str) else "explicit",
        "joint_map": {"joints": dict(joint_map.joints), "groups": {g: list(v) for g, v in joint_map.groups.items()}},
        "style_names": list(style_names),
        "style_unit": style_unit,
        "clip_ids": [str(c) for c in (clip_ids or [])],
        "subjects": [str(s) for s in (subjects or [])],
        "settings": dict(settings or {}),
    }
    return save_model(path, arrays, info)


def _kriging(a: dict[str, np.ndarray], g: str, spec: dict) -> UniversalKriging:
    krig = UniversalKriging(**spec["kriging"])
    for k in _KRIGING_ARRAYS:
        setattr(krig, k, np.asarray(a[f"kriging.{g}.{k}"], dtype=float))
    v = spec["variogram"]
    krig.variogram_ = Variogram(v["model"], float(v["nugget"]), tuple(float(p) for p in v["params"]))
    krig.variogram_fit_ = None  # the binned semivariogram is not saved (module docstring)
    return krig


def load_style_variation_model(path: str | Path) -> SavedStyleModel:
    """Read a model written by :func:`save_style_variation_model`; FileNotFoundError for a
    missing file and ValueError naming the file when it is not a complete model."""
    arrays, info = load_model(path, kind=KIND)
    source = model_base(path)
    try:
        if info.get("version") != VERSION:
            raise ValueError(f"version {info.get('version')} (expected {VERSION})")
        sk = Skeleton(
            names=tuple(info["skeleton"]["names"]),
            parents=arrays["skeleton.parents"],
            offsets=arrays["skeleton.offsets"],
            end_sites={
                int(j): np.asarray(o)
                for j, o in zip(arrays["skeleton.end_site_joints"], arrays["skeleton.end_site_offsets"])
            },
        )
        order = info["group_order"]
        groups = {g: arrays[f"groups.{g}"] for g in order}
        structure = {n: tuple(p) for n, p in info["structure"].items()}
        model = StyleVariationModel(groups, structure, **info["model_settings"])
        model.eta_ = arrays["eta"]
        model.tau_ = {g: int(info["tau"][g]) for g in order}
        model.xi_ = {g: arrays[f"xi.{g}"] for g in order}
        net = PropagationNetwork(structure)
        net.nodes_ = {
            n: NodeModel(
                tuple(spec["parents"]), arrays[f"network.{n}.weights"], float(spec["mu"]), float(spec["sigma2"])
            )
            for n, spec in info["network"].items()
        }
        model.network_ = net
        model.timing_group_ = info["timing_group"]
        model.n_keys_ = int(info["n_keys"])
        model.reference_keys_ = arrays["reference_keys"]
        model.skeleton_ = sk
        model.fps_ = float(info["fps"])
        model.style_ = arrays["style"]
        model.key_times_span_ = arrays["key_times_span"]
        model.interpolators_ = {}
        for g, spec in info["interpolators"].items():
            codec = ClipCodec(
                arrays[f"codec.{g}.joints"],
                spec["timing"],
                spec["root_height"],
                spec.get("key_timing", "absolute"),  # files written before the setting: absolute
            ).set_fitted(arrays[f"codec.{g}.reference"])
            model.interpolators_[g] = (codec, _kriging(arrays, g, spec))
        jm = JointMap.from_dict(info["joint_map"], origin=f"{source}.json")
        return SavedStyleModel(
            model,
            jm,
            list(info["style_names"]),
            info["style_unit"],
            list(info["clip_ids"]),
            list(info["subjects"]),
            dict(info["settings"]),
        )
    except (KeyError, TypeError, ValueError) as exc:
        raise ValueError(f"{source}.npz/.json: not a complete {KIND} ({exc!r}); rerun rule ma2010_model") from exc
