"""Synthetic CMU-style motion capture: subjects, locomotion, reaching, idle standing, and
the packed dataset of them all (:func:`generate_dataset`)."""

from .dataset import BEHAVIOURS, CONTRACT_COLUMNS, SynthSpec, generate_dataset, subject_traits
from .gait_params import (
    Manner,
    RunParams,
    SidestepParams,
    WalkParams,
    sample_run_params,
    sample_sidestep_params,
    sample_walk_params,
)
from .idle import IdleParams, generate_idle
from .locomotion import generate_run, generate_sidestep, generate_walk
from .reach import ReachParams, generate_pick, generate_place
from .styles import STYLE_FACTORS, STYLES, StyleFactors
from .subjects import Subject, make_subjects

__all__ = [
    "BEHAVIOURS",
    "CONTRACT_COLUMNS",
    "IdleParams",
    "Manner",
    "ReachParams",
    "RunParams",
    "STYLES",
    "STYLE_FACTORS",
    "SidestepParams",
    "StyleFactors",
    "Subject",
    "SynthSpec",
    "WalkParams",
    "generate_dataset",
    "generate_idle",
    "generate_pick",
    "generate_place",
    "generate_run",
    "generate_sidestep",
    "generate_walk",
    "make_subjects",
    "sample_run_params",
    "sample_sidestep_params",
    "sample_walk_params",
    "subject_traits",
]
