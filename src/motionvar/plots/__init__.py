"""Figures for the report: stick figures (any rig), key-frame grids, animated GIFs.

- :mod:`.stick`: :func:`project` (orthographic view), :func:`draw_pose`,
  :func:`plot_key_frames` (one clip's key frames side by side on an axes),
  :func:`key_frame_grid` (a figure, one clip per row, shared scale).
- :mod:`.animation`: :func:`animate_motions` (GIF of clips side by side),
  :func:`render_frames` and :func:`write_gif` for positions that are not Motions
  (e.g. a model's output).
- :mod:`.page`: :func:`gif_page` (an HTML page playing a GIF, for the report).
- :mod:`.overview`: :func:`dataset_overview`, key frames per behaviour and per walk style.
- :mod:`.realism`: :func:`realism_figure`, a dataset's realism statistics against their bands.
"""

from ..core.lazy import lazy_exports

# imported on first use (PEP 562): a GIF page's rule does not load matplotlib
_EXPORTS = {
    ".animation": ["animate_motions", "render_frames", "write_gif"],
    ".page": ["gif_page"],
    ".overview": ["dataset_overview", "overview_clips"],
    ".realism": ["realism_figure"],
    ".stick": [
        "KeyFrameRow",
        "draw_pose",
        "evenly_spaced_frames",
        "key_frame_grid",
        "plot_key_frames",
        "project",
        "view_axis",
    ],
}
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = [
    "KeyFrameRow",
    "animate_motions",
    "dataset_overview",
    "gif_page",
    "draw_pose",
    "evenly_spaced_frames",
    "key_frame_grid",
    "overview_clips",
    "realism_figure",
    "plot_key_frames",
    "project",
    "render_frames",
    "view_axis",
    "write_gif",
]
