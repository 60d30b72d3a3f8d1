"""Import a labelled folder of BVH files as clips plus a metadata table, and export
single clips as BVH (docs/design.md, "Datasets"; README, "Your own BVH data").

The labels CSV has one row per clip with the columns ``file`` (path relative to the
folder), ``subject``, ``behaviour`` and ``style``; any further columns (``variant``,
``primitive``, ...) are carried into the metadata. A labelled file lies inside the folder
and its name ends in ``.bvh`` in any case (:func:`is_bvh_name`): the workflow's data rule
takes the folder's BVH files (:func:`bvh_files`, matched the same way) as its inputs, so
that editing one reruns the import.

Labels as users write them: ``behaviour_aliases`` maps the source's behaviour words to
ours (optionally with a variant: ``sidestep_left -> sidestep, variant left``),
``style_aliases`` its style words, and ``neutral_style`` names its neutral style (mapped to
``neutral``). The source's words stay in the columns ``source_behaviour`` and
``source_style``. Clips whose behaviour (after the aliases) is not one the papers use
(:data:`BEHAVIOURS`) are left out with a count in the log; only the kept files are read.

Mixed rigs: with ``mixed_rigs="skip_minority"`` the clips whose skeleton (topology or
channel layout) differs from the most common one are left out, named in the log;
``"error"`` stops at the first such file.

A ROOT that is not the pelvis (the joint map's ``hips`` is not joint 0, e.g. Bandai's
ground-projected ``joint_Root``): every clip is re-rooted at the hips
(:func:`motionvar.core.reroot.reroot`), so that joint 0 is the pelvis downstream.

Clips that are each one primitive already (e.g. DFKI's single walk steps): with
``primitive_labels = {"column": ..., "names": {label: primitive}}`` each clip gets
``primitive`` = the name its label maps to and ``segments`` = ``"name:0:n_frames"`` (the
format of the synthetic data's ground truth, read by ``prep.use_ground_truth_segments``);
see :func:`primitive_names`.

The CMU files of the cgspeed conversion start with a synthetic T-pose at frame 0 that
the converter added; pass ``drop_first_frame=True`` to remove it (the 3dsMax-friendly
release, e.g. 131_*.bvh, has none). No heuristic tries to detect it.
"""

from __future__ import annotations

import logging
import os
from collections import Counter
from collections.abc import Mapping
from pathlib import Path

import pandas as pd

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..core.reroot import RerootError, reroot, reroot_skeleton
from ..core.skeleton import Skeleton
from .bvh import read_bvh, write_bvh
from .dataset import DatasetError

log = logging.getLogger(__name__)

REQUIRED_COLUMNS = ("file", "subject", "behaviour", "style")
METADATA_COLUMNS = (
    "clip_id",
    "subject",
    "behaviour",
    "style",
    "variant",
    "primitive",
    "source_file",
    "source_behaviour",
    "source_style",
)
#: The behaviours the papers use (the segmenters of motionvar.prep.segmentation.SEGMENTERS;
#: tests check that the two agree).
BEHAVIOURS = ("idle", "pick", "place", "run", "sidestep", "walk")
MIXED_RIGS = ("error", "skip_minority")
#: The file name suffix of BVH files, matched without regard to case (``N.BVH``).
BVH_SUFFIX = ".bvh"
#: A behaviour alias: a behaviour, or {"behaviour": ..., "variant": ...}.
BehaviourAlias = str | Mapping[str, str]
#: Labels of clips that are one primitive each: {"column": labels column, "names": {label value: primitive}}.
PrimitiveLabels = Mapping[str, object]


def is_bvh_name(name: str) -> bool:
    """Whether a file name ends in :data:`BVH_SUFFIX`, in any case."""
    return name.lower().endswith(BVH_SUFFIX)


def bvh_files(folder: str | Path) -> list[Path]:
    """The BVH files (:func:`is_bvh_name`) in ``folder`` and its subfolders, sorted;
    linked subfolders are not followed."""
    return sorted(Path(root, f) for root, _, files in os.walk(folder) for f in files if is_bvh_name(f))


