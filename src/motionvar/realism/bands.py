"""Bands of the realism statistics, from captured data (docs/gait.md, "Realism").

Each band is derived by one rule from the values the captured sets give the statistic, so
the numbers the band comes from are on record beside it:

- ``factor2`` (rates, lengths, noise): from half the smallest to twice the largest captured value;
- ``share`` (shares of channels): the captured range widened by 0.1 either side, within [0, 1];
- ``literature``: a statistic the shared captured sets cannot give (reaching: none holds a
  reach; within- against between-subject spread: each set has one performer), from the
  published range named in ``source``.

A band gates (``Band.gates``: the table's ``in_band`` is a verdict on the data) only where it
rejects the generator's clean data (``SynthSpec(captured_variation=False)``: strides repeated
within a walk, left equal to right, half the channels still, single-peaked reaches), in every
seed at CI size (``tests/realism/test_realism.py``); a band that clean data passes tells nothing about
realism, and its statistic is descriptive (``gates=False``: shown beside its band, never failed).
Each band says what it rests on (``basis``: sets, performers, walks, strides).

Standing idle (``behaviour`` idle): the one captured set that holds it is ReActIdle
(``config/real/reactidle_idle.yaml``: 7 performers, 11 recordings of 38-160 s, markerless), and
its bands follow the same two rules, fixed from its values before the generator's idle data was
measured: ``factor2`` for the sway's amplitude, its fast part and median frequency, the rate
of weight shifts and the within- against between-person spread of postures; ``share`` for the
channel shares. Markerless capture adds noise to the fast sway and may add shifts; the
bands' factor of two on either side is what allows for it.

The captured values are the realism tables of the shared real sets (``config/real/*``:
Xia et al. 2015 on the CMU rig, Bandai-Namco dataset-1, DFKI markerless walk steps) at their
default settings. Xia's walks hold 2-3 cycles and DFKI's files one step each: neither has a
walk of three strides (DFKI's spurious contacts in its noisy single steps give values no walk
has), so the within-walk statistics come from Bandai-Namco's 60 walks (468 strides) alone. DFKI's toe clearance is left out: its markerless feet pass below their
own contact height (5th percentile -3.3 cm), which no foot does. The bands were fixed from
these numbers before any claim was re-run on data generated inside them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd

RULES = ("factor2", "share", "literature")


@dataclass(frozen=True)
class Band:
    """A statistic's band: ``captured`` (set -> value) and the ``rule`` that widens them, or
    ``lo``/``hi`` given directly for the ``literature`` rule; ``source`` says where from,
    ``basis`` how much captured data it rests on; ``gates`` False: descriptive (module
    docstring)."""

    rule: str
    source: str
    captured: dict[str, float] = field(default_factory=dict)
    lo: float = float("nan")
    hi: float = float("nan")
    basis: str = ""
    gates: bool = True

    def __post_init__(self) -> None:
        if self.rule not in RULES:
            raise ValueError(f"Band: rule must be one of {RULES}; got {self.rule!r}")
        if self.rule != "literature" and not self.captured:
            raise ValueError("Band: a captured band needs captured values")

    @property
    def limits(self) -> tuple[float, float]:
        """(lo, hi) of the band."""
        if self.rule == "literature":
            return self.lo, self.hi
        values = np.array(list(self.captured.values()), dtype=float)
        if self.rule == "factor2":
            return float(values.min() / 2.0), float(values.max() * 2.0)
        return float(max(values.min() - 0.1, 0.0)), float(min(values.max() + 0.1, 1.0))


_BANDAI = "Bandai-Namco dataset-1 walks"
_CAPTURED = "Xia (CMU rig), Bandai-Namco, DFKI markerless walks"
_CMU = "the channels Xia's and CMU 02_01's walks agree on (CMU_CAPTURED_CHANNELS)"
_WITHIN = "1 set, 1 performer: Bandai-Namco dataset-1, 60 walks of 15 styles, 468 strides"
_CHANNELS = "3 sets, 3 performers (Xia, Bandai-Namco, DFKI markerless; 8 + 60 + 396 walks)"
_CMU_BASIS = "2 sets, 2 performers on the CMU rig (Xia's 8 walks, CMU 02_01)"
_CLEAN_PASSES = "descriptive: the generator's clean data lies in this band too"

BANDS: dict[tuple[str, str], Band] = {
    ("stride_cv_pct", "walk"): Band("factor2", _BANDAI, {"bandai_ds1": 3.073}, basis=_WITHIN),
    ("stride_time_cv_pct", "walk"): Band("factor2", _BANDAI, {"bandai_ds1": 2.860}, basis=_WITHIN),
    ("step_time_cv_pct", "walk"): Band("factor2", _BANDAI, {"bandai_ds1": 5.786}, basis=_WITHIN),
    ("stance_fraction_sd_pct", "walk"): Band("factor2", _BANDAI, {"bandai_ds1": 1.834}, basis=_WITHIN),
    ("step_asymmetry_cm", "walk"): Band("factor2", _BANDAI, {"bandai_ds1": 2.884}, basis=_WITHIN),
    ("step_asymmetry_pct", "walk"): Band("factor2", _BANDAI, {"bandai_ds1": 5.290}, basis=_WITHIN),
    ("toe_clearance_median_cm", "walk"): Band(
        "factor2",
        "Xia, Bandai-Namco walks",
        {"xia": 1.394, "bandai_ds1": 2.119},
        basis=f"2 sets, 2 performers (30 + 587 swings); {_CLEAN_PASSES}",
        gates=False,
    ),
    ("toe_clearance_p5_cm", "walk"): Band(
        "factor2",
        "Xia, Bandai-Namco walks",
        {"xia": 0.661, "bandai_ds1": 0.572},
        basis=f"2 sets, 2 performers (30 + 587 swings); {_CLEAN_PASSES}",
        gates=False,
    ),
    ("noise_rms_mm", "walk"): Band(
        "factor2",
        _CAPTURED,
        {"xia": 0.115, "bandai_ds1": 0.460, "dfki_markerless": 2.141},
        basis=f"{_CHANNELS}; {_CLEAN_PASSES}",
        gates=False,
    ),
    ("channels_static_share", "walk"): Band(
        "share", _CAPTURED, {"xia": 0.189, "bandai_ds1": 0.0, "dfki_markerless": 0.241}, basis=_CHANNELS
    ),
    ("channels_near_static_share", "walk"): Band(
        "share",
        _CAPTURED,
        {"xia": 0.078, "bandai_ds1": 0.067, "dfki_markerless": 0.046},
        basis=f"{_CHANNELS}; {_CLEAN_PASSES}",
        gates=False,
    ),
    ("channels_moving_share", "walk"): Band(
        "share", _CAPTURED, {"xia": 0.733, "bandai_ds1": 0.933, "dfki_markerless": 0.713}, basis=_CHANNELS
    ),
    ("cmu_captured_moving_kept_share", "walk"): Band("share", _CMU, {"xia": 1.0, "cmu_02_01": 1.0}, basis=_CMU_BASIS),
    ("cmu_captured_static_kept_share", "walk"): Band(
        "share", _CMU, {"xia": 1.0, "cmu_02_01": 1.0}, basis=f"{_CMU_BASIS}; {_CLEAN_PASSES}", gates=False
    ),
    ("stride_within_between", "walk"): Band(
        "literature",
        "test-retest ICC of stride length in healthy adults 0.8-0.98 (instrumented walkways, e.g. "
        "Bilney, Morris & Webster 2003): within/between SD sqrt((1 - ICC) / ICC)",
        lo=0.14,
        hi=0.5,
        basis="no captured set: each holds one performer",
    ),
    ("posture_within_between", "walk"): Band(
        "literature",
        "subject traits persist: within-subject spread below between-subject (docs/gait.md)",
        lo=0.0,
        hi=1.0,
        basis=f"no captured set: each holds one performer; {_CLEAN_PASSES}",
        gates=False,
    ),
    ("reach_multi_peak_share", "pick"): Band(
        "literature",
        "corrective sub-movements frequently follow the primary reach (Meyer et al. 1988; Novak, Miller & Houk "
        "2002): some reaches have them, not all",
        lo=0.1,
        hi=0.9,
        basis="no captured set holds a reach",
    ),
    ("reach_path_ratio", "pick"): Band(
        "literature",
        "point-to-point hand paths are nearly straight (Morasso 1981)",
        lo=1.0,
        hi=1.3,
        basis=f"no captured set holds a reach; {_CLEAN_PASSES}",
        gates=False,
    ),
}

_IDLE = "ReActIdle standing idle (markerless)"
_IDLE_BASIS = "1 set, 7 performers, 11 recordings (38-160 s; genuine and acted)"
_IDLE_PASSES = f"{_IDLE_BASIS}; {_CLEAN_PASSES}"
BANDS.update(
    {
        ("idle_sway_sd_cm", "idle"): Band(
            "factor2", _IDLE, {"reactidle_idle": 4.1077}, basis=_IDLE_PASSES, gates=False
        ),
        ("idle_sway_fast_rms_mm", "idle"): Band(
            "factor2", _IDLE, {"reactidle_idle": 2.6062}, basis=_IDLE_PASSES, gates=False
        ),
        ("idle_sway_median_hz", "idle"): Band(
            "factor2", _IDLE, {"reactidle_idle": 0.15}, basis=_IDLE_PASSES, gates=False
        ),
        ("idle_weight_shifts_per_min", "idle"): Band("factor2", _IDLE, {"reactidle_idle": 10.484}, basis=_IDLE_BASIS),
        ("idle_posture_within_between", "idle"): Band(
            "factor2", _IDLE, {"reactidle_idle": 0.9833}, basis=f"{_IDLE_PASSES}; 124 windows of 10 s", gates=False
        ),
        ("channels_static_share", "idle"): Band("share", _IDLE, {"reactidle_idle": 0.1667}, basis=_IDLE_BASIS),
        ("channels_near_static_share", "idle"): Band(
            "share", _IDLE, {"reactidle_idle": 0.1296}, basis=_IDLE_PASSES, gates=False
        ),
        ("channels_moving_share", "idle"): Band("share", _IDLE, {"reactidle_idle": 0.7037}, basis=_IDLE_BASIS),
    }
)

#: Captured walks on the CMU rig, channel by channel (rotation-vector x/y/z of each non-root
#: joint's local rotation, RealismSettings' classes): "moving" where both Xia et al. 2015's walks
#: (retargeted onto the rig) and CMU's own capture 02_01 (``../shared/data/bvh/cmu``) move it,
#: "still" where both hold it static or near-static, "either" where they differ (CMU holds the
#: hip joints, collars and hands constant, Xia's retargeting moves them and holds the head).
CMU_CAPTURED_CHANNELS: dict[str, tuple[str, str, str]] = {
    "LHipJoint": ("either", "either", "either"),
    "LeftUpLeg": ("moving", "moving", "moving"),
    "LeftLeg": ("moving", "moving", "either"),
    "LeftFoot": ("moving", "moving", "moving"),
    "LeftToeBase": ("moving", "moving", "either"),
    "RHipJoint": ("either", "either", "either"),
    "RightUpLeg": ("moving", "moving", "moving"),
    "RightLeg": ("moving", "moving", "either"),
    "RightFoot": ("moving", "moving", "moving"),
    "RightToeBase": ("moving", "moving", "either"),
    "LowerBack": ("moving", "moving", "moving"),
    "Spine": ("moving", "moving", "moving"),
    "Spine1": ("moving", "moving", "moving"),
    "Neck": ("moving", "moving", "moving"),
    "Neck1": ("moving", "either", "moving"),
    "Head": ("either", "either", "either"),
    "LeftShoulder": ("either", "either", "either"),
    "LeftArm": ("moving", "moving", "moving"),
    "LeftForeArm": ("either", "moving", "moving"),
    "LeftHand": ("either", "either", "either"),
    "LeftFingerBase": ("either", "either", "either"),
    "LeftHandIndex1": ("still", "still", "still"),
    "LThumb": ("either", "either", "either"),
    "RightShoulder": ("either", "either", "either"),
    "RightArm": ("moving", "moving", "moving"),
    "RightForeArm": ("either", "moving", "moving"),
    "RightHand": ("either", "either", "either"),
    "RightFingerBase": ("either", "either", "either"),
    "RightHandIndex1": ("still", "still", "still"),
    "RThumb": ("either", "either", "either"),
}


def judge(table: pd.DataFrame, bands: dict[tuple[str, str], Band] | None = None) -> pd.DataFrame:
    """The realism table with each statistic's band (``band_lo``, ``band_hi``, ``band_rule``,
    ``band_source``, ``band_basis``, ``gates``) and ``in_band``: True or False, empty where the
    statistic has no band or no value. Only rows whose band gates are a verdict on the data."""
    bands = BANDS if bands is None else bands
    out = table.copy()
    limits = [bands.get((s, b)) for s, b in zip(out["statistic"], out["behaviour"])]
    out["band_lo"] = [band.limits[0] if band else np.nan for band in limits]
    out["band_hi"] = [band.limits[1] if band else np.nan for band in limits]
    out["band_rule"] = [band.rule if band else "" for band in limits]
    out["band_source"] = [band.source if band else "" for band in limits]
    out["band_basis"] = [band.basis if band else "" for band in limits]
    out["gates"] = [bool(band and band.gates) for band in limits]
    value = out["value"].to_numpy(dtype=float)
    known = np.isfinite(value) & np.isfinite(out["band_lo"].to_numpy(dtype=float))
    inside = (value >= out["band_lo"].to_numpy(dtype=float)) & (value <= out["band_hi"].to_numpy(dtype=float))
    out["in_band"] = pd.array([bool(i) if k else pd.NA for i, k in zip(inside, known)], dtype="boolean")
    return out
