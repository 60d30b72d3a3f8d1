"""Start-up cost of the rule jobs: every job is a fresh Python process, and scikit-learn
(with scipy.stats), torch and matplotlib take seconds to import. A module that short rules
import loads only what those rules need; each case imports in a fresh interpreter and
checks which heavy packages got loaded."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

SCRIPTS = Path(__file__).resolve().parents[2] / "workflow" / "scripts"

CASES = {
    # the runner of every rule script (pandas and matplotlib only where a rule uses them)
    "rule runner": (
        f"import sys; sys.path.insert(0, {str(SCRIPTS)!r}); import _rule",
        ["pandas", "matplotlib", "scipy", "sklearn", "torch"],
    ),
    # rule applicability: the papers' requirements, not their models
    "requirements": (
        "import motionvar.applicability, motionvar.du2022.requirements, "
        "motionvar.egges2004.requirements, motionvar.ma2010.requirements",
        ["sklearn", "scipy.signal", "scipy.stats", "scipy.spatial", "matplotlib", "torch"],
    ),
    # every rule script builds its section's settings object
    "settings": (
        "from motionvar.config_sections import SECTIONS, settings_class; [settings_class(s) for s in SECTIONS]",
        ["sklearn", "matplotlib", "torch"],
    ),
    # rules gif_page_*: an HTML page around a GIF
    "gif page": ("from motionvar.plots import gif_page", ["matplotlib", "pandas", "scipy", "torch"]),
    # reading and writing BVH (scipy's Rotation only where a motion is converted with it)
    "bvh io": ("import motionvar.io", ["scipy.spatial", "sklearn", "matplotlib", "torch"]),
    # a fitted Ma 2010 model: its users never find key frames (scipy.signal, scikit-learn's PCA)
    "ma2010 model": (
        "from motionvar.ma2010.storage import load_style_variation_model",
        ["scipy.signal", "sklearn", "matplotlib", "torch"],
    ),
    # Du 2022 Fig. 3.10's error curves: the FPCA variants need neither torch nor sklearn.metrics
    "du2022 fda curves": (
        f"import sys, types; sys.path.insert(0, {str(SCRIPTS)!r}); import _du2022_fda; "
        "_du2022_fda.setup_threads(types.SimpleNamespace(threads=1)); "
        "from motionvar.du2022.fda.evaluations import reconstruction_curves",
        ["sklearn.metrics", "torch"],
    ),
    # the Egges 2004 evaluations of a fitted model (fitting it needs scikit-learn; they do not)
    "egges2004 evaluations": (
        "from motionvar.egges2004.storage import load_idle_model; "
        "from motionvar.egges2004.evaluations import fitting, idle_animation, repetition, speed",
        ["sklearn", "scipy.stats", "torch"],
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_import_loads_only_what_the_rule_needs(case):
    statement, heavy = CASES[case]
    code = f"{statement}\nimport json, sys\nprint(json.dumps(sorted(sys.modules)))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    loaded = set(json.loads(out.splitlines()[-1]))
    assert not [h for h in heavy if h in loaded], f"{case}: `{statement}` loads {[h for h in heavy if h in loaded]}"


def test_lazy_exports_refuses_a_name_that_its_module_shadows():
    """``from package import diversity`` would return the submodule once it is imported."""
    from motionvar.core.lazy import lazy_exports

    with pytest.raises(ValueError, match="diversity"):
        lazy_exports("motionvar.du2022.style", {".diversity": ["diversity", "pose_sd"]})
