"""Realism of a dataset: the statistics of :mod:`motionvar.metrics.realism` over a packed
dataset (:mod:`.table`), and the bands that captured data gives them (:mod:`.bands`)."""

from .bands import BANDS, Band, judge
from .settings import RealismSettings
from .table import dataset_realism

__all__ = ["BANDS", "Band", "RealismSettings", "dataset_realism", "judge"]