def _read_labels(labels_csv: Path) -> pd.DataFrame:
    if not labels_csv.is_file():
        raise DatasetError(f"{labels_csv}: labels CSV not found")
    try:
        labels = pd.read_csv(labels_csv, dtype=str, keep_default_na=False)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        raise DatasetError(f"{labels_csv}: not a readable CSV ({exc})") from exc
    labels.columns = [str(c).strip() for c in labels.columns]
    for col in REQUIRED_COLUMNS:
        if col not in labels.columns:
            raise DatasetError(f"{labels_csv}: missing required column {col!r} (has {list(labels.columns)})")
    reserved = [c for c in ("source_behaviour", "source_style", "clip_id", "source_file") if c in labels.columns]
    if reserved:
        raise DatasetError(f"{labels_csv}: columns {reserved} are written by the import; rename them")
    if labels.empty:
        raise DatasetError(f"{labels_csv}: no clips listed")
    labels.index = labels.index + 2  # the CSV line of each row (header = line 1)
    return labels


def _alias_target(word: str, alias: BehaviourAlias) -> tuple[str, str]:
    """(behaviour, variant) of one behaviour alias; ValueError naming it if malformed."""
    if isinstance(alias, str):
        behaviour, variant = alias, ""
    elif (
        isinstance(alias, Mapping)
        and isinstance(alias.get("behaviour"), str)
        and set(alias) <= {"behaviour", "variant"}
    ):
        behaviour, variant = alias["behaviour"], str(alias.get("variant", ""))
    else:
        raise DatasetError(
            f"behaviour_aliases: {word}: expected a behaviour or {{behaviour: ..., variant: ...}}; got {alias!r}"
        )
    if behaviour not in BEHAVIOURS:
        raise DatasetError(
            f"behaviour_aliases: {word} -> {behaviour!r} is not a behaviour the papers use ({', '.join(BEHAVIOURS)})"
        )
    return behaviour, variant


def apply_label_aliases(
    labels: pd.DataFrame,
    behaviour_aliases: Mapping[str, BehaviourAlias] | None = None,
    style_aliases: Mapping[str, str] | None = None,
    neutral_style: str | None = None,
    labels_csv: str | Path = "labels",
) -> pd.DataFrame:
    """Labels with our behaviour/style words; the source's in ``source_behaviour`` and
    ``source_style``. An alias with a variant fills an empty ``variant``; a row whose own
    variant differs is an error naming its CSV line (the index of ``labels``)."""
    behaviour_aliases = dict(behaviour_aliases or {})
    style_aliases = dict(style_aliases or {})
    if neutral_style:
        if style_aliases.get(neutral_style, "neutral") != "neutral":
            raise DatasetError(
                f"neutral_style {neutral_style!r} is also in style_aliases "
                f"(-> {style_aliases[neutral_style]!r}); keep one"
            )
        style_aliases[neutral_style] = "neutral"
    out = labels.copy()
    out["source_behaviour"] = out["behaviour"].str.strip()
    out["source_style"] = out["style"].str.strip()
    targets = {w: _alias_target(w, a) for w, a in behaviour_aliases.items()}
    out["behaviour"] = out["source_behaviour"].map(lambda w: targets[w][0] if w in targets else w)
    alias_variant = out["source_behaviour"].map(lambda w: targets[w][1] if w in targets else "")
    own = out["variant"].str.strip() if "variant" in out else pd.Series("", index=out.index)
    clash = (alias_variant != "") & (own != "") & (own != alias_variant)
    if clash.any():
        line = clash.idxmax()
        raise DatasetError(
            f"{labels_csv}:{line}: variant {own[line]!r} contradicts behaviour_aliases "
            f"({out.at[line, 'source_behaviour']} -> variant {alias_variant[line]!r})"
        )
    out["variant"] = own.where(own != "", alias_variant)
    out["style"] = out["source_style"].map(lambda w: style_aliases.get(w, w))
    unused = [w for w in behaviour_aliases if w not in set(out["source_behaviour"])]
    unused += [w for w in style_aliases if w not in set(out["source_style"])]
    if unused:
        log.warning("%s: aliases that match no clip: %s", labels_csv, ", ".join(unused))
    return out


