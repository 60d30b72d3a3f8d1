"""Write docs/claims.md, every declared claim and its bound (motionvar.claim_catalog.catalog_markdown).

python tools/claims_doc.py
"""

from __future__ import annotations

from pathlib import Path

from motionvar.claim_catalog import catalog_markdown

DOC = Path(__file__).resolve().parents[1] / "docs" / "claims.md"

if __name__ == "__main__":
    DOC.write_text(catalog_markdown(), encoding="utf-8")
    print(f"{DOC}: written")
