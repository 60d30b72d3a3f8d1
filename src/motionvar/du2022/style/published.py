"""The published values of Du 2022 ch. 5 (Tables 5.1-5.3), as printed in the thesis."""

from __future__ import annotations

import pandas as pd

STYLES = ("proud", "depressed", "angry", "female", "childlike", "old")
"""The six styles of Sec. 5.4, in the order of Table 5.1."""

_T51 = [
    [0.0149, 0.1096, 0.0345, 0.2731, 0.0377, 0.1792, 0.1712],
    [0.1937, 0.0658, 0.1292, 0.0916, 0.0818, 0.0957, 0.1414],
    [0.0825, 0.0883, 0.0357, 0.1502, 0.0448, 0.1179, 0.1030],
    [0.1769, 0.0906, 0.1081, 0.0697, 0.0832, 0.0959, 0.1183],
    [0.1694, 0.0842, 0.1137, 0.1156, 0.0697, 0.1148, 0.1457],
    [0.0977, 0.0718, 0.0939, 0.1405, 0.0719, 0.0456, 0.1257],
    [0.1728, 0.1118, 0.0987, 0.1344, 0.1071, 0.1395, 0.0624],
]
_T52 = {  # walk left stance: pose_SD, V_SD, step_SD
    "training data": (52.8613, 0.4816, 10.1233),
    "neutral": (52.6766, 0.4197, 7.6634),
    "proud": (50.6545, 0.5782, 11.2539),
    "depressed": (48.3101, 0.5892, 9.3205),
    "angry": (49.9446, 0.6611, 11.7906),
    "female": (49.7224, 0.5974, 10.7240),
    "childlike": (51.1589, 0.5058, 9.6104),
    "old": (46.0082, 0.5383, 9.9513),
}
_T53 = {  # walk right stance
    "training data": (53.0372, 0.4985, 9.9842),
    "neutral": (52.8817, 0.4610, 7.5081),
    "proud": (51.1320, 0.6147, 11.8916),
    "depressed": (48.5037, 0.6031, 9.9183),
    "angry": (50.2103, 0.7035, 12.7569),
    "female": (50.3722, 0.6669, 10.7090),
    "childlike": (51.3179, 0.5389, 8.8596),
    "old": (45.5661, 0.5998, 10.2023),
}


def table5_1() -> pd.DataFrame:
    """Table 5.1: style distance D(m, s) (Eq. 5.12) for walk left stance; rows models,
    columns style examples (the row minima lie on the diagonal)."""
    names = ["neutral", *STYLES]
    t = pd.DataFrame(_T51, index=names, columns=names)
    t.index.name = "model"
    return t


def diversity_tables() -> pd.DataFrame:
    """Tables 5.2 (walk_leftStance) and 5.3 (walk_rightStance): columns primitive, model,
    pose_sd, v_sd, step_sd."""
    rows = []
    for prim, table in (("walk_leftStance", _T52), ("walk_rightStance", _T53)):
        for model, (p, v, s) in table.items():
            rows.append({"primitive": prim, "model": model, "pose_sd": p, "v_sd": v, "step_sd": s})
    return pd.DataFrame(rows)
