"""Reusable motion metrics, one function per metric (import from the submodules):

- :mod:`.jerk` — mean jerk of joint positions (smoothness).
- :mod:`.foot_skating` — horizontal foot speed while a foot is in contact.
- :mod:`.stride` — stride length per support phase (Ma 2010, Sec. 7.1-7.2).
- :mod:`.pose_distance` — distance of each pose to the nearest pose of a reference set.
- :mod:`.discontinuities` — frames whose joint acceleration exceeds a threshold.
"""
