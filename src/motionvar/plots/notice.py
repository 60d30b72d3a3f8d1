"""A figure that says in words why there is no plot (e.g. an evaluation the dataset
cannot support), so that the report shows the reason where the figure would be."""

from __future__ import annotations

import textwrap

import matplotlib.pyplot as plt
from matplotlib.figure import Figure


def draw_notice(title: str, text: str, width_chars: int = 90) -> Figure:
    """A plain figure with ``title`` and ``text`` (wrapped), no axes."""
    fig = plt.figure(figsize=(9, 2.6))
    fig.text(0.03, 0.82, title, fontsize=13, weight="bold", va="top")
    fig.text(0.03, 0.62, textwrap.fill(text, width_chars), fontsize=10.5, va="top", linespacing=1.4)
    return fig
