"""ReportSettings: config section ``report``, the data figures that open the report
(rules dataset_overview and dataset_animation) and the size of every evaluation's GIF."""

from __future__ import annotations

from dataclasses import dataclass

from ..core.settings import Settings


@dataclass(frozen=True)
class ReportSettings(Settings):
    """overview_key_frames: key frames per row of the dataset overview figure.
    animation_clips: clips in the dataset animation (one per behaviour, first ones first).
    animation_seconds: length of the dataset animation (s); longer clips are cut.
    animation_fps: frames per second of every GIF (clips are resampled to it).
    animation_panel_px: width and height (pixels) of one clip's panel in a GIF."""

    SECTION = "report"

    overview_key_frames: int = 5
    animation_clips: int = 4
    animation_seconds: float = 6.0
    animation_fps: float = 20
    animation_panel_px: int = 260
