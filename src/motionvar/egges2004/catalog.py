"""The evaluations of Egges et al. 2004 (:class:`motionvar.claims.Evaluation`): the one list the
workflow's rules, the applicability table (:mod:`.requirements`) and the claims are read off."""

from ..claims import Evaluation

EVALUATIONS: tuple[Evaluation, ...] = (
    Evaluation(
        "egges2004_identification",
        "Sec. 8",
        "Generated idle motion is recognisably the person's own.",
        "egges2004",
        label="Sec. 8: person identification",
        inputs="egges2004_recordings",
        measure="motionvar.egges2004.evaluations.identification:identification",
        draw="motionvar.egges2004.figures:draw_identification",
        mem_mb=4000,
    ),
    Evaluation(
        "egges2004_repetition",
        "Sec. 6",
        "Generated idle motion does not repeat itself, unlike a looped clip.",
        "egges2004",
        label="Sec. 6: repetition",
        inputs="egges2004_training",
        measure="motionvar.egges2004.evaluations.repetition:repetition",
        draw="motionvar.egges2004.figures:draw_repetition",
        mem_mb=4000,
        own_keys=("repetition", "extrema_pc"),
    ),
    Evaluation(
        "egges2004_fitting",
        "Sec. 5.4.4, Fig. 4-5",
        "Fitted animations start and end at the given postures; the pieces join smoothly.",
        "egges2004",
        label="Sec. 5.4.4, Fig. 4-5: fitting",
        inputs="egges2004_model",
        measure="motionvar.egges2004.evaluations.fitting:fitting",
        draw="motionvar.egges2004.figures:draw_fitting",
        own_keys=("fitting",),
    ),
    Evaluation(
        "egges2004_speed",
        "Sec. 8",
        "Idle motion is generated in real time.",
        "egges2004",
        label="Sec. 8: real time",
        inputs="egges2004_model",
        measure="motionvar.egges2004.evaluations.speed:speed",
        draw="motionvar.egges2004.figures:draw_speed",
        own_keys=("speed",),
    ),
)
