"""Morphable Graph (Du 2022 ch. 4; Herrmann et al. 2017): motion primitives with a GMM
latent density chosen by BIC, space-partitioning trees for constraint search, MAP
synthesis by Levenberg-Marquardt and graph-walk generation.

- :mod:`.settings`: :class:`GraphSettings` (config section ``du2022_graph``) and its subsections
  :class:`ModelSettings`, :class:`SearchSettings`, :class:`DiversitySettings`,
  :class:`SynthesisSettings` (the settings of the graph walk).
- :mod:`.primitive`: :class:`MotionPrimitive` (DTW time warping + SFPCA + GMM/BIC,
  Sec. 4.4.1, Eq. 4.1): ``fit``, ``sample``, ``log_prob``, ``key_frame_pose`` (f_k(M(s))
  at key frames), ``to_motions`` (back-projection), ``save``/``load`` (npz + json);
  :func:`primitive_clips` (the clips of one primitive in a dataset).
- :mod:`.constraints`: :class:`Constraint` (position, orientation, heading),
  :class:`Objective` (Eq. 4.2, counts evaluations), :class:`ConstraintStack` (Eq. 4.2 for
  many queries at once), :func:`random_constraints` (Sec. 4.6.2).
- :mod:`.trees`: :class:`SpacePartitioningTree` (k-means, GMM, median; beam search,
  Sec. 4.4.2/4.5.2), :class:`MedianKDTree` (the median tree as a kd-tree split by depth, as DFKI
  uses in its k-means tree's leaves: median-sample nodes, greedy or beam descent), :func:`select_beam` (the
  beam an evaluation budget allows, reported beside the fixed verdict beam),
  :func:`brute_force`, :func:`random_search`, :class:`KeyFramePositionIndex` (exact search
  and batch objectives on precomputed key-frame poses); ``search_many`` of the trees and
  :func:`random_search_many` answer many queries in lockstep (Fig. 4.12).
- :mod:`.synthesis`: :func:`optimize_map` (Eq. 4.9 by Levenberg-Marquardt);
  :class:`StepChain`, :class:`StepGoal` and :func:`optimize_chain` (several steps of a walk
  optimised together, Algorithm 1 line 9).
- :mod:`.morphable_graph`: :class:`MorphableGraph` (edges from the prep metadata),
  :func:`follow_path` and :func:`synthesize_step` (Algorithm 1).
- :mod:`.evaluations`: one module per evaluation of Sec. 4.6 (Fig. 4.9 coverage, Fig. 4.10
  constrained generation, Fig. 4.12 search comparison, Sec. 4.6.1 compactness), each
  returning an EvaluationResult; :mod:`.figures` draws them.
"""

from ...core.lazy import lazy_exports

_EXPORTS = {
    ".constraints": ["Constraint", "ConstraintStack", "Objective", "random_constraints"],
    ".morphable_graph": [
        "MorphableGraph",
        "Path2D",
        "StepResult",
        "concatenate_steps",
        "follow_path",
        "place_motion",
        "synthesize_step",
    ],
    ".primitive": ["MotionPrimitive", "PrimitiveOptions", "primitive_clips", "select_gmm"],
    ".settings": ["DiversitySettings", "GraphSettings", "ModelSettings", "SearchSettings", "SynthesisSettings"],
    ".synthesis": ["ChainResult", "MapResult", "StepChain", "StepGoal", "optimize_chain", "optimize_map"],
    ".trees": [
        "TREE_KINDS",
        "KeyFramePositionIndex",
        "MedianKDTree",
        "SearchResult",
        "SpacePartitioningTree",
        "brute_force",
        "random_search",
        "random_search_many",
        "select_beam",
        "tree_search",
    ],
}
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = [
    "TREE_KINDS",
    "ChainResult",
    "Constraint",
    "ConstraintStack",
    "DiversitySettings",
    "GraphSettings",
    "KeyFramePositionIndex",
    "MapResult",
    "MedianKDTree",
    "ModelSettings",
    "MorphableGraph",
    "MotionPrimitive",
    "Objective",
    "Path2D",
    "PrimitiveOptions",
    "SearchResult",
    "SearchSettings",
    "SpacePartitioningTree",
    "StepChain",
    "StepGoal",
    "StepResult",
    "SynthesisSettings",
    "brute_force",
    "concatenate_steps",
    "follow_path",
    "optimize_chain",
    "optimize_map",
    "place_motion",
    "primitive_clips",
    "random_constraints",
    "random_search",
    "random_search_many",
    "select_beam",
    "select_gmm",
    "synthesize_step",
    "tree_search",
]