def keep_paper_behaviours(labels: pd.DataFrame, labels_csv: str | Path = "labels") -> pd.DataFrame:
    """The rows whose behaviour is in :data:`BEHAVIOURS`; the others are logged by count.
    DatasetError if none is left."""
    keep = labels["behaviour"].isin(BEHAVIOURS)
    if not keep.any():
        found = ", ".join(sorted(set(labels["behaviour"])))
        raise DatasetError(
            f"{labels_csv}: no clip has a behaviour the papers use ({', '.join(BEHAVIOURS)}); "
            f"found {found}: map the source's words with behaviour_aliases"
        )
    if not keep.all():
        counts = labels.loc[~keep, "behaviour"].value_counts().sort_index()
        log.warning(
            "left out %d clips of behaviours no paper uses: %s",
            int((~keep).sum()),
            ", ".join(f"{b} {n}" for b, n in counts.items()),
        )
    return labels[keep]


def _primitive_label_map(primitive_labels: PrimitiveLabels) -> tuple[str, dict[str, str]]:
    """(column, {label value: primitive name}) of a ``primitive_labels`` option; label
    values as text (YAML's 0 and "0" agree). DatasetError naming the key if malformed."""
    if not isinstance(primitive_labels, Mapping) or set(primitive_labels) != {"column", "names"}:
        raise DatasetError(
            f"primitive_labels: expected {{column: ..., names: {{label: primitive, ...}}}}; got {primitive_labels!r}"
        )
    column, names = primitive_labels["column"], primitive_labels["names"]
    if not isinstance(column, str) or not column.strip():
        raise DatasetError(f"primitive_labels.column: expected a labels column name; got {column!r}")
    if not isinstance(names, Mapping) or not names:
        raise DatasetError(f"primitive_labels.names: expected {{label: primitive, ...}}; got {names!r}")
    bad = {k: v for k, v in names.items() if not isinstance(v, str) or not v.strip() or set(v) & set(":;")}
    if bad:
        raise DatasetError(f"primitive_labels.names: {bad} are not primitive names (non-empty, no ':' or ';')")
    return column.strip(), {str(k).strip(): v.strip() for k, v in names.items()}


def primitive_names(
    labels: pd.DataFrame, primitive_labels: PrimitiveLabels, labels_csv: str | Path = "labels"
) -> pd.Series:
    """Each row's primitive name: its value in ``primitive_labels["column"]`` mapped by
    ``primitive_labels["names"]`` (index: that of ``labels``, the CSV lines). DatasetError
    naming the CSV line and the mapping for a value the names lack, and for a labels CSV
    that also has a ``segments`` column or a filled ``primitive`` column of its own."""
    column, names = _primitive_label_map(primitive_labels)
    if column not in labels.columns:
        raise DatasetError(
            f"{labels_csv}: primitive_labels.column {column!r} is not a column (has {list(labels.columns)})"
        )
    if "segments" in labels.columns:
        raise DatasetError(f"{labels_csv}: has a 'segments' column and primitive_labels sets it; keep one")
    if column != "primitive" and "primitive" in labels.columns and labels["primitive"].str.strip().ne("").any():
        raise DatasetError(
            f"{labels_csv}: has a filled 'primitive' column and primitive_labels sets it from {column!r}; keep one"
        )
    values = labels[column].str.strip()
    unmapped = ~values.isin(list(names))
    if unmapped.any():
        line = unmapped.idxmax()
        mapping = ", ".join(f"{k} -> {v}" for k, v in names.items())
        raise DatasetError(
            f"{labels_csv}:{line}: {column} {values[line]!r} is not in primitive_labels.names "
            f"({mapping}); {int(unmapped.sum())} rows unmapped"
        )
    return values.map(names)


def _layout(sk: Skeleton) -> tuple:
    return sk.names, tuple(sk.parents.tolist()), sk.rotation_orders, sk.position_channels


def _describe_difference(a: Skeleton, b: Skeleton) -> str:
    if a.n_joints != b.n_joints:
        return f"{a.n_joints} joints, not {b.n_joints}"
    if a.names != b.names or not (a.parents == b.parents).all():
        return "another joint hierarchy"
    return "another channel layout"


