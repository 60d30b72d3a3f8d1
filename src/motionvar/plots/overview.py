"""Dataset overview: stick-figure key frames of one clip per behaviour and one clip per
walking style, so that a reader sees what the data looks like before any result."""

from __future__ import annotations

import pandas as pd
from matplotlib.figure import Figure

from ..io.dataset import MotionDataset
from .stick import KeyFrameRow, key_frame_grid


def _pick(rows: pd.DataFrame, style_col: str | None) -> int:
    """Index label of the first neutral clip among ``rows`` (or of the first clip)."""
    if style_col is not None:
        neutral = rows.index[rows[style_col].astype(str) == "neutral"]
        if len(neutral):
            return int(neutral[0])
    return int(rows.index[0])


def overview_clips(
    metadata: pd.DataFrame,
    behaviour_col: str = "behaviour",
    style_col: str = "style",
    walk_behaviour: str = "walk",
) -> tuple[list[tuple[str, int]], list[tuple[str, int]]]:
    """Clips that show a dataset: ``(behaviour rows, walk-style rows)``, each a list of
    (label, row position in ``metadata``), in order of first appearance.

    One clip per behaviour (its first neutral-style clip if there is one), and one clip
    per style of ``walk_behaviour`` (none if the metadata has no ``style_col``).
    """
    if behaviour_col not in metadata:
        raise ValueError(f"metadata has no {behaviour_col!r} column (columns: {list(metadata.columns)})")
    meta = metadata.reset_index(drop=True)
    style = style_col if style_col in meta else None
    behaviours = [(f"{b}", _pick(group, style)) for b, group in meta.groupby(behaviour_col, sort=False)]
    styles: list[tuple[str, int]] = []
    if style is not None:
        walks = meta[meta[behaviour_col] == walk_behaviour]
        walks = walks[walks[style].notna()]
        styles = [(f"{walk_behaviour}, {s}", int(g.index[0])) for s, g in walks.groupby(style, sort=False)]
    return behaviours, styles


def dataset_overview(
    dataset: MotionDataset,
    n_keys: int = 5,
    title: str | None = None,
    behaviour_col: str = "behaviour",
    style_col: str = "style",
    walk_behaviour: str = "walk",
) -> Figure:
    """Key frames (side view of locomotion, front view of standing) of one clip per
    behaviour (left block) and one clip per walking style (right block, where the data has
    walking styles); ``title`` is followed by what the blocks show."""
    behaviours, styles = overview_clips(dataset.metadata, behaviour_col, style_col, walk_behaviour)

    def row(label: str, i: int) -> KeyFrameRow:
        m = dataset.motion(i)
        meta = dataset.metadata.iloc[i]
        who = f" (subject {meta['subject']})" if "subject" in meta and pd.notna(meta["subject"]) else ""
        return KeyFrameRow(
            label=f"{label}{who}",
            positions=m.positions(),
            parents=m.skeleton.parents,
            names=m.skeleton.names,
            fps=m.fps,
        )

    blocks = [[row(lab, i) for lab, i in behaviours]]
    if styles:
        blocks.append([row(lab, i) for lab, i in styles])
    n_rows = max(len(b) for b in blocks)
    rows = [r for b in blocks for r in b + [None] * (n_rows - len(b))]
    shown = "one clip per behaviour" + (" (left) and per walking style (right)" if styles else "")
    return key_frame_grid(rows, n_keys=n_keys, columns=len(blocks), title=f"{title}: {shown}" if title else shown)
