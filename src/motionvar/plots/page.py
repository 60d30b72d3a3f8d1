"""An HTML page that plays a GIF, for the report (Snakemake's report shows HTML pages, not
GIF files): a module of its own, so that the page rules do not load matplotlib."""

from __future__ import annotations

import base64
import html
from pathlib import Path


def gif_page(gif_path: str | Path, title: str = "") -> str:
    """A self-contained HTML page that plays the GIF at ``gif_path`` (inlined as base64):
    Snakemake's report shows HTML pages but not GIF files. ValueError naming the file if
    it is not a GIF."""
    gif_path = Path(gif_path)
    data = gif_path.read_bytes()
    if data[:6] not in (b"GIF87a", b"GIF89a"):
        raise ValueError(f"{gif_path}: not a GIF file")
    src = "data:image/gif;base64," + base64.b64encode(data).decode("ascii")
    esc = html.escape(title or gif_path.name)
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        f"<title>{esc}</title></head>"
        '<body style="margin:0.5em;font-family:Helvetica,Arial,sans-serif">'
        f'<p style="margin:0 0 0.4em 0;color:#333">{esc}</p>'
        f'<img src="{src}" alt="{esc}" style="max-width:100%;height:auto"></body></html>\n'
    )
