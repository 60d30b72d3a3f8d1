"""RealismSettings: the thresholds of the realism statistics (rule dataset_realism)."""

from __future__ import annotations

from dataclasses import dataclass

from ..core.settings import Settings


@dataclass(frozen=True)
class RealismSettings(Settings):
    """noise_band_hz: frequency band (Hz) of the capture-noise RMS; 8 Hz lies above the
        content of walking joint trajectories (99 % of their power is below 6 Hz, Winter 2009
        ch. 2), 14 Hz below the Nyquist frequency of a 30 fps capture.
    static_deg / near_static_deg: a rotation channel whose SD over the data is below
        ``static_deg`` is static (numerically constant), below ``near_static_deg`` near-static.
    toe_window: fraction of each swing in which its minimum toe clearance is taken.
    peak_prominence: a hand-speed peak counts when its prominence is at least this fraction
        of the reach's peak speed (a sub-movement, Meyer et al. 1988).
    min_clips_per_subject: subjects with fewer clips of a behaviour are left out of the
        within- against between-subject spread."""

    SECTION = "realism"

    noise_band_hz: tuple[float, float] = (8.0, 14.0)
    static_deg: float = 1e-3
    near_static_deg: float = 0.5
    toe_window: tuple[float, float] = (0.25, 0.75)
    peak_prominence: float = 0.1
    min_clips_per_subject: int = 2
