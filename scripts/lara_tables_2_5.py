"""Lara (2013), Tables 2–5: the triaxiality polynomials q_i, g_(i,m), ℓ_(i,m), L_(i,m) of eqs. 30–34.

The copy of the paper in the project withholds these tables; they are computed here by
``andoyer series sam`` (Deprit's algorithm in exact rationals, ``andoyer.theories.sam_theory``),
with δ = (L'/G')/√(1 − β²) (see the erratum on eq. 31). The paper gives q_i up to i = 10 and the
others up to i = 9; ``--order 10`` writes every polynomial with i ≤ 10, as Markdown, LaTeX and
JSON (exact fractions as strings).

Run: ``python3 scripts/lara_tables_2_5.py --out reproduced``
(writes ``lara_tables_2_5.md``, ``.tex`` and ``.json``).
"""

from __future__ import annotations

from _common import output_folder

from andoyer.cli import main as andoyer

ORDER = 10


def main(argv: list[str] | None = None) -> None:
    """Run ``andoyer series sam --order 10`` once per format into the output folder."""
    out = output_folder(__doc__.splitlines()[0], argv)
    for fmt, suffix in (("md", "md"), ("tex", "tex"), ("json", "json")):
        path = out / f"lara_tables_2_5.{suffix}"
        status = andoyer(["series", "sam", "--order", str(ORDER), "--format", fmt, "--output", str(path)])
        if status:
            raise SystemExit(status)
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
