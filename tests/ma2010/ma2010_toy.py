"""What the Ma 2010 tests share: the default settings and their key-frame thresholds, the toy
settings of the evaluations (a short timeline; the linear variogram), a toy dataset of walkers
and the check of an evaluation's result."""

import json

import matplotlib
import matplotlib.pyplot as plt
from claim_checks import check_value_bound
from ma2010_toywalk import walks_folder

from motionvar.claim_catalog import spec
from motionvar.claims import VERDICTS
from motionvar.core import cmu_joint_map
from motionvar.io import load_dataset
from motionvar.ma2010.evaluations.common import PAPER
from motionvar.ma2010.settings import Ma2010Settings

matplotlib.use("Agg")  # noqa: E402  (tests draw figures to nowhere)


JM = cmu_joint_map()
DEFAULTS = Ma2010Settings()
KEYFRAMES = (DEFAULTS.clips.keyframe_prominence, DEFAULTS.clips.keyframe_min_separation_s)  # extract_cycles' thresholds
TOY = Ma2010Settings().replace(clips__n_frames=24)  # neutral forward walks, a short timeline


LINEAR = TOY.replace(model__variogram_model="linear")


def toy_dataset(path, styles, n_cycles=3):
    """Toy walkers of growing stride, some lengthening their strides as they walk (a steady
    walker's two support strides are equal: the style space would be a line)."""
    return load_dataset(walks_folder(path, styles, n_cycles, hip_growth=0.03))


def check(result, draw, claim_prefix):
    assert len(result.table) and result.claims
    json.dumps(result.measurements)  # plain numbers, strings, lists and dicts of them
    for c in result.claims:
        assert c.claim_id.startswith(f"{PAPER}.{claim_prefix}") and c.verdict in VERDICTS
        check_value_bound(c)  # the number the verdict comes from travels with the claim
        again = spec(c.claim_id).claim(result.measurements)  # the measurements alone decide the claim
        assert (again.verdict, again.measured, again.kind) == (c.verdict, c.measured, spec(c.claim_id).kind)
    fig = draw(result)
    assert fig.axes
    plt.close(fig)
