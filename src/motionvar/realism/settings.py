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
    stance_range / travel_tolerance / min_clearance_cm: a walk's gait events count only where
        every stride's stance fraction lies in ``stance_range``, its length within
        ``travel_tolerance`` of the root's travel and no swing's toe lower than
        ``min_clearance_cm`` (:func:`motionvar.metrics.realism.implausible_events`). The
        detected stance of Bandai-Namco's 60 captured walks, stylised ones included, lies in
        0.43-0.82 of the cycle, their strides within 0.85-1.16 of the root's travel, their
        lowest swing clearance at -0.03 cm; running has a stance under 0.4 (Novacheck 1998), a
        missed or spurious footfall changes a stride by about half; markerless feet pass 3 cm
        below their contact height.
    min_clips_per_subject: subjects with fewer clips of a behaviour are left out of the
        within- against between-subject spread.
    min_subjects: the within- against between-subject spread needs this many subjects: with
        two walks each, the ratio is known to about sqrt(1 / (2 (k - 1)) + 1 / (2 k)) of itself
        (23 % at 20 subjects, 33 % at 10), against a band spanning a factor of 3.6.
    min_reaches: the share of reaches with a corrective sub-movement needs this many reaches:
        at a share of 0.1, the band's low edge, its standard error is then 0.039."""

    SECTION = "realism"

    noise_band_hz: tuple[float, float] = (8.0, 14.0)
    static_deg: float = 1e-3
    near_static_deg: float = 0.5
    toe_window: tuple[float, float] = (0.25, 0.75)
    peak_prominence: float = 0.1
    stance_range: tuple[float, float] = (0.35, 0.9)
    travel_tolerance: float = 0.25
    min_clearance_cm: float = -1.0
    min_clips_per_subject: int = 2
    min_subjects: int = 20
    min_reaches: int = 60
