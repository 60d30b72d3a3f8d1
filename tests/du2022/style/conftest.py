"""Fixtures shared by the Du 2022 ch. 5 tests: the 21 joints of the style features."""

import pytest

from motionvar.core import cmu_joint_map, cmu_skeleton
from motionvar.du2022.style import style_joints


@pytest.fixture(scope="session")
def layout():
    return style_joints(cmu_skeleton(), cmu_joint_map())
