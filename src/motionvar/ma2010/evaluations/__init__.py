"""The evaluations of Ma et al. 2010, one module per figure or section; each function takes
the loaded walking cycles (or dataset), the fitted model where it needs one, and the whole
:class:`motionvar.ma2010.settings.Ma2010Settings`, and returns a
:class:`motionvar.claims.EvaluationResult` (table, claims, the numbers its figure draws;
figures: :mod:`motionvar.ma2010.figures`).

- :mod:`.common` — paper key, protocol note, published stride bound, shared measures.
- :mod:`.fig3` — key frames at one gait phase (Fig. 3, Sec. 4.1).
- :mod:`.fig6` — leave-one-out stride error; Kriging vs RBF (Fig. 6, Sec. 7.1).
- :mod:`.fig7b` — reliability over the style space (Fig. 7b, Sec. 7.2).
- :mod:`.fig8` — variation at a fixed style (Fig. 8a, Sec. 7.3).
- :mod:`.sec7_4` — comparison with related methods (Sec. 7.4).
- :mod:`.sec8` — synthesis time per second of motion (Sec. 8).
- :mod:`.variogram` — the Kriging variograms (Sec. 6.1-6.2; a diagnostic, no claim).
"""
