"""What the Du 2022 evaluations need from a dataset (:mod:`motionvar.applicability`): the
segmented primitives each chapter models (ch. 3 functional data, ch. 4 Morphable Graph
primitives, ch. 5 neutral and stylised primitives)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from ..applicability import Joints, Need, Requirement
from ..core.joint_map import OPTIONAL_JOINTS
from .catalog import EVALUATIONS
from .graph.settings import REACH_JOINT

if TYPE_CHECKING:
    from .fda.settings import FdaSettings
    from .graph.settings import GraphSettings
    from .style.settings import StyleSettings

DECLARED = {e.name: e for e in EVALUATIONS}


def _primitives(primitives: Sequence[str], min_count: int, why: str, **where) -> tuple[Need, ...]:
    return tuple(
        Need(what=f"{p} primitives", stage="prep", where={"primitive": (p,), **where}, min_count=min_count, why=why)
        for p in dict.fromkeys(primitives)
    )


def fda_requirements(settings: FdaSettings) -> list[Requirement]:
    """Ch. 3 (config fda): the primitives of ``behaviours`` for the basis and Table 3.1;
    the ``reconstruction.primitives`` of Fig. 3.10; ``reconstruction.pick_primitive`` with two
    or more variants for Fig. 3.11's separation (each at least ``min_clips`` clips)."""
    behaviours, min_clips = settings.behaviours, settings.min_clips
    primitives, pick_primitive = settings.reconstruction.primitives, settings.reconstruction.pick_primitive
    why = "Du 2022 ch. 3 fits functional models to the segmented primitives (at least du2022_fda.min_clips of each)"
    canonical = Need(
        what=f"{'/'.join(behaviours)} primitives",
        stage="prep",
        where={"behaviour": tuple(behaviours)},
        min_count=min_clips,
        why=why,
    )
    recon = _primitives(primitives, min_clips, why)
    labelled = Need(
        what=f"{pick_primitive} primitives",
        stage="prep",
        where={"primitive": (pick_primitive,)},
        min_count=min_clips,
        min_distinct={"variant": 2},
        why="Fig. 3.11 colours the latent space by the clips' variant (e.g. the picked object's "
        "height) and measures how well the methods separate them",
    )
    return [
        Requirement.of(
            DECLARED["du2022_fig3_9"],
            (canonical,),
        ),
        Requirement.of(
            DECLARED["du2022_fig3_10"],
            recon,
        ),
        Requirement.of(
            DECLARED["du2022_fig3_11"],
            recon + (labelled,),
        ),
        Requirement.of(
            DECLARED["du2022_table3_1"],
            (canonical,),
        ),
    ]


HANDS = ("left_hand", "right_hand")


def _optional(names: Sequence[str]) -> tuple[str, ...]:
    """The hands and toes (:data:`~motionvar.core.joint_map.OPTIONAL_JOINTS`) among ``names``
    (semantic joints), in order, once."""
    return tuple(n for n in dict.fromkeys(names) if n in OPTIONAL_JOINTS)


#: ch. 5's features: the CMU 21-joint subset (Sec. 5.4.1; style.features.FEATURE_JOINTS, not imported here: it
#: loads the motion code), hands and toes among them
STYLE_JOINTS = Joints(OPTIONAL_JOINTS, "Du 2022 ch. 5's features are the CMU 21-joint subset, hands and toes included")


# clips a Morphable Graph primitive (ch. 4) and a VAE/CVAE (ch. 5) need at the least
GRAPH_MIN_CLIPS = 3
STYLE_MIN_CLIPS = 2


def graph_requirements(settings: GraphSettings, min_clips: int = GRAPH_MIN_CLIPS) -> list[Requirement]:
    """Ch. 4 (config graph): the graph's ``primitives`` (Sec. 4.6.1 compactness), the
    ``search.primitives`` (Fig. 4.12), walk leftStance and pick reach (Fig. 4.9), and the
    graph's walking primitives and ``synthesis.reach_primitive`` for Fig. 4.10's
    path-and-reach synthesis."""
    primitives, search_primitives = settings.primitives, settings.search.primitives
    walk_primitives = [q for q in primitives if q.startswith("walk_")]
    reach_primitive = settings.synthesis.reach_primitive
    why = "Du 2022 ch. 4 fits a motion primitive (SFPCA + GMM) to the clips of each primitive"
    return [
        Requirement.of(
            DECLARED["du2022_fig4_12"],
            _primitives(search_primitives, min_clips, why),
            Joints(
                _optional(
                    [
                        *(settings.search.joints.get(p, settings.search.default_joint) for p in search_primitives),
                        *settings.search.pose_joints,
                    ]
                ),
                "Fig. 4.12 constrains these joints (du2022_graph.search.joints, default_joint, pose_joints)",
            ),
        ),
        Requirement.of(
            DECLARED["du2022_fig4_9"],
            _primitives(
                ["walk_leftStance", "pick_reach"], min_clips, why + "; Fig. 4.9 shows walk leftStance and pick reach"
            ),
            Joints(HANDS, "Fig. 4.9 shows the pick reach's hand positions"),
        ),
        Requirement.of(
            DECLARED["du2022_fig4_10"],
            _primitives(
                [*walk_primitives, reach_primitive], min_clips, why + "; Fig. 4.10 walks along a path, then reaches"
            ),
            Joints((REACH_JOINT,), f"Fig. 4.10 reaches targets with the {REACH_JOINT.replace('_', ' ')}"),
        ),
        Requirement.of(
            DECLARED["du2022_sec4_6_1"],
            _primitives(primitives, min_clips, why),
        ),
    ]


def style_requirements(settings: StyleSettings, min_clips: int = STYLE_MIN_CLIPS) -> list[Requirement]:
    """Ch. 5 (config style): neutral clips of every VAE primitive and clips of every
    style for the stylised primitives (CVAE)."""
    styles, vae_primitives = settings.styles, settings.vae_primitives
    style_primitives, distance_primitive = settings.style_primitives, settings.distance_primitive
    why_vae = "Du 2022 ch. 5 trains a VAE per primitive on its neutral clips"
    why_cvae = (
        "Du 2022 ch. 5 trains a CVAE per style on that style's clips; set du2022_style.styles to styles your "
        "data has (and neutral_style in the dataset entry if it calls neutral otherwise)"
    )
    neutral = _primitives(vae_primitives, min_clips, why_vae, style=("neutral",))
    stylised = tuple(
        Need(
            what=f"{s} {p} primitives",
            stage="prep",
            where={"primitive": (p,), "style": (s,)},
            min_count=1,
            why=why_cvae,
        )
        for p in dict.fromkeys(style_primitives)
        for s in styles
    )
    distance = tuple(n for n in stylised if n.where["primitive"] == (distance_primitive,))
    return [
        Requirement.of(
            DECLARED["du2022_table5_1"],
            _primitives([distance_primitive], min_clips, why_vae, style=("neutral",)) + distance,
            STYLE_JOINTS,
        ),
        Requirement.of(
            DECLARED["du2022_table5_2"],
            neutral + stylised,
            STYLE_JOINTS,
        ),
        Requirement.of(
            DECLARED["du2022_fig5_4"],
            neutral + stylised,
            STYLE_JOINTS,
        ),
    ]
