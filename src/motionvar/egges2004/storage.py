"""The fitted :class:`~motionvar.egges2004.pipeline.IdleModel` on disk, in the project's
one model format (:mod:`motionvar.io.model_file`): every array in ``<base>.npz``, the
names, frame rates and clip lists in ``<base>.json``; loading rebuilds the posture PCA,
each subject's :class:`IdleDatabase` (categories, transition graph, animations,
postures, variation model, resting segments) and skeleton exactly as they were fitted.

Variable-length lists of arrays (the animations A, the posture sets Q_c, the resting
segments per recording) are stored concatenated with their lengths.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..core.skeleton import Skeleton
from ..io.model_file import load_model, model_base, save_model
from .categories import CategoryModel
from .category_graph import CategoryGraph
from .database import IdleDatabase
from .pca import PosturePCA
from .pipeline import IdleModel
from .variations import VariationModel

KIND = "egges2004_idle_model"
VERSION = 1


def _split(joined: np.ndarray, lengths: np.ndarray) -> list[np.ndarray]:
    """Undo ``np.concatenate``: pieces of the given lengths, each its own array."""
    return [piece.copy() for piece in np.split(joined, np.cumsum(lengths)[:-1])] if len(lengths) else []


def _database_arrays(db: IdleDatabase, sk: Skeleton, p: str) -> dict[str, np.ndarray]:
    D = db.weights.size
    recs = list(db.segments.values())
    end_joints = list(sk.end_sites)
    return {
        f"{p}weights": db.weights,
        f"{p}categories.centroids": db.categories.centroids,
        f"{p}categories.centroid_category": db.categories.centroid_category,
        f"{p}categories.scale": db.categories.scale,
        f"{p}graph.counts": db.graph.counts,
        f"{p}graph.probabilities": db.graph.probabilities,
        f"{p}graph.t_min": db.graph.t_min,
        f"{p}graph.t_max": db.graph.t_max,
        f"{p}animations": np.concatenate(db.animations),
        f"{p}animation_lengths": np.array([len(a) for a in db.animations], dtype=np.int64),
        f"{p}anim_from": db.anim_from,
        f"{p}anim_to": db.anim_to,
        f"{p}postures": np.concatenate([np.reshape(q, (-1, D)) for q in db.postures]),
        f"{p}posture_counts": np.array([len(q) for q in db.postures], dtype=np.int64),
        f"{p}variations.pcs": db.variations.pcs,
        f"{p}variations.points": db.variations.points,
        f"{p}variations.counts": db.variations.counts,
        f"{p}variations.transition": db.variations.transition,
        f"{p}variations.n_clusters": db.variations.n_clusters,
        f"{p}segments": np.concatenate([np.reshape(s, (-1, 2)) for s, _ in recs] or [np.zeros((0, 2), np.int64)]),
        f"{p}segment_categories": np.concatenate([c for _, c in recs] or [np.zeros(0, np.int64)]),
        f"{p}segment_counts": np.array([len(s) for s, _ in recs], dtype=np.int64),
        f"{p}skeleton.parents": sk.parents,
        f"{p}skeleton.offsets": sk.offsets,
        f"{p}skeleton.end_site_joints": np.array(end_joints, dtype=np.int64),
        f"{p}skeleton.end_site_offsets": np.array([sk.end_sites[j] for j in end_joints], dtype=float).reshape(-1, 3),
    }


def save_idle_model(path: str | Path, model: IdleModel) -> list[Path]:
    """Write ``<base>.npz`` and ``<base>.json`` (``path`` with or without a suffix);
    returns both paths. A failed write leaves no file."""
    pca = model.pca
    arrays = {
        "pca.joints": pca.joints_,
        "pca.mean": pca.mean_,
        "pca.components": pca.components_,
        "pca.explained_variance": pca.explained_variance_,
        "pca.base_rotations": pca.base_rotations_,
    }
    subjects = []
    for i, (s, db) in enumerate(model.databases.items()):
        if db.subject != s or db.graph.names != db.categories.names:
            raise ValueError(f"idle model: the database of subject {s} is inconsistent (subject or category names)")
        sk = model.skeletons[s]
        arrays.update(_database_arrays(db, sk, f"s{i}."))
        subjects.append(
            {
                "subject": s,
                "fps": db.fps,
                "rest_speed": db.rest_speed,
                "categories": list(db.categories.names),
                "recordings": list(db.segments),
                "skeleton": {
                    "names": list(sk.names),
                    "rotation_orders": list(sk.rotation_orders),
                    "position_channels": list(sk.position_channels),
                },
            }
        )
    settings = {
        "kind": KIND,
        "version": VERSION,
        "translation_scale": pca.translation_scale,
        "subjects": subjects,
        "train_clips": model.train_clips,
        "test_clips": model.test_clips,
    }
    return save_model(path, arrays, settings)


def _database(a: dict[str, np.ndarray], entry: dict, p: str) -> tuple[IdleDatabase, Skeleton]:
    cats = CategoryModel(
        tuple(entry["categories"]),
        a[f"{p}categories.centroids"],
        a[f"{p}categories.centroid_category"],
        a[f"{p}categories.scale"],
    )
    graph = CategoryGraph(
        tuple(entry["categories"]),
        a[f"{p}graph.counts"],
        a[f"{p}graph.probabilities"],
        a[f"{p}graph.t_min"],
        a[f"{p}graph.t_max"],
    )
    variations = VariationModel(
        *(a[f"{p}variations.{k}"] for k in ("pcs", "points", "counts", "transition", "n_clusters"))
    )
    segs = _split(a[f"{p}segments"], a[f"{p}segment_counts"])
    seg_cats = _split(a[f"{p}segment_categories"], a[f"{p}segment_counts"])
    db = IdleDatabase(
        subject=entry["subject"],
        fps=entry["fps"],
        weights=a[f"{p}weights"],
        categories=cats,
        graph=graph,
        animations=_split(a[f"{p}animations"], a[f"{p}animation_lengths"]),
        anim_from=a[f"{p}anim_from"],
        anim_to=a[f"{p}anim_to"],
        postures=_split(a[f"{p}postures"], a[f"{p}posture_counts"]),
        variations=variations,
        rest_speed=entry["rest_speed"],
        segments={name: (s, c) for name, s, c in zip(entry["recordings"], segs, seg_cats, strict=True)},
    )
    sk = entry["skeleton"]
    skeleton = Skeleton(
        names=tuple(sk["names"]),
        parents=a[f"{p}skeleton.parents"],
        offsets=a[f"{p}skeleton.offsets"],
        end_sites={int(j): o for j, o in zip(a[f"{p}skeleton.end_site_joints"], a[f"{p}skeleton.end_site_offsets"])},
        rotation_orders=tuple(sk["rotation_orders"]),
        position_channels=tuple(bool(c) for c in sk["position_channels"]),
    )
    return db, skeleton


def load_idle_model(path: str | Path) -> IdleModel:
    """Read a model written by :func:`save_idle_model`; ValueError naming the file when
    it is not one (or is incomplete)."""
    arrays, settings = load_model(path, kind=KIND)
    source = model_base(path)
    try:
        pca = PosturePCA(settings["translation_scale"], arrays["pca.joints"]).set_fitted(
            arrays["pca.joints"],
            arrays["pca.mean"],
            arrays["pca.components"],
            arrays["pca.explained_variance"],
            arrays["pca.base_rotations"],
        )
        databases, skeletons = {}, {}
        for i, entry in enumerate(settings["subjects"]):
            databases[entry["subject"]], skeletons[entry["subject"]] = _database(arrays, entry, f"s{i}.")
        return IdleModel(
            pca=pca,
            databases=databases,
            skeletons=skeletons,
            train_clips={s: list(c) for s, c in settings["train_clips"].items()},
            test_clips={s: list(c) for s, c in settings["test_clips"].items()},
        )
    except (KeyError, TypeError, ValueError) as exc:
        raise ValueError(
            f"{source}.npz/.json: not a complete idle model ({exc!r}); rerun rule egges2004_model"
        ) from exc
