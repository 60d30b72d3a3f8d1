"""What the realism tests know the generator departs from (findings, not bands moved)."""

#: gating idle statistics the generator's idle data lies outside, with why (a finding, not a band
#: moved: the generator's dwell between balance shifts, subject.weight_shift_s ~ U(4, 15) s, gives 3-4
#: shifts a minute against ReActIdle's 10.5, whose own recordings span 1.9-17.8)
IDLE_OUTSIDE = {("idle_weight_shifts_per_min", "idle")}