def _outside(name: str) -> bool:
    """Whether a labels ``file`` entry names a path outside the folder (absolute, or up
    through ``..`` beyond it)."""
    return os.path.isabs(name) or os.path.normpath(name).split(os.sep)[0] == os.pardir


def _check_files(labels: pd.DataFrame, folder: Path, labels_csv: Path) -> list[Path]:
    """Paths of the labelled files; errors name the CSV line (the index of ``labels``)."""
    paths = []
    for line, name in labels["file"].str.strip().items():
        if not name:
            raise DatasetError(f"{labels_csv}:{line}: empty 'file' entry")
        if _outside(name):
            raise DatasetError(
                f"{labels_csv}:{line}: labelled file {name!r} lies outside the dataset folder {folder}: "
                f"move it into the folder (the run tracks only the folder's files)"
            )
        if not is_bvh_name(name):
            raise DatasetError(
                f"{labels_csv}:{line}: labelled file {name!r} is not a .bvh file (the run tracks only "
                f"files whose name ends in .bvh, in any case)"
            )
        path = folder / name
        if not path.is_file():
            raise DatasetError(f"{labels_csv}:{line}: labelled file {name!r} does not exist in {folder}")
        paths.append(path)
    stems = pd.Series([p.stem for p in paths], index=labels.index)
    dup = stems[stems.duplicated(keep=False)]
    if len(dup):
        lines = ", ".join(str(i) for i in dup.index)
        raise DatasetError(f"{labels_csv}: duplicate clip ids {sorted(set(dup))} (file stems at lines {lines})")
    return paths


def _one_rig(motions: list[Motion], paths: list[Path], mixed_rigs: str) -> list[int]:
    """Indices of the clips on the most common rig; the others are left out (logged) or,
    with ``mixed_rigs="error"``, stop the import at the first one."""
    keys = [_layout(m.skeleton) for m in motions]
    if mixed_rigs == "error":
        for k, p in zip(keys, paths):
            if k != keys[0]:
                raise DatasetError(
                    f"{p}: skeleton topology or channel layout differs from {paths[0]} (all clips "
                    f"must share one; mixed_rigs: skip_minority leaves the minority out)"
                )
        return list(range(len(motions)))
    counts = Counter(keys).most_common()
    if len(counts) > 1 and counts[0][1] == counts[1][1]:
        a, b = (paths[keys.index(k)] for k, _ in counts[:2])
        raise DatasetError(
            f"{b}: skeleton topology or channel layout differs from {a}, and no rig holds a "
            f"majority of the clips ({counts[0][1]} and {counts[1][1]}): label one rig per dataset"
        )
    kept = [i for i, k in enumerate(keys) if k == counts[0][0]]
    if len(kept) < len(motions):
        ref = motions[kept[0]].skeleton
        left = [i for i in range(len(motions)) if keys[i] != counts[0][0]]
        log.warning(
            "left out %d clips on another rig than the other %d (%s): %s",
            len(left),
            len(kept),
            _describe_difference(motions[left[0]].skeleton, ref),
            ", ".join(paths[i].name for i in left),
        )
    return kept


def _fit_joint_map(joint_map: JointMap, skeleton: Skeleton, source: str) -> int:
    """Validate ``joint_map`` on ``skeleton``; the index of its hips. If the hips is not
    joint 0, check that the rig can be re-rooted there and that the groups list no joint
    above it."""
    try:
        joint_map.validate(skeleton, source=source)
    except ValueError as exc:
        raise DatasetError(str(exc)) from exc
    hips = joint_map.index(skeleton, "hips")
    if hips == 0:
        return hips
    where = f"{source} ({joint_map.origin})" if joint_map.origin else source
    try:
        new, _ = reroot_skeleton(skeleton, hips)
    except RerootError as exc:
        raise DatasetError(f"{where}: hips = {skeleton.names[hips]} is not the BVH ROOT and {exc}") from exc
    above = [n for g, ns in joint_map.groups.items() for n in ns if n not in new.names]
    if above:
        raise DatasetError(
            f"{where}: groups list {above}, above the hips {skeleton.names[hips]}; the clips are "
            f"re-rooted at the hips, which removes them: delete them from the groups"
        )
    log.info(
        "re-rooting every clip at the joint map's hips %s (the BVH ROOT is %s)", skeleton.names[hips], skeleton.names[0]
    )
    return hips


