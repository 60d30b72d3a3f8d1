"""motionvar: a reproducible replication suite for style and variation in human motion
(Ma et al. 2010; Du 2022; Egges et al. 2004)."""

__version__ = "0.1.0"
