"""Style-only interpolation of whole clips: universal Kriging without variation
parameters (Mukai & Kuriyama 2005) and RBFs (Rose et al. 1998) on the same clip vectors.

Both map the style parameters c alone to a whole-body clip (all joints, key times and,
for flight behaviours, the root height curve): the same c always gives the same clip,
which is why they produce no variation (Ma et al. 2010, Sec. 7.4).
"""

from __future__ import annotations

import numpy as np

from ..kriging import UniversalKriging
from ..representation import ClipCodec, ClipSet
from ..settings import Ma2010Settings, ModelSettings
from ..svi import ClipPrediction
from .rbf import RBFInterpolation


class StyleClipInterpolation:
    """Whole clips as a function of style, interpolated by ``method`` ('kriging' or 'rbf');
    ``variogram_model`` and ``variogram_scale`` are Kriging's (:class:`..kriging.UniversalKriging`;
    None for RBF)."""

    def __init__(
        self,
        method: str,
        variogram_model: str | None,
        variogram_scale: str | None,
        flight: bool = False,
        trend_rcond: float = 0.0,
        key_timing: str = ModelSettings.key_timing,
    ):
        if method not in ("kriging", "rbf"):
            raise ValueError(f"StyleClipInterpolation: method must be 'kriging' or 'rbf'; got {method!r}")
        self.method = method
        self.variogram_model = variogram_model
        self.variogram_scale = variogram_scale
        self.flight = flight
        self.trend_rcond = trend_rcond  # cut-off of the hyperplane's pseudo-inverse (both methods)
        self.key_timing = key_timing  # how the key times are interpolated (as ours)

    def fit(self, clips: ClipSet, groups: np.ndarray | None = None) -> "StyleClipInterpolation":
        """Fit to ``clips``. For RBF, ``groups`` (N,) labels clips that are one example (the cycles
        of one walk: one kernel at their mean style, :meth:`.rbf.RBFInterpolation.fit`); Kriging
        takes every clip as it is."""
        joints = np.arange(clips.skeleton.n_joints)
        self.codec_ = ClipCodec(joints, timing=True, root_height=self.flight, key_timing=self.key_timing).fit(clips)
        self.n_keys_ = len(clips.reference_keys)
        self.reference_keys_ = clips.reference_keys
        y = self.codec_.encode(clips)
        if self.method == "kriging":
            kriging = UniversalKriging(
                self.variogram_model, variogram_scale=self.variogram_scale, trend_rcond=self.trend_rcond
            )
            self.interpolator_ = kriging.fit(clips.style, y)
        else:
            self.interpolator_ = RBFInterpolation(linear_rcond=self.trend_rcond).fit(clips.style, y, groups)
        return self

    def predict(self, c: np.ndarray) -> ClipPrediction:
        rot, keys, height = self.codec_.decode(self.interpolator_.predict(np.atleast_2d(c)), self.n_keys_)
        return ClipPrediction(rotations=rot, key_times=keys, root_height=height)


def mk05_kriging(settings: Ma2010Settings, flight: bool = False) -> StyleClipInterpolation:
    """Universal Kriging over the style parameters only (Mukai & Kuriyama 2005), with the
    variogram, trend cut-off and key timing of ``settings`` (as ours)."""
    return StyleClipInterpolation(
        "kriging",
        settings.model.variogram_model,
        settings.model.variogram_scale,
        flight,
        settings.model.trend_rcond,
        settings.model.key_timing,
    )


def rose98_rbf(settings: Ma2010Settings, flight: bool = False) -> StyleClipInterpolation:
    """RBF interpolation with a linear term (Rose et al. 1998), with the trend cut-off of its
    linear part and the key timing of ``settings`` (as ours)."""
    return StyleClipInterpolation("rbf", None, None, flight, settings.model.trend_rcond, settings.model.key_timing)