def import_bvh_folder(
    folder: str | Path,
    labels_csv: str | Path,
    unit_cm: float,
    drop_first_frame: bool = False,
    joint_map: JointMap | None = None,
    behaviour_aliases: Mapping[str, BehaviourAlias] | None = None,
    style_aliases: Mapping[str, str] | None = None,
    neutral_style: str | None = None,
    mixed_rigs: str = "skip_minority",
    primitive_labels: PrimitiveLabels | None = None,
) -> tuple[list[Motion], pd.DataFrame]:
    """Read the BVH files listed in ``labels_csv`` (a relative path is taken inside
    ``folder``) with lengths scaled by ``unit_cm`` (cm per file unit, e.g.
    ``CMU_UNIT_CM``). Returns the clips and their metadata (one row per clip, columns
    :data:`METADATA_COLUMNS` plus any extra label columns). Aliases, behaviours left out,
    mixed rigs and re-rooting at the joint map's hips: see the module docstring. With
    ``primitive_labels`` (:func:`primitive_names`) every clip is one primitive: its
    ``primitive`` is the mapped name and a ``segments`` column holds ``"name:0:n_frames"``.
    """
    if mixed_rigs not in MIXED_RIGS:
        raise DatasetError(f"mixed_rigs: {mixed_rigs!r} is not one of {list(MIXED_RIGS)}")
    folder = Path(folder)
    labels_csv = Path(labels_csv)
    if not labels_csv.is_absolute():
        labels_csv = folder / labels_csv
    if not folder.is_dir():
        raise DatasetError(f"{folder}: BVH folder not found")
    if not bvh_files(folder):
        raise DatasetError(f"{folder}: no .bvh files in the folder")
    labels = _read_labels(labels_csv)
    labels = apply_label_aliases(labels, behaviour_aliases, style_aliases, neutral_style, labels_csv)
    labels = keep_paper_behaviours(labels, labels_csv)
    if primitive_labels is not None:
        labels = labels.assign(primitive=primitive_names(labels, primitive_labels, labels_csv))
    paths = _check_files(labels, folder, labels_csv)
    motions = [read_bvh(path, scale=unit_cm) for path in paths]
    kept = _one_rig(motions, paths, mixed_rigs)
    motions, paths, labels = [motions[i] for i in kept], [paths[i] for i in kept], labels.iloc[kept]
    if drop_first_frame:
        short = [p for p, m in zip(paths, motions) if m.n_frames < 2]
        if short:
            raise DatasetError(f"{short[0]}: only 1 frame; cannot drop the first frame")
        motions = [m.slice(1, m.n_frames) for m in motions]
    if joint_map is not None:
        hips = _fit_joint_map(joint_map, motions[0].skeleton, source=f"joint map for {paths[0]}")
        motions = [reroot(m, hips) for m in motions]
    meta = pd.DataFrame(
        {
            "clip_id": [p.stem for p in paths],
            "subject": labels["subject"].to_numpy(),
            "behaviour": labels["behaviour"].to_numpy(),
            "style": labels["style"].to_numpy(),
            "variant": labels["variant"].to_numpy(),
            "primitive": labels["primitive"].to_numpy() if "primitive" in labels else "",
            "source_file": [str(p) for p in paths],
            "source_behaviour": labels["source_behaviour"].to_numpy(),
            "source_style": labels["source_style"].to_numpy(),
        }
    )
    extra = [c for c in labels.columns if c not in METADATA_COLUMNS and c != "file"]
    for c in extra:
        meta[c] = labels[c].to_numpy()
    if primitive_labels is not None:
        meta["segments"] = [f"{p}:0:{m.n_frames}" for p, m in zip(meta["primitive"], motions)]
    return motions, meta


def export_clip_bvh(motion: Motion, path: str | Path) -> None:
    """Write one clip as BVH in cm (Blender's BVH importer reads it; set its scale to
    0.01 for metres). Atomic; the channel layout is the clip's own."""
    write_bvh(path, motion, scale=1.0)
