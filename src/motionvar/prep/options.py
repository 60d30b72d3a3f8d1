"""PrepOptions: every threshold and choice of the preprocessing stage, in one place.

Thresholds are physical (cm, cm/s, seconds), so they hold for any frame rate; a motion
in other length units is handled through ``units_cm`` (cm per motion length unit).
Defaults were chosen from gait facts (docs/gait.md: a stance foot is still, a swing foot moves
at 1-5 m/s and clears the floor) and checked on the synthetic generator and on CMU walks;
they are not tuned to any claim.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, fields

HEADINGS = ("hips", "movement")


@dataclass(frozen=True)
class PrepOptions:
    """Options of foot-contact detection, segmentation and alignment.

    Foot contacts (per foot; a foot is planted when its ankle or its toe is both slow and
    low, Du 2022 Sec. 4.3 "contact state transitions"):
        contact_velocity_cm_s: a joint is slow below this speed (cm/s). A swinging foot
            moves at 100-500 cm/s. The synthetic generator pins the ankle from heel strike
            (0 cm/s), but on real walks (CMU 02_01) the ankle still moves at 40-60 cm/s
            in the heel rocker of the first ~0.1 s after heel contact: at 30 cm/s heel
            strikes came ~8 frames late with one frame of double support; at 50 cm/s
            double support is ~13 frames, about 10 % of the gait cycle (docs/gait.md).
        contact_height_cm: a joint is low when it is less than this above its floor level.
        floor_percentile: a joint's floor level is this percentile of its height over the
            clip (robust to floor offsets and to rigs with other ankle heights).
        velocity_window_s: speeds are central differences over this span (noise filter).
        min_contact_s: shorter contact runs are dropped (flicker at toe-off / swing).
        min_gap_s: shorter breaks inside a contact are filled.
    Reach segmentation (pick/place):
        hand_smooth_s: the hand speed is box-filtered over this span before its minimum
            at the target is taken.
        hand_stop_fraction: the hands have stopped at the first frame of the speed valley
            within this fraction of the outward speed peak above the valley's minimum.
        hand_rest_fraction: a rise of the hand speed ends the reach's valley only once the
            speed has fallen under this fraction of the peak (the hands nearly at rest on
            the target); an earlier rise is a corrective sub-movement of the reach, which
            starts while the primary still moves (at 70-90 % of its duration, Novak, Miller
            & Houk 2002; a minimum-jerk primary still moves at 13 % of its peak speed at
            90 %). On generated reaches 0.15 finds the stop of corrected reaches and keeps
            a place's release apart (tests/prep/test_prep_synthetic.py).
    Alignment (Ma 2010 Sec. 4.2, space warping):
        heading: "hips" (the facing direction from the left-hip -> right-hip vector) or
            "movement" (Ma's overall movement direction, first to last root position).
        heading_frames: frames at the start of a clip averaged for the "hips" heading.
    Pipeline:
        use_ground_truth_segments: cut at the metadata's ``segments`` column instead of
            detecting contacts (synthetic data: the generator's ground truth).
        min_primitive_s: primitives shorter than this (s) are dropped and counted (noisy
            contacts on real data cut slivers of 1-5 frames, which no later step can warp
            or resample). No step of human locomotion is shorter: a walking step lasts
            0.5-0.6 s, a running step 0.33-0.4 s at 150-180 steps/min (docs/gait.md), a
            sprint step 0.2 s at 5 steps/s. A walk's end primitive (the last heel strike to
            the clip's end) holds the closing weight transfer and the standing that follows:
            0.225 s with the generator's minimum of 0.1 s standing (tests/prep/test_prep_synthetic.py). The
            workflow's synthetic data have no primitive under 0.33 s. Whatever the value, a
            primitive needs at least 2 frames.
        skip_unsegmentable: drop clips in which no primitive is found or left (counted)
            instead of raising; with False such a clip stops the run, naming it.
        units_cm: centimetres per length unit of the motions (1.0: motions in cm).
    """

    contact_velocity_cm_s: float = 50.0
    contact_height_cm: float = 6.0
    floor_percentile: float = 2.0
    velocity_window_s: float = 1.0 / 60.0
    min_contact_s: float = 0.05
    min_gap_s: float = 0.05
    hand_smooth_s: float = 0.1
    hand_stop_fraction: float = 0.02
    hand_rest_fraction: float = 0.15
    heading: str = "hips"
    heading_frames: int = 1
    use_ground_truth_segments: bool = False
    min_primitive_s: float = 0.2
    skip_unsegmentable: bool = True
    units_cm: float = 1.0

    def __post_init__(self) -> None:
        positive = ("contact_velocity_cm_s", "contact_height_cm", "units_cm")
        non_negative = ("velocity_window_s", "min_contact_s", "min_gap_s", "hand_smooth_s", "min_primitive_s")
        for name in positive:
            if not getattr(self, name) > 0:
                raise ValueError(f"PrepOptions.{name} must be positive; got {getattr(self, name)!r}")
        for name in non_negative:
            if not getattr(self, name) >= 0:
                raise ValueError(f"PrepOptions.{name} must be >= 0; got {getattr(self, name)!r}")
        for name in ("hand_stop_fraction", "hand_rest_fraction"):
            if not 0 <= getattr(self, name) < 1:
                raise ValueError(f"PrepOptions.{name} must be in [0, 1); got {getattr(self, name)!r}")
        if not 0 <= self.floor_percentile <= 50:
            raise ValueError(f"PrepOptions.floor_percentile must be in [0, 50]; got {self.floor_percentile!r}")
        if self.heading not in HEADINGS:
            raise ValueError(f"PrepOptions.heading must be one of {HEADINGS}; got {self.heading!r}")
        if not (isinstance(self.heading_frames, int) and self.heading_frames >= 1):
            raise ValueError(f"PrepOptions.heading_frames must be an integer >= 1; got {self.heading_frames!r}")

    @classmethod
    def from_dict(cls, d: dict | None) -> "PrepOptions":
        """Options from a config mapping; unknown keys raise ValueError naming them."""
        d = dict(d or {})
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(d) - known)
        if unknown:
            raise ValueError(f"PrepOptions: unknown options {unknown} (known: {sorted(known)})")
        return cls(**d)

    def to_dict(self) -> dict:
        return asdict(self)

    def frames(self, seconds: float, fps: float) -> int:
        """A span in seconds as a whole number of frames at ``fps`` (at least 0)."""
        return max(int(round(seconds * fps)), 0)
