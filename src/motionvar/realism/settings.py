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
        at a share of 0.1, the band's low edge, its standard error is then 0.039.
    idle_band_hz / idle_segment_s: the band (Hz) and the Welch segment length (s) of the
        sway's median frequency: above the drift a segment cannot resolve, below the 3 Hz
        under which quiet standing sway lies (Prieto et al. 1996 filter at 5 Hz).
    idle_fast_hz: the sway above this frequency is the small posture variations beside the
        posture held (Egges et al. 2004, Sec. 4: "continuous small posture variations" beside
        "posture shifts"; a balance shift takes about a second or more).
    idle_margin / idle_min_s: the pelvis stands over one foot beyond ``idle_margin`` of the
        middle of the ankles, and holds a side for at least ``idle_min_s`` s (the Egges 2004
        analysis' support margin and shortest rest, egges2004.analysis).
    idle_window_s: windows whose mean posture gives the within- against between-person
        spread of standing postures.
    min_idle_subjects: that spread needs this many people with two windows or more; with
        many windows each, the between-person SD alone is uncertain, to about
        sqrt(1 / (2 (k - 1))) of itself (35 % at 5)."""

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
    idle_band_hz: tuple[float, float] = (0.05, 3.0)
    idle_segment_s: float = 20.0
    idle_fast_hz: float = 0.5
    idle_margin: float = 0.1
    idle_min_s: float = 1.0
    idle_window_s: float = 10.0
    min_idle_subjects: int = 5
